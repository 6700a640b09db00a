#pragma once
// The state estimator's error in a closed-loop run through CAN: each ROBOT_STATE (topay-estimator's
// estimate) against the plant's true state at the same time (SIM_PLANT_STATE, topay-sim's CAN mode,
// linearly interpolated between its two samples around the estimate's utime).

#include <cstdint>
#include <vector>

#include "procs/msgs/convert_robot_state.h"
#include "tools/report/sample_stats.h"

namespace topay::report {

struct EstimationSummary {
  std::int64_t pairs = 0;       ///< estimates with a true state within max_gap_s on both sides
  ErrorStats position_m;        ///< |p_WB estimated - p_WB true|, m
  ErrorStats yaw_rad;           ///< |yaw estimated - yaw true| wrapped to [0, pi], rad
  ErrorStats joint_rad;         ///< the largest |q_i estimated - q_i true| per estimate, rad
};

/// Pairs every estimate with the true state at its utime (both lists in log order; true states
/// more than `max_gap_s` apart around it: that estimate is skipped). Empty without true states.
EstimationSummary SummarizeEstimation(const std::vector<msgs::RobotStateEstimate>& estimates,
                                      const std::vector<msgs::RobotStateEstimate>& truths,
                                      double max_gap_s = 0.05);

}  // namespace topay::report
