#pragma once
// Planned against measured motion over the run, at every ROBOT_STATE: measured v, omega and
// joints from the state; planned from the trajectory active at the state's time
// (active_trajectory.h) evaluated there (held at its end once it has ended).

#include <cstdint>
#include <vector>

#include "tools/report/run_log.h"

namespace topay::report {

/// Every vector has one entry per ROBOT_STATE; planned values are NaN while no trajectory is
/// active (and for joints a trajectory does not have).
struct RunTimeSeries {
  std::int64_t t0_utime = 0;  ///< t = 0: the first ROBOT_STATE
  std::vector<double> t_s;
  std::vector<double> v_measured_mps, v_planned_mps;
  std::vector<double> omega_measured_radps, omega_planned_radps;
  std::vector<std::vector<double>> q_measured_rad, q_planned_rad;  ///< [joint][sample]
  std::vector<double> switch_t_s;  ///< trajectory switches (TrajectorySwitchUtimes) from t0
};

RunTimeSeries SampleRunTimeSeries(const RunLog& log);

}  // namespace topay::report
