#pragma once
// The options of the pick-and-place scenario (pick_place_scenario.h), loaded from YAML
// (config/scenarios/pick_place.yaml documents every key; every key is optional).

#include <string>

namespace topay {

struct PickPlaceScenarioOptions {
  std::string source;  ///< The file these came from ("" = defaults), for error messages.
  /// The room: no generated obstacle within this radius (m) of the start (the origin). >= 0.
  double keep_out_radius_m = 1.2;
  /// Only table tops whose upper face is at most this high (m) hold goals: the arm's wrist
  /// reaches 0.41 + 0.47 m above the floor, the flange (E) not much higher. > 0.
  double top_height_max_m = 0.65;
  /// The end-effector point p_WE is this far (m) above its table top's upper face, uniform in
  /// [min, max]. 0 <= min <= max.
  double height_min_m = 0.15;
  double height_max_m = 0.30;
  /// ... and at least this far (m) inside the top's footprint edge (uniform over the rest). >= 0.
  double edge_inset_m = 0.05;
  /// ... and at most this far (m) inside it: the arm reaches over the edge. >= edge_inset_m.
  double edge_depth_max_m = 0.3;
  /// Exact obstacle clearance (m) every goal keeps, arm spheres and base: the sensed map's
  /// 5 cm voxels stand up to ~0.10 m out of the surfaces they hold. >= 0.
  double obstacle_clearance_m = 0.12;
  /// The pickup's base is at least this far (m) from the start. >= 0.
  double pickup_distance_min_m = 1.5;
  /// The drop-off's base is at least this far (m) from the pickup's ("across the room"). >= 0.
  double dropoff_distance_min_m = 4.0;
  /// The tool's orientation R_WE = Rz(yaw) Ry(pi/2 + pitch) (E's z axis is the tool's, out of
  /// the flange): yaw points into the table from the edge nearest to p_WE, +-
  /// tool_yaw_spread_rad (uniform, >= 0); pitch uniform in [min, max] (rad; 0: the tool
  /// horizontal, > 0 tilted down, pi/2 straight down, which the arm's 0.47 m shoulder-to-wrist
  /// reach rarely gets above a table; < 0 tilted up). -pi/2 <= min <= max <= pi/2.
  double tool_yaw_spread_rad = 0.5;
  double tool_pitch_min_rad = -0.4;
  double tool_pitch_max_rad = 0.8;
  /// End-effector targets drawn per goal before the goal is given up. >= 1.
  int max_targets = 1000;
  /// Pickup goals tried (each with its own drop-off search) before the scenario is given up. >= 1.
  int max_pickups = 4;
  /// Damped least-squares iterations of the whole-body IK per target (WholeBodyIk's
  /// max_total_iterations; no wall-clock budget, so the result is deterministic). >= 1.
  int ik_iterations = 3000;
  /// Base poses the whole-body IK tries per target (WholeBodyIk's max_base_candidates). >= 1.
  int ik_base_candidates = 48;
  /// The mission's wait after the gripper opens (s). >= 0.
  double wait_s = 1.0;
};

/// Loads options from YAML. Throws ConfigError naming the file and the key for an unreadable
/// file, an unknown key, a wrong type or a value out of range.
PickPlaceScenarioOptions LoadPickPlaceScenarioOptions(const std::string& path);

/// Throws ConfigError (file `source`) naming the first key whose value is out of range.
void CheckPickPlaceScenarioOptions(const PickPlaceScenarioOptions& options, const std::string& source);

}  // namespace topay
