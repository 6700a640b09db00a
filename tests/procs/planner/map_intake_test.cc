#include "procs/planner/map_intake.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "procs/msgs/map_codec.h"
#include "tests/common/arm_state.h"
#include "tests/procs/planner/planner_test_support.h"

namespace topay::planner {
namespace {

TEST(MapIntakeTest, FirstSnapshotResetsThenDeltasAndMatchingSnapshotsGiveOnlyChanges) {
  const GridGeometry3 g = testing::RoomGeometry();
  std::vector<std::uint8_t> states = testing::StatesOf(g, testing::RoomBoxes());
  MapIntake intake(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  std::optional<MapWork> work = intake.Accept(msgs::EncodeFullMap(g, states, 100, 1), &result);
  ASSERT_TRUE(work.has_value());
  EXPECT_TRUE(work->reset);
  EXPECT_EQ(work->states, states);
  EXPECT_EQ(work->map_seq, 1);

  const std::vector<VoxelChange> changes = {{{10, 20, 3}, VoxelState::kOccupied}, {{11, 20, 3}, VoxelState::kUnknown}};
  work = intake.Accept(msgs::EncodeMapDelta(g, changes, 200, 2), &result);
  ASSERT_TRUE(work.has_value());
  EXPECT_FALSE(work->reset);
  EXPECT_EQ(work->changes.size(), 2u);
  EXPECT_EQ(work->map_seq, 2);

  // The same map again as a snapshot: nothing to do.
  for (const VoxelChange& c : changes) states[g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] = static_cast<std::uint8_t>(c.state);
  EXPECT_FALSE(intake.Accept(msgs::EncodeFullMap(g, states, 300, 3), &result).has_value());
  EXPECT_EQ(result.outcome, msgs::MapUpdateOutcome::kSnapshotApplied);
  // A snapshot that differs in one voxel: that voxel only.
  states[g.Index(5, 5, 5)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
  work = intake.Accept(msgs::EncodeFullMap(g, states, 400, 4), &result);
  ASSERT_TRUE(work.has_value());
  ASSERT_EQ(work->changes.size(), 1u);
  EXPECT_EQ(work->changes[0].voxel, Eigen::Vector3i(5, 5, 5));
}

TEST(MapIntakeTest, MalformedAndOutOfOrderMessagesGiveNoWork) {
  const GridGeometry3 g = testing::RoomGeometry();
  MapIntake intake(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  map_update_t bad = msgs::EncodeFullMap(g, testing::StatesOf(g, {}), 1, 1);
  bad.num_payload_voxels += 7;
  EXPECT_FALSE(intake.Accept(bad, &result).has_value());
  EXPECT_EQ(result.outcome, msgs::MapUpdateOutcome::kRejected);
  const std::vector<VoxelChange> one = {{{1, 1, 1}, VoxelState::kOccupied}};
  EXPECT_FALSE(intake.Accept(msgs::EncodeMapDelta(g, one, 2, 2), &result).has_value());
  EXPECT_EQ(result.outcome, msgs::MapUpdateOutcome::kWaitingForSnapshot);
  EXPECT_FALSE(intake.has_map());
}

TEST(MapIntakeTest, BlockedBoxesNearCoverTheOccupiedVoxelsOfTheRegionOnly) {
  const GridGeometry3 g = testing::RoomGeometry();
  MapIntake intake(UnknownVoxelPolicy::kFree);
  msgs::MapAcceptResult result;
  intake.Accept(msgs::EncodeFullMap(g, testing::StatesOf(g, testing::RoomBoxes()), 1, 1), &result);
  // Around the table only: its voxels as boxes, none of the walls.
  const std::vector<OrientedBox> boxes =
      intake.BlockedBoxesNear({Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1.6)});
  ASSERT_FALSE(boxes.empty());
  Eigen::AlignedBox3d covered;
  for (const OrientedBox& b : boxes) {
    covered.extend(b.center_W_m - 0.5 * b.size_m);
    covered.extend(b.center_W_m + 0.5 * b.size_m);
  }
  EXPECT_NEAR(covered.min().x(), -0.5, 1e-9);
  EXPECT_NEAR(covered.max().x(), 0.5, 1e-9);
  EXPECT_NEAR(covered.max().z(), 0.75, 1e-9);
  EXPECT_TRUE(intake.NearBlocked({0.0, 0.0, 0.5}, 0.0));
  EXPECT_FALSE(intake.NearBlocked({0.0, 0.0, 1.0}, 0.2));
  EXPECT_TRUE(intake.NearBlocked({0.0, 0.0, 0.9}, 0.2));
}

TEST(MapIntakeTest, ClearBaseFootprintFreesOnlyBlockedVoxelsInsideTheBase) {
  const GridGeometry3 g = testing::RoomGeometry();
  // A small box inside the base at (1, 1), one just outside it, one above it, a voxel
  // straddling the base's top (z 0.15-0.20 m, the top at 0.155 m), and one whose centre is
  // outside the radius (0.426 m from the axis, diagonally) while its square reaches 0.01 m into it.
  std::vector<std::uint8_t> states = testing::StatesOf(
      g, {MakeBox({1.1, 1.0, 0.05}, {0.1, 0.1, 0.1}), MakeBox({1.6, 1.0, 0.05}, {0.1, 0.1, 0.1}),
          MakeBox({1.0, 1.0, 0.5}, {0.1, 0.1, 0.1}), MakeBox({0.725, 1.025, 0.175}, {0.05, 0.05, 0.05}),
          MakeBox({1.275, 1.325, 0.075}, {0.05, 0.05, 0.05})});
  const std::vector<std::uint8_t> before = states;
  const BaseCylinder base;  // radius 0.40 m, height 0.155 m
  EXPECT_EQ(ClearBaseFootprint(g, {1.0, 1.0}, base, UnknownVoxelPolicy::kFree, &states), 10);
  const auto at = [&](double x, double y, double z) {
    const Eigen::Vector3i c = g.CellOf({x, y, z});
    return static_cast<VoxelState>(states[g.Index(c.x(), c.y(), c.z())]);
  };
  EXPECT_EQ(at(1.1, 1.0, 0.05), VoxelState::kFree);
  EXPECT_EQ(at(1.6, 1.0, 0.05), VoxelState::kOccupied);
  EXPECT_EQ(at(1.0, 1.0, 0.5), VoxelState::kOccupied);
  EXPECT_EQ(at(0.725, 1.025, 0.175), VoxelState::kFree);
  EXPECT_EQ(at(1.275, 1.325, 0.075), VoxelState::kFree);
  // Nothing else changed.
  int changed = 0;
  for (std::size_t i = 0; i < states.size(); ++i) changed += states[i] != before[i];
  EXPECT_EQ(changed, 10);
}

// Around one arm sphere of the robot standing in a block of occupied voxels: the voxels the
// sphere reaches into by at most 3 cm are cleared, deeper ones and those it does not reach stay
// (judged on the voxels no other sphere reaches, so that the one sphere decides).
TEST(MapIntakeTest, ClearArmOverlapsFreesOnlyShallowOverlapsOfTheArm) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  const WholeBodyState state = BentArmState(0.0, 0.0, 0.0);
  KinematicsCache cache = kinematics.MakeCache();
  kinematics.Update(state, &cache);
  const int s = static_cast<int>(cache.p_WS.size()) - 1;  // the outermost sphere
  const Eigen::Vector3d p = cache.p_WS[s];
  const double r = model.spheres[s].radius_m;
  const GridGeometry3 g = testing::RoomGeometry();
  std::vector<std::uint8_t> states = testing::StatesOf(g, {MakeBox(p, Eigen::Vector3d::Constant(2.0 * r + 0.2))});
  const std::vector<std::uint8_t> before = states;
  const int cleared = ClearArmOverlaps(g, kinematics, state, 0.03, UnknownVoxelPolicy::kFree, &states);
  EXPECT_GT(cleared, 0);
  const double half = 0.5 * g.resolution_m;
  const auto distance = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& c) {
    return ((centre - c).cwiseAbs().array() - half).max(0.0).matrix().norm();
  };
  int shallow = 0, deep = 0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (before[i] != static_cast<std::uint8_t>(VoxelState::kOccupied)) continue;
    const int ix = static_cast<int>(i % g.dims.x()), iy = static_cast<int>((i / g.dims.x()) % g.dims.y()),
              iz = static_cast<int>(i / (static_cast<std::size_t>(g.dims.x()) * g.dims.y()));
    const Eigen::Vector3d c = g.CellCenter(ix, iy, iz);
    bool other = false;
    for (std::size_t o = 0; o < cache.p_WS.size(); ++o) {
      other |= static_cast<int>(o) != s && distance(cache.p_WS[o], c) < model.spheres[o].radius_m;
    }
    if (other) continue;
    const double d = distance(p, c);
    const bool expect_cleared = d < r && d > r - 0.03;
    shallow += expect_cleared;
    deep += d <= r - 0.03;
    EXPECT_EQ(states[i], static_cast<std::uint8_t>(expect_cleared ? VoxelState::kFree : VoxelState::kOccupied))
        << "voxel at " << c.transpose() << ", " << d << " m from the sphere's centre (radius " << r << ")";
  }
  EXPECT_GT(shallow, 0);
  EXPECT_GT(deep, 0);
  // Depth 0: nothing of the arm is cleared.
  std::vector<std::uint8_t> untouched = before;
  EXPECT_EQ(ClearArmOverlaps(g, kinematics, state, 0.0, UnknownVoxelPolicy::kFree, &untouched), 0);
}

}  // namespace
}  // namespace topay::planner
