#pragma once
// The shipped TopAY robot and the pick-and-place scenarios of a few seeds, made once per test
// process (each takes a second or two).

#include <cstdint>
#include <map>
#include <string>

#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "sim/scenarios/pick_place_scenario.h"

namespace topay::test {

inline const Kinematics& TopayKinematics() {
  static const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                                 std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  static const Kinematics kinematics(model);
  return kinematics;
}

/// MakePickPlaceScenario(defaults, seed), cached.
inline const PickPlaceScenario& DefaultScenario(std::uint64_t seed) {
  static std::map<std::uint64_t, PickPlaceScenario> made;
  auto it = made.find(seed);
  if (it == made.end()) it = made.emplace(seed, MakePickPlaceScenario({}, seed, TopayKinematics())).first;
  return it->second;
}

}  // namespace topay::test
