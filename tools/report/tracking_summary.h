#pragma once
// Tracking errors and NMPC solve times from TRACKER_STATUS (topay-tracker).

#include <cstdint>
#include <vector>

#include "tools/report/sample_stats.h"
#include "topay/tracker_status_t.hpp"

namespace topay::report {

/// Over the statuses whose state is TRACKING (idle, stopping and finished cycles left out).
struct TrackingSummary {
  ErrorStats position_m;   ///< position_error_m: RMS and max, m
  ErrorStats yaw_rad;      ///< |yaw_error_rad|: RMS and max, rad
  ErrorStats joint_rad;    ///< joint_error_rad (the largest joint's error per cycle), rad
  TimingStats solve_ms;    ///< solve_ms: median, p95, p99, max, ms
};

TrackingSummary SummarizeTracking(const std::vector<tracker_status_t>& statuses);

}  // namespace topay::report
