#include "procs/planner/standing_robot.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/map/voxel_boxes.h"
#include "procs/msgs/map_codec.h"
#include "procs/planner/map_intake.h"
#include "tests/common/arm_state.h"
#include "tests/procs/planner/planner_test_support.h"

namespace topay::planner {
namespace {

class StandingRobotTest : public ::testing::Test {
 protected:
  // The robot standing in the room's free corner, a block of occupied voxels around its base and
  // its outermost arm sphere (so that both clear something and the arm leaves deep voxels).
  void SetUp() override {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(standing_.state, &cache);
    const Eigen::Vector3d p_WS = cache.p_WS.back();
    const double r = model_.spheres.back().radius_m;
    states_ = testing::StatesOf(geometry_, {MakeBox(p_WS, Eigen::Vector3d::Constant(2.0 * r + 0.2)),
                                            MakeBox({standing_.state.x_m, standing_.state.y_m, 0.1}, {0.3, 0.3, 0.2})});
  }
  RobotModel model_ = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                     TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  StandingRobot standing_{BentArmState(-2.5, -2.5, 0.0), 0.03};
  GridGeometry3 geometry_ = testing::RoomGeometry();
  std::vector<std::uint8_t> states_;
};

// The base's voxels and the arm's shallow overlaps, exactly as the two clearings one after the
// other; with arm_overlap_m 0 the base's only.
TEST_F(StandingRobotTest, ClearsTheBaseFootprintAndTheArmsShallowOverlaps) {
  std::vector<std::uint8_t> expected = states_;
  const int base = ClearBaseFootprint(geometry_, {standing_.state.x_m, standing_.state.y_m}, model_.base_cylinder,
                                      UnknownVoxelPolicy::kFree, &expected);
  const int arm = ClearArmOverlaps(geometry_, kinematics_, standing_.state, 0.03, UnknownVoxelPolicy::kFree, &expected);
  ASSERT_GT(base, 0);
  ASSERT_GT(arm, 0);
  std::vector<std::uint8_t> states = states_;
  EXPECT_EQ(ClearStandingRobot(geometry_, kinematics_, standing_, UnknownVoxelPolicy::kFree, &states), base + arm);
  EXPECT_EQ(states, expected);

  // Every cleared voxel lies within StandingRobotBounds (the intake skips the copy outside it).
  const Eigen::AlignedBox3d bounds = StandingRobotBounds(kinematics_, standing_, geometry_.resolution_m);
  for (int iz = 0; iz < geometry_.dims.z(); ++iz)
    for (int iy = 0; iy < geometry_.dims.y(); ++iy)
      for (int ix = 0; ix < geometry_.dims.x(); ++ix) {
        const std::int64_t i = geometry_.Index(ix, iy, iz);
        if (states[i] != states_[i]) {
          EXPECT_TRUE(bounds.contains(geometry_.CellCenter(ix, iy, iz)));
        }
      }

  std::vector<std::uint8_t> base_only = states_;
  EXPECT_EQ(ClearStandingRobot(geometry_, kinematics_, {standing_.state, 0.0}, UnknownVoxelPolicy::kFree, &base_only),
            base);
}

// The map check of a plan from rest: the intake's boxes without the standing robot's voxels,
// the intake's own map untouched (the next check without them sees them again).
TEST_F(StandingRobotTest, TheIntakesBoxesLeaveOutTheStandingRobotsVoxelsOnly) {
  MapIntake intake(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  intake.Accept(msgs::EncodeFullMap(geometry_, states_, 1, 1), &result);
  const Eigen::AlignedBox3d region(Eigen::Vector3d(-4.0, -4.0, 0.0), Eigen::Vector3d(-1.0, -1.0, 2.0));
  std::vector<std::uint8_t> cleared = states_;
  ClearStandingRobot(geometry_, kinematics_, standing_, UnknownVoxelPolicy::kFree, &cleared);
  const std::vector<OrientedBox> without = intake.BlockedBoxesNear(region, kinematics_, standing_);
  const std::vector<OrientedBox> with = intake.BlockedBoxesNear(region);
  // Every voxel the robot leaves out lies in no box of `without`, and in one of `with`.
  const auto covered = [](const std::vector<OrientedBox>& boxes, const Eigen::Vector3d& c) {
    for (const OrientedBox& b : boxes) {
      if (((c - b.center_W_m).cwiseAbs() - 0.5 * b.size_m).maxCoeff() < 0.0) return true;
    }
    return false;
  };
  int left_out = 0, kept = 0;
  const GridGeometry3& g = geometry_;
  for (int iz = 0; iz < g.dims.z(); ++iz) {
    for (int iy = 0; iy < g.dims.y(); ++iy) {
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const std::int64_t i = g.Index(ix, iy, iz);
        const Eigen::Vector3d c = g.CellCenter(ix, iy, iz);
        if (states_[i] != static_cast<std::uint8_t>(VoxelState::kOccupied) || !region.contains(c)) continue;
        const bool robot = cleared[i] != states_[i];
        left_out += robot;
        kept += !robot;
        EXPECT_EQ(covered(without, c), !robot) << "voxel at " << c.transpose();
        EXPECT_TRUE(covered(with, c)) << "voxel at " << c.transpose();
      }
    }
  }
  EXPECT_GT(left_out, 0);
  EXPECT_GT(kept, 0);
  const std::span<const std::uint8_t> held = intake.receiver().states();
  EXPECT_TRUE(std::equal(held.begin(), held.end(), states_.begin(), states_.end()));
}

}  // namespace
}  // namespace topay::planner
