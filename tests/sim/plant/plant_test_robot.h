#pragma once
// The shipped TopAY robot for the simulator's tests.

#include <string>

#include "core/io/robot_loader.h"

namespace topay::test {

inline const RobotModel& TopayRobot() {
  static const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                                 std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  return model;
}

}  // namespace topay::test
