#pragma once
// The options of the pick-and-place scenario (pick_place_scenario.h), loaded from YAML
// (config/scenarios/pick_place.yaml documents every key; every key is optional).

#include <string>

namespace topay {

struct PickPlaceScenarioOptions {
  std::string source;  ///< The file these came from ("" = defaults), for error messages.
  /// The room: no generated obstacle within this radius (m) of the start (the origin). >= 0.
  double keep_out_radius_m = 1.2;
  /// The end-effector point p_WE is this far (m) above its table top's upper face, uniform in
  /// [min, max]. 0 <= min <= max.
  double height_min_m = 0.15;
  double height_max_m = 0.30;
  /// ... and at least this far (m) inside the top's footprint edge (uniform over the rest). >= 0.
  double edge_inset_m = 0.05;
  /// Exact obstacle clearance (m) every goal keeps, arm spheres and base: the sensed map's
  /// 5 cm voxels stand up to ~0.10 m out of the surfaces they hold. >= 0.
  double obstacle_clearance_m = 0.12;
  /// The pickup's base is at least this far (m) from the start. >= 0.
  double pickup_distance_min_m = 1.5;
  /// The drop-off's base is at least this far (m) from the pickup's ("across the room"). >= 0.
  double dropoff_distance_min_m = 4.0;
  /// The tool points down: R_WE = Rz(yaw) Ry(pi/2) (E's x axis along -z), yaw uniform. false:
  /// R_WE = Rz(yaw) Ry(pitch) with pitch uniform in [0, pi/2] (tilted reaches too).
  bool tool_down = true;
  /// End-effector targets drawn per goal before the goal is given up. >= 1.
  int max_targets = 300;
  /// Pickup goals tried (each with its own drop-off search) before the scenario is given up. >= 1.
  int max_pickups = 4;
  /// Damped least-squares iterations of the whole-body IK per target (WholeBodyIk's
  /// max_total_iterations; no wall-clock budget, so the result is deterministic). >= 1.
  int ik_iterations = 3000;
  /// The mission's wait after the gripper opens (s). >= 0.
  double wait_s = 1.0;
};

/// Loads options from YAML. Throws ConfigError naming the file and the key for an unreadable
/// file, an unknown key, a wrong type or a value out of range.
PickPlaceScenarioOptions LoadPickPlaceScenarioOptions(const std::string& path);

/// Throws ConfigError (file `source`) naming the first key whose value is out of range.
void CheckPickPlaceScenarioOptions(const PickPlaceScenarioOptions& options, const std::string& source);

}  // namespace topay
