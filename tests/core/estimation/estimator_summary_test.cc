// FormatEstimatorSummary prints every count in its place.

#include "core/estimation/estimator_summary.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(EstimatorSummary, EveryCountIsPrinted) {
  EstimatorSummary s;
  s.odometry_applied = 101;
  s.odometry_not_finite = 102;
  s.odometry_out_of_order = 103;
  s.odometry_too_old = 104;
  s.poses_initialised = 105;
  s.poses_accepted = 106;
  s.poses_gated = 107;
  s.reinitialisations = 108;
  s.poses_not_finite = 109;
  s.poses_out_of_order = 110;
  s.poses_too_old = 111;
  s.delayed_inputs = 112;
  s.replayed_events = 113;
  const std::string text = FormatEstimatorSummary(s);
  EXPECT_NE(text.find("odometry 101 (rejected: 102 not finite, 103 out of order, 104 too old)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("105 initial, 106 accepted, 107 gated, 108 reinit (rejected: 109 not finite, 110 out of "
                      "order, 111 too old)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("112 delayed inputs, 113 events replayed"), std::string::npos) << text;
}

}  // namespace
}  // namespace topay
