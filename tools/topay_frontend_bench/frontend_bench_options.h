#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace topay::frontend_bench {

/// What topay-frontend-bench runs: N generated benchmark tasks and the front-end settings
/// that override the planner YAML's front_end section (unset: the YAML's value).
struct FrontEndBenchOptions {
  std::string scene = "cuboids";  ///< cuboids | tables
  std::string range = "medium";   ///< small | medium | large
  int tasks = 20;                 ///< number of tasks (>= 1)
  std::uint64_t seed = 1;         ///< task i uses DeriveSeed(seed, i)
  /// Front-end workers (0: all cores); unset: the YAML's front_end.num_threads.
  std::optional<int> threads;
  bool jps_only = false;  ///< the JPS-only ablation
  /// Base yaw-rate limit of the layer times; unset: the YAML's planner.base_limits if it
  /// sets them, else the authors' simulation benchmark's 1.25 rad/s.
  std::optional<double> omega_max_radps;
  std::string robot_urdf;
  std::string robot_yaml;
  std::string planner_config;  ///< planner YAML: its front_end section sets the options
  bool verbose = false;        ///< one line per task on the log stream
  std::optional<double> rrt_budget_s;
  std::optional<double> window_s;
  bool first_solution = false;
  bool chassis_band_only = false;
  /// Field settings; unset: PlannerFieldOptions' (3D 0.05 m, 2D base field, two bands).
  std::optional<double> base_resolution_m;
  std::optional<double> resolution_m;
  std::optional<double> band_margin_m;  ///< one base band up to the rigid body's top + this
  std::optional<double> clearance_m;
  std::optional<double> fallback_clearance_m;
};

}  // namespace topay::frontend_bench
