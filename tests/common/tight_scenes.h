#pragma once
// Test helper: scenes in which one box stands a chosen exact distance from a whole-body state
// of the TopAY robot (a few millimetres clear, or a millimetre in collision), for the planner's
// close-quarters tests: next to a tall box, under a table top, beside a floating cube.

#include <string>

#include <Eigen/Core>

#include "core/collision/scene_clearance.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "tests/common/arm_state.h"
#include "tests/common/make_box.h"

namespace topay {

/// Exact obstacle clearance (m) of `state` in `scene`: the base cylinder and every arm sphere
/// against every box.
inline double ObstacleClearance(const Kinematics& kinematics, const Scene& scene,
                                const WholeBodyState& state) {
  return SceneClearanceChecker(kinematics, scene).Compute(state).obstacle_m();
}

/// Moves scene->boxes[box] along the unit `direction` (pointing from the robot to the box)
/// until the exact obstacle clearance of `state` is clearance_m (bisection on the offset in
/// [-1, 2] m, to 1e-10 m; the box must overlap the robot at -1 m). Returns the clearance
/// reached.
inline double PlaceBoxAtClearance(const Kinematics& kinematics, Scene* scene, int box,
                                  const Eigen::Vector3d& direction, const WholeBodyState& state,
                                  double clearance_m) {
  const Eigen::Vector3d centre = scene->boxes[box].center_W_m;
  const auto clearance_at = [&](double offset_m) {
    scene->boxes[box].center_W_m = centre + offset_m * direction;
    return ObstacleClearance(kinematics, *scene, state);
  };
  double lo = -1.0, hi = 2.0;
  for (int i = 0; i < 60 && hi - lo > 1e-10; ++i) {
    const double mid = 0.5 * (lo + hi);
    (clearance_at(mid) < clearance_m ? lo : hi) = mid;
  }
  return clearance_at(hi);
}

/// The three close-quarters situations, each an 8 x 8 m room (z 0 to 1.6 m) with the robot at
/// the origin (yaw 0, the tests' bent arm) and one box `clearance_m` from its nearest part.
enum class TightSpot { kNextToBox, kUnderTableTop, kBaseUnderLowTableTop, kBesideFloatingCube };

inline std::string TightSpotName(TightSpot spot) {
  switch (spot) {
    case TightSpot::kNextToBox:
      return "next to a box";
    case TightSpot::kUnderTableTop:
      return "under a table top";
    case TightSpot::kBaseUnderLowTableTop:
      return "base partly under a low table top";
    case TightSpot::kBesideFloatingCube:
      return "beside a floating cube";
  }
  return "?";
}

struct TightScene {
  Scene scene;
  WholeBodyState state;  ///< The robot in its tight spot.
  int box = 0;           ///< Index of the box placed at the clearance.
};

inline TightScene MakeTightScene(const Kinematics& kinematics, TightSpot spot, double clearance_m) {
  TightScene tight;
  tight.state = BentArmState(0.0, 0.0, 0.0);
  Scene& scene = tight.scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  Eigen::Vector3d direction;
  switch (spot) {
    case TightSpot::kNextToBox:  // a tall box ahead of the robot
      scene.boxes.push_back(MakeBox({1.2, 0.0, 0.6}, {0.6, 0.8, 1.2}));
      direction = Eigen::Vector3d::UnitX();
      break;
    case TightSpot::kUnderTableTop:  // a table top over the arm and the front of the base
      scene.boxes.push_back(MakeBox({0.5, 0.0, 1.2}, {1.2, 1.0, 0.04}));
      scene.boxes.push_back(MakeBox({1.05, 0.45, 0.3}, {0.05, 0.05, 0.6}));  // far legs
      scene.boxes.push_back(MakeBox({1.05, -0.45, 0.3}, {0.05, 0.05, 0.6}));
      direction = Eigen::Vector3d::UnitZ();
      break;
    case TightSpot::kBaseUnderLowTableTop:  // a low table top over the back of the base
      scene.boxes.push_back(MakeBox({-0.7, 0.0, 1.0}, {1.2, 1.0, 0.04}));
      direction = Eigen::Vector3d::UnitZ();
      break;
    case TightSpot::kBesideFloatingCube:  // a cube in the air beside the arm
      scene.boxes.push_back(MakeBox({0.3, 0.8, 0.8}, {0.3, 0.3, 0.3}));
      direction = Eigen::Vector3d::UnitY();
      break;
  }
  PlaceBoxAtClearance(kinematics, &scene, tight.box, direction, tight.state, clearance_m);
  return tight;
}

}  // namespace topay
