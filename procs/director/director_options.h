#pragma once
// topay-director's options and script (config/director/pick_place.yaml, --config): scripted
// disturbances for demos and tests. Today one kind of event: box_on_route.

#include <cstdint>
#include <string>
#include <vector>

#include "sim/scenarios/route_box.h"

namespace topay::director {

/// A box put on the robot's route once the mission's step `during_step` runs and the robot
/// drives (docs/director.md).
struct BoxOnRouteEvent {
  std::string name;         ///< For logs; default "box on route <i>".
  std::string during_step;  ///< Required: the mission step's name (its `name`, e.g. dropoff).
  /// The robot's base speed |v| (ROBOT_STATE) must be at least this (m/s). >= 0.
  double min_speed_mps = 0.3;
  /// Where and what (ahead_m: [min, max], side_m: [min, max], height_m, min_robot_distance_m,
  /// scene_gap_m, end_margin_m, tries; sim/scenarios/route_box.h).
  RouteBoxOptions box;
  /// The new box's id in the world; -1: max(1000, the scene's box count) + the event's index.
  int box_id = -1;
};

struct DirectorOptions {
  std::string source;      ///< The file these came from ("" = defaults).
  std::string robot_urdf;  ///< "" = the shipped robot (config/robot/topay_mm.urdf).
  std::string robot_yaml;  ///< "" = config/robot/topay_mm.yaml.
  std::uint64_t seed = 1;       ///< The placements' random draws (ahead distance, side).
  double tick_period_s = 0.2;   ///< How often a pending event tries to place its box (s). > 0.
  /// After a placement attempt whose draws were all rejected, the next one waits this long
  /// (s; each attempt is up to `tries` flood fills over the room, on a core the robot's
  /// processes share). >= 0 and < 3600.
  double retry_period_s = 1.0;
  double path_sample_s = 0.02;  ///< The trajectory's base path is sampled this often (s). > 0.
  std::vector<BoxOnRouteEvent> events;
};

/// Loads the options and the script. Every key is optional but each event's `type`
/// (box_on_route) and `during_step`. Throws ConfigError naming the file and the field (e.g.
/// "events[0].ahead_m") for an unreadable file, an unknown key or type, a missing field, a
/// wrong type or a value out of range.
DirectorOptions LoadDirectorOptions(const std::string& path);

}  // namespace topay::director
