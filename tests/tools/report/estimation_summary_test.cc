#include "tools/report/estimation_summary.h"

#include <cmath>

#include <gtest/gtest.h>

namespace topay::report {
namespace {

msgs::RobotStateEstimate State(std::int64_t utime, double x, double y, double yaw, double q0) {
  msgs::RobotStateEstimate s;
  s.utime = utime;
  s.state.x_m = x;
  s.state.y_m = y;
  s.state.yaw_rad = yaw;
  s.state.q_rad = Eigen::VectorXd::Constant(7, q0);
  return s;
}

TEST(EstimationSummaryTest, ComparesEachEstimateWithTheTruthInterpolatedAtItsTime) {
  // Truth: x from 0 to 1 m over 0.01 s (5 ms samples), yaw across +-pi, q0 from 0 to 0.2.
  const std::vector<msgs::RobotStateEstimate> truths = {State(0, 0.0, 0.0, M_PI - 0.1, 0.0),
                                                        State(5000, 0.5, 0.0, -M_PI + 0.1, 0.1),
                                                        State(10000, 1.0, 0.0, -M_PI + 0.3, 0.2)};
  // At 2500 us the truth is x 0.25, yaw pi (wrapped), q 0.05: errors 0.03 m, 0.02 rad, 0.01 rad.
  // At 5000 us exactly the second sample: errors 0.04 m (y), 0, 0.
  const std::vector<msgs::RobotStateEstimate> estimates = {State(2500, 0.25, 0.03, -M_PI + 0.02, 0.06),
                                                           State(5000, 0.5, 0.04, -M_PI + 0.1, 0.1)};
  const EstimationSummary s = SummarizeEstimation(estimates, truths);
  EXPECT_EQ(s.pairs, 2);
  EXPECT_NEAR(s.position_m.max, 0.04, 1e-9);
  EXPECT_NEAR(s.position_m.rms, std::sqrt((0.03 * 0.03 + 0.04 * 0.04) / 2.0), 1e-9);
  EXPECT_NEAR(s.yaw_rad.max, 0.02, 1e-9);
  EXPECT_NEAR(s.joint_rad.max, 0.01, 1e-9);
}

TEST(EstimationSummaryTest, SkipsEstimatesOutsideTheTruthOrAcrossAGap) {
  const std::vector<msgs::RobotStateEstimate> truths = {State(0, 0, 0, 0, 0), State(200000, 1, 0, 0, 0)};
  const std::vector<msgs::RobotStateEstimate> estimates = {State(-1000, 0, 0, 0, 0), State(100000, 9, 0, 0, 0),
                                                           State(300000, 0, 0, 0, 0)};
  EXPECT_EQ(SummarizeEstimation(estimates, truths).pairs, 0);  // before, inside a 0.2 s gap, after
  EXPECT_EQ(SummarizeEstimation(estimates, {}).pairs, 0);
  EXPECT_EQ(SummarizeEstimation(estimates, truths, 0.2).pairs, 1);
  EXPECT_NEAR(SummarizeEstimation(estimates, truths, 0.2).position_m.max, 8.5, 1e-9);
}

}  // namespace
}  // namespace topay::report
