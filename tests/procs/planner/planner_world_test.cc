// PlannerWorld: map work folded into pending changes (one per voxel, only what the fields can
// see), applied in a plan's fresh regions, by background slices or whole; after each, the
// fields are exactly those of their own voxel states (bitwise a rebuild), and map_seq says
// which update is wholly in them.

#include "procs/planner/planner_world.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "planner_test_support.h"

namespace topay::planner {
namespace {

class PlannerWorldTest : public ::testing::Test {
 protected:
  PlannerWorldTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf", TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  MapWork Reset(std::int64_t seq) const {
    MapWork work;
    work.reset = true;
    work.geometry = testing::RoomGeometry();
    work.states = testing::StatesOf(work.geometry, testing::RoomBoxes());
    work.map_seq = seq;
    return work;
  }
  // A delta making the voxels of a small box at (x, y) occupied (or `state`).
  MapWork BoxAt(double x, double y, std::int64_t seq, VoxelState state = VoxelState::kOccupied) const {
    const GridGeometry3 g = testing::RoomGeometry();
    const CellBox cells = VoxelsOverlapping(g, {Eigen::Vector3d(x - 0.1, y - 0.1, 0.0), Eigen::Vector3d(x + 0.1, y + 0.1, 0.5)});
    MapWork work;
    work.geometry = g;
    work.map_seq = seq;
    for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz)
      for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy)
        for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) work.changes.push_back({{ix, iy, iz}, state});
    return work;
  }
  static VoxelState StateAt(const PlannerWorld& world, double x, double y, double z) {
    const Eigen::Vector3i c = world.fields().geometry().CellOf({x, y, z});
    return world.fields().state(c.x(), c.y(), c.z());
  }
  // The fields against a rebuild from their own states: bitwise equal.
  static void ExpectExactForTheirStates(const PlannerWorld& world) {
    VoxelMapFields rebuilt = world.fields();
    rebuilt.RebuildAll();
    EXPECT_EQ(world.fields().field_3d().values(), rebuilt.field_3d().values());
    EXPECT_EQ(world.fields().base_field_2d().values(), rebuilt.base_field_2d().values());
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(PlannerWorldTest, AFreshRegionGetsItsChangesAndTheRestWaits) {
  PlannerWorld world(kinematics_, UnknownVoxelPolicy::kFree, 2.0);
  world.Queue(Reset(1));
  world.Flush();
  world.Queue(BoxAt(-2.0, -2.0, 2));
  world.Queue(BoxAt(2.5, 2.5, 3));
  const std::int64_t queued = world.pending_changes();
  EXPECT_GT(queued, 0);
  const std::vector<Eigen::AlignedBox2d> regions{{Eigen::Vector2d(-3.0, -3.0), Eigen::Vector2d(-1.0, -1.0)}};
  const MapFlushSummary s = world.FlushWithin(regions);
  EXPECT_EQ(StateAt(world, -2.0, -2.0, 0.2), VoxelState::kOccupied);
  EXPECT_EQ(StateAt(world, 2.5, 2.5, 0.2), VoxelState::kFree);  // not yet
  EXPECT_EQ(s.field_changes + s.left_pending, queued);
  EXPECT_GT(s.left_pending, 0);
  EXPECT_EQ(world.map_seq(), 1) << "update 3 is not wholly in the fields";
  ExpectExactForTheirStates(world);
  // The fields feel the new box: the 3D field is negative inside it.
  EXPECT_LT(world.fields().field_3d().Distance({-2.0, -2.0, 0.2}), 0.0);
  world.Flush();
  EXPECT_EQ(StateAt(world, 2.5, 2.5, 0.2), VoxelState::kOccupied);
  EXPECT_EQ(world.pending_changes(), 0);
  EXPECT_EQ(world.map_seq(), 3);
  ExpectExactForTheirStates(world);
}

TEST_F(PlannerWorldTest, BackgroundSlicesGoOldestFirstUntilNothingIsPending) {
  using Clock = PlannerWorld::Clock;
  PlannerWorld world(kinematics_, UnknownVoxelPolicy::kFree, 2.0);
  world.Queue(Reset(1));
  EXPECT_EQ(world.OldestPending(), Clock::time_point::min()) << "a new grid is due at once";
  world.FlushOldestSlice();
  EXPECT_TRUE(world.has_map());
  const Clock::time_point t0 = Clock::now();
  world.Queue(BoxAt(2.5, 2.5, 2), t0);                            // older
  world.Queue(BoxAt(-2.5, -2.5, 3), t0 + std::chrono::seconds(1));  // another slice, newer
  EXPECT_EQ(world.OldestPending(), t0);
  world.FlushOldestSlice();
  EXPECT_EQ(StateAt(world, 2.5, 2.5, 0.2), VoxelState::kOccupied);
  EXPECT_EQ(StateAt(world, -2.5, -2.5, 0.2), VoxelState::kFree);
  EXPECT_EQ(world.OldestPending(), t0 + std::chrono::seconds(1));
  ExpectExactForTheirStates(world);
  world.FlushOldestSlice();
  EXPECT_EQ(StateAt(world, -2.5, -2.5, 0.2), VoxelState::kOccupied);
  EXPECT_FALSE(world.OldestPending().has_value());
  EXPECT_EQ(world.map_seq(), 3);
  ExpectExactForTheirStates(world);
}

TEST_F(PlannerWorldTest, ChangesTheFieldsCannotSeeAreNotPending) {
  PlannerWorld world(kinematics_, UnknownVoxelPolicy::kFree, 2.0);
  world.Queue(Reset(1));
  world.Flush();
  // Free -> unknown: the same class under "free".
  world.Queue(BoxAt(1.0, -2.0, 2, VoxelState::kUnknown));
  EXPECT_EQ(world.pending_changes(), 0);
  EXPECT_EQ(world.map_seq(), 2);
  // Occupied, then back to free before a flush: nothing left to do.
  world.Queue(BoxAt(1.0, -2.0, 3));
  EXPECT_GT(world.pending_changes(), 0);
  world.Queue(BoxAt(1.0, -2.0, 4, VoxelState::kFree));
  EXPECT_EQ(world.pending_changes(), 0);
}

TEST_F(PlannerWorldTest, ChangesOnTopOfAGridNotBuiltYetGoIntoIt) {
  PlannerWorld world(kinematics_, UnknownVoxelPolicy::kFree, 2.0);
  world.Queue(Reset(1));
  world.Queue(BoxAt(-2.0, 2.0, 2));
  const std::vector<Eigen::AlignedBox2d> nowhere;
  EXPECT_TRUE(world.FlushWithin(nowhere).reset) << "a new grid is built whole";
  EXPECT_EQ(StateAt(world, -2.0, 2.0, 0.2), VoxelState::kOccupied);
  EXPECT_EQ(world.map_seq(), 2);
}

TEST_F(PlannerWorldTest, AChangeOutsideTheGridIsReportedByTheNextFlush) {
  PlannerWorld world(kinematics_, UnknownVoxelPolicy::kFree, 2.0);
  world.Queue(Reset(1));
  world.Flush();
  MapWork bad;
  bad.map_seq = 2;
  bad.changes.push_back({{1000, 0, 0}, VoxelState::kOccupied});
  world.Queue(bad);
  try {
    world.Flush();
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(1000, 0, 0)"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(world.pending());
  EXPECT_TRUE(world.has_map()) << "the fields keep what they had";
}

}  // namespace
}  // namespace topay::planner
