// ReadRunLog on the crafted run: what it decodes, the final map (snapshot + delta), the
// trajectories rebuilt, the log's span, and the failures per channel.

#include "tools/report/run_log.h"

#include <gtest/gtest.h>

#include "core/map/voxel_state.h"
#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

TEST(RunLog, DecodesEveryChannelTheReportUses) {
  const std::string path = test::FreshTestDir("run_log") + "/graph.lcmlog";
  test::WriteCraftedRunLog(path);
  const RunLog log = ReadRunLog(path);
  EXPECT_EQ(log.path, path);
  EXPECT_EQ(log.first_utime, test::At(0.0));
  EXPECT_EQ(log.last_utime, test::At(2.0));
  EXPECT_EQ(log.mission_statuses.size(), 6u);
  EXPECT_EQ(log.planner_statuses.size(), 11u);  // the tracker status on PLANNER_STATUS is not one
  EXPECT_EQ(log.tracker_statuses.size(), 7u);
  EXPECT_EQ(log.sim_statuses.size(), 2u);
  EXPECT_EQ(log.sim_contacts.size(), 2u);
  EXPECT_EQ(log.sim_events.size(), 3u);
  EXPECT_EQ(log.goals.size(), 1u);
  ASSERT_EQ(log.robot_states.size(), static_cast<std::size_t>(test::kRobotStates));
  EXPECT_DOUBLE_EQ(log.robot_states[20].state.y_m, test::BaseAt(20).y());
  EXPECT_EQ(log.trajectory_messages, 3);
  ASSERT_EQ(log.trajectories.size(), 2u);
  EXPECT_EQ(log.trajectories[0].poly.trajectory_id, 101);
  EXPECT_EQ(log.trajectories[1].poly.trajectory_id, 103);
  EXPECT_DOUBLE_EQ(log.trajectories[1].trajectory.duration_s(), 6.0);
  EXPECT_EQ(log.channels.at("ROBOT_STATE").decode_failures, 1);
}

TEST(RunLog, TheMapIsTheSnapshotWithItsDeltaApplied) {
  const std::string path = test::FreshTestDir("run_log") + "/graph.lcmlog";
  test::WriteCraftedRunLog(path);
  const RunLog log = ReadRunLog(path);
  ASSERT_TRUE(log.map.has_value());
  const GridGeometry3& g = log.map->geometry;
  EXPECT_EQ(g.dims, Eigen::Vector3i(40, 40, 10));
  auto state = [&](int ix, int iy, int iz) { return static_cast<VoxelState>(log.map->states[g.Index(ix, iy, iz)]); };
  EXPECT_EQ(state(1, 25, 4), VoxelState::kOccupied);  // snapshot
  EXPECT_EQ(state(1, 25, 7), VoxelState::kOccupied);  // delta
  EXPECT_EQ(state(1, 25, 5), VoxelState::kFree);
  EXPECT_EQ(log.channels.at("MAP_UPDATE").messages, 2);
}

TEST(RunLog, AMalformedMapUpdateIsCountedAndTheMapKept) {
  const std::string path = test::FreshTestDir("run_log") + "/graph.lcmlog";
  {
    test::CraftedLogWriter log(path);
    test::WriteMap(&log);
    map_update_t bad = msgs::EncodeFullMap(test::MapGeometry(),
                                           std::vector<std::uint8_t>(test::MapGeometry().NumCells(), 0), 0, 3);
    bad.dims[0] = -4;  // decodes as LCM, refused by the map codec
    log.Publish(test::At(1.0), "MAP_UPDATE", bad);
  }
  const RunLog log = ReadRunLog(path);
  EXPECT_EQ(log.channels.at("MAP_UPDATE").decode_failures, 1);
  ASSERT_TRUE(log.map.has_value());
  EXPECT_EQ(static_cast<VoxelState>(log.map->states[log.map->geometry.Index(1, 25, 7)]), VoxelState::kOccupied);
}

}  // namespace
}  // namespace topay::report
