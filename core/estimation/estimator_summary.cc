#include "core/estimation/estimator_summary.h"

#include <cstdio>

namespace topay {

std::string FormatEstimatorSummary(const EstimatorSummary& s) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "odometry %lld (rejected: %lld not finite, %lld out of order, %lld too old); poses: %lld initial, "
                "%lld accepted, %lld gated, %lld reinit (rejected: %lld not finite, %lld out of order, %lld too "
                "old); %lld delayed inputs, %lld events replayed",
                static_cast<long long>(s.odometry_applied), static_cast<long long>(s.odometry_not_finite),
                static_cast<long long>(s.odometry_out_of_order), static_cast<long long>(s.odometry_too_old),
                static_cast<long long>(s.poses_initialised), static_cast<long long>(s.poses_accepted),
                static_cast<long long>(s.poses_gated), static_cast<long long>(s.reinitialisations),
                static_cast<long long>(s.poses_not_finite), static_cast<long long>(s.poses_out_of_order),
                static_cast<long long>(s.poses_too_old), static_cast<long long>(s.delayed_inputs),
                static_cast<long long>(s.replayed_events));
  return text;
}

}  // namespace topay
