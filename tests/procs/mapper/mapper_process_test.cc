// topay-mapper as a real process beside topay-sim, over real LCM in a private network
// namespace (skipped, with the reason, where none can be made): the boxes' faces in view are
// occupied in the map, the space between robot and boxes is free, the robot's own points never
// enter the map; a box removed from the world is cleared and one added appears; MAP_UPDATE
// comes at >= 2 Hz as a snapshot then deltas, in kilobytes; --save writes an OctoMap that
// --prior starts from; a mapper killed mid-run starts again from its journal (--checkpoint).
// Bad clouds are counted, skipped and leave the mapper running.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "core/map/occupancy_map.h"
#include "graph_test_support.h"
#include "procs/msgs/map_receiver.h"
#include "tests/common/sanitizer_build.h"
#include "topay/map_update_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/sim_event_t.hpp"

namespace topay::test {
namespace {

// Scans are ~240 kB (LCM fragments): the mapper and this test read them with a larger socket
// buffer (platform notes: a full buffer loses fragments, and LCM 1.4 then the whole message).
constexpr const char* kLcmUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608";

std::string Bin(const std::string& name) { return BinDir() + "/" + name; }
std::string ConfigFile(const std::string& rel) { return std::string(TOPAY_SOURCE_DIR) + "/config/" + rel; }

// The test room: the robot at the origin facing +x; a wall ahead, a crate on the left with a
// wall behind it (rays through the crate's place return from there once it is gone: free space
// is only known along rays that return), a pillar behind (ids 0 .. 3 in file order).
constexpr const char* kRoom = R"({"boxes": [
  {"center": [3.0, 0.0, 0.6], "size": [0.4, 3.0, 1.2], "yaw": 0},
  {"center": [0.0, 2.5, 0.4], "size": [1.0, 1.0, 0.8], "yaw": 0},
  {"center": [-2.5, 0.0, 0.75], "size": [0.6, 0.6, 1.5], "yaw": 0},
  {"center": [0.0, 4.2, 0.8], "size": [4.0, 0.4, 1.6], "yaw": 0}]})";

VoxelStateCounts CountsOf(const msgs::MapReceiver& receiver) {
  VoxelStateCounts counts;
  for (const std::uint8_t b : receiver.states()) {
    const auto state = static_cast<VoxelState>(b);
    counts.occupied += state == VoxelState::kOccupied;
    counts.free += state == VoxelState::kFree;
    counts.unknown += state == VoxelState::kUnknown;
  }
  return counts;
}

struct MapListener {
  msgs::MapReceiver receiver;
  std::vector<std::int64_t> bytes;
  std::vector<bool> full;
  std::vector<Clock::time_point> at;
  void On(const lcm::ReceiveBuffer* rbuf, const std::string&, const map_update_t* m) {
    bytes.push_back(rbuf->data_size);
    full.push_back(m->is_full);
    at.push_back(Clock::now());
    receiver.Accept(*m);
  }
  // Fraction of the voxels with centres in [lo, hi] that are in `state`.
  double Fraction(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, VoxelState state) const {
    const GridGeometry3& g = receiver.geometry();
    const Eigen::Vector3i a = g.CellOf(lo), b = g.CellOf(hi);
    int n = 0, k = 0;
    for (int iz = a.z(); iz <= b.z(); ++iz)
      for (int iy = a.y(); iy <= b.y(); ++iy)
        for (int ix = a.x(); ix <= b.x(); ++ix) {
          ++n;
          k += receiver.state(ix, iy, iz) == state;
        }
    return n > 0 ? static_cast<double>(k) / n : 0.0;
  }
  // Fraction of the (y, z) cells of a face at x = x_face (normal along x) where one of the
  // two voxels next to the face plane is occupied (the range noise puts points on both sides).
  double FaceXOccupied(double x_face, double y0, double y1, double z0, double z1) const {
    const GridGeometry3& g = receiver.geometry();
    const int ix = static_cast<int>(std::lround((x_face - g.origin_W_m.x()) / g.resolution_m));
    int n = 0, k = 0;
    for (int iz = g.CellOf({0, 0, z0}).z(); iz <= g.CellOf({0, 0, z1}).z(); ++iz)
      for (int iy = g.CellOf({0, y0, 0}).y(); iy <= g.CellOf({0, y1, 0}).y(); ++iy) {
        ++n;
        k += receiver.state(ix - 1, iy, iz) == VoxelState::kOccupied || receiver.state(ix, iy, iz) == VoxelState::kOccupied;
      }
    return static_cast<double>(k) / n;
  }
  double FaceYOccupied(double y_face, double x0, double x1, double z0, double z1) const {
    const GridGeometry3& g = receiver.geometry();
    const int iy = static_cast<int>(std::lround((y_face - g.origin_W_m.y()) / g.resolution_m));
    int n = 0, k = 0;
    for (int iz = g.CellOf({0, 0, z0}).z(); iz <= g.CellOf({0, 0, z1}).z(); ++iz)
      for (int ix = g.CellOf({x0, 0, 0}).x(); ix <= g.CellOf({x1, 0, 0}).x(); ++ix) {
        ++n;
        k += receiver.state(ix, iy - 1, iz) == VoxelState::kOccupied || receiver.state(ix, iy, iz) == VoxelState::kOccupied;
      }
    return static_cast<double>(k) / n;
  }
};

class MapperProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("mapper");
    WriteText(dir_ + "/room.json", kRoom);
    watcher_ = std::make_unique<HeartbeatWatcher>(kLcmUrl);
    watcher_->lcm().subscribe(std::string(channels::MAP_UPDATE), &MapListener::On, &map_);
  }
  void TearDown() override {
    for (pid_t pid : {sim_, mapper_}) {
      if (pid > 0 && launch::ProcessAlive(pid)) {
        kill(pid, SIGKILL);
        WaitFor(pid, 3.0);
      }
    }
  }
  void StartSim() {
    sim_ = Spawn({Bin("topay-sim"), "--config", ConfigFile("sim/sim.yaml"), "--scene", dir_ + "/room.json", "--name", "sim"},
                 dir_ + "/sim.txt");
  }
  void StartMapper(std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{Bin("topay-mapper"), "--config", config_, "--name", "mapper", "--lcm-url", kLcmUrl};
    argv.insert(argv.end(), extra.begin(), extra.end());
    mapper_ = Spawn(argv, dir_ + "/mapper.txt");
    ASSERT_TRUE(watcher_->SpinUntil([&] { return watcher_->last.contains("mapper"); }, 10.0)) << ReadText(dir_ + "/mapper.txt");
  }
  int StopMapper() {
    kill(mapper_, SIGINT);
    const int status = WaitFor(mapper_, 10.0);
    mapper_ = -1;
    return status;
  }
  void SendEvent(std::int8_t action, int box_id, const Eigen::Vector3d& center, const Eigen::Vector3d& size) {
    sim_event_t e{};
    e.name = "test";
    e.action = action;
    e.box_id = box_id;
    e.has_box = action == sim_event_t::APPEAR;
    for (int a = 0; a < 3; ++a) {
      e.center_m[a] = center(a);
      e.size_m[a] = size(a);
    }
    e.trigger = sim_event_t::NOW;
    watcher_->lcm().publish(std::string(channels::SIM_EVENT), &e);
  }

  std::string dir_;
  std::string config_ = ConfigFile("mapper/mapper.yaml");
  pid_t sim_ = -1, mapper_ = -1;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  MapListener map_;
};

TEST_F(MapperProcess, MapsTheBoxesInViewAndTheFreeSpaceButNeverTheRobot) {
  StartMapper({"--save", dir_ + "/map.bt"});
  StartSim();
  watcher_->Spin(4.0);
  ASSERT_TRUE(map_.receiver.has_map()) << ReadText(dir_ + "/mapper.txt");
  // The faces towards the robot (sensor at 0.3, 0, 0.22 m): wall at x = 2.8, crate at y = 2.0,
  // pillar at x = -2.2.
  EXPECT_GE(map_.FaceXOccupied(2.8, -1.4, 1.4, 0.05, 1.15), 0.95);
  EXPECT_GE(map_.FaceYOccupied(2.0, -0.45, 0.45, 0.05, 0.75), 0.95);
  // (The pillar behind: the robot's base top and its stowed arm hide its lower part from the
  // sensor.)
  EXPECT_GE(map_.FaceXOccupied(-2.2, -0.25, 0.25, 0.85, 1.45), 0.95);
  // Between the robot and the wall, below the rays to the wall's top edge (rays above it return
  // nothing and clear nothing): seen free. Nothing occupied anywhere in front of the wall.
  EXPECT_GE(map_.Fraction({1.5, -1.0, 0.3}, {2.6, 1.0, 0.65}, VoxelState::kFree), 0.9);
  EXPECT_EQ(map_.Fraction({1.0, -1.0, 0.05}, {2.6, 1.0, 1.55}, VoxelState::kOccupied), 0.0);
  // The robot itself (base and arm, which the LiDAR sees): never in the map.
  EXPECT_EQ(map_.Fraction({-0.6, -0.6, 0.0}, {0.9, 0.6, 1.55}, VoxelState::kOccupied), 0.0);
  // MAP_UPDATE: a snapshot first, then deltas, >= 2 Hz, kilobytes.
  ASSERT_GE(map_.bytes.size(), 8u);
  EXPECT_TRUE(map_.full.front());
  EXPECT_FALSE(map_.full.back());
  for (std::size_t k = 1; k < map_.at.size(); ++k) {
    EXPECT_LE(std::chrono::duration<double>(map_.at[k] - map_.at[k - 1]).count(), 0.6) << "update " << k;
  }
  for (std::size_t k = 0; k < map_.bytes.size(); ++k) EXPECT_LT(map_.bytes[k], 200'000) << "update " << k;
  EXPECT_EQ(map_.receiver.counts().rejected, 0);
  EXPECT_EQ(map_.receiver.counts().waiting, 0);
  // The heartbeat carries the map's statistics.
  EXPECT_NE(watcher_->last["mapper"].status.find("occupied"), std::string::npos) << watcher_->last["mapper"].status;
  // SIGINT: the report and the OctoMap file.
  const int status = StopMapper();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadText(dir_ + "/mapper.txt");
  const std::string out = ReadText(dir_ + "/mapper.txt");
  EXPECT_NE(out.find("scan in -> MAP_UPDATE"), std::string::npos) << out;
  ASSERT_TRUE(std::filesystem::exists(dir_ + "/map.bt")) << out;
  EXPECT_GT(std::filesystem::file_size(dir_ + "/map.bt"), 1000u);

  // A mapper started from that prior publishes the wall at once (no scans: the sim is stopped).
  kill(sim_, SIGTERM);
  WaitFor(sim_, 5.0);
  sim_ = -1;
  map_.receiver = msgs::MapReceiver();
  StartMapper({"--prior", dir_ + "/map.bt"});
  ASSERT_TRUE(watcher_->SpinUntil([&] { return map_.receiver.has_map(); }, 10.0));
  EXPECT_GE(map_.FaceXOccupied(2.8, -1.4, 1.4, 0.05, 1.15), 0.95);
  // No scans: the heartbeat says so (WARN), and empty deltas keep MAP_UPDATE at >= 2 Hz.
  const std::size_t before = map_.bytes.size();
  watcher_->Spin(2.0);
  EXPECT_GE(map_.bytes.size() - before, 3u);
  EXPECT_NE(watcher_->last["mapper"].status.find("no POINT_CLOUD"), std::string::npos) << watcher_->last["mapper"].status;
}

TEST_F(MapperProcess, ARemovedBoxIsClearedAndAnAddedOneAppears) {
  StartMapper();
  StartSim();
  watcher_->Spin(3.0);
  ASSERT_TRUE(map_.receiver.has_map());
  ASSERT_GE(map_.FaceYOccupied(2.0, -0.45, 0.45, 0.05, 0.75), 0.95);
  // The crate goes; a new box appears at (1.5, -1.5).
  SendEvent(sim_event_t::DISAPPEAR, 1, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  SendEvent(sim_event_t::APPEAR, 7, {1.5, -1.75, 0.5}, {0.5, 0.5, 1.0});
  watcher_->Spin(3.0);
  // Cleared where rays now return from the wall behind (above 0.15 m: lower rays to the wall
  // meet the floor first, which returns nothing in this simulation).
  EXPECT_LE(map_.FaceYOccupied(2.0, -0.45, 0.45, 0.15, 0.75), 0.05);
  EXPECT_GE(map_.FaceYOccupied(-1.5, 1.3, 1.7, 0.05, 0.95), 0.95);
}

// Finding 21 of docs/reliability.md: a mapper killed mid-run and started again by the launcher
// (same --checkpoint) publishes the map it had, not an empty one (a planner taking unknown
// voxels as free would plan through what is now out of the LiDAR's view).
TEST_F(MapperProcess, AMapperKilledMidRunStartsAgainFromItsJournal) {
  const std::string journal = dir_ + "/map_journal.bin";
  StartMapper({"--checkpoint", journal});
  StartSim();
  watcher_->Spin(3.0);
  ASSERT_TRUE(map_.receiver.has_map()) << ReadText(dir_ + "/mapper.txt");
  ASSERT_GE(map_.FaceXOccupied(2.8, -1.4, 1.4, 0.05, 1.15), 0.95);
  // The crate goes from the world after the last snapshot: the journal's deltas carry it.
  SendEvent(sim_event_t::DISAPPEAR, 1, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  ASSERT_TRUE(watcher_->SpinUntil([&] { return map_.FaceYOccupied(2.0, -0.45, 0.45, 0.15, 0.75) <= 0.05; },
                                  1.5 * topay::testing::kBuildSlowdown));
  const VoxelStateCounts before = CountsOf(map_.receiver);
  // No scans after the kill (the sim stops first), so the restarted mapper can only know the
  // map from its journal.
  kill(sim_, SIGKILL);
  WaitFor(sim_, 5.0);
  sim_ = -1;
  watcher_->Spin(0.3);
  const VoxelStateCounts last = CountsOf(map_.receiver);
  kill(mapper_, SIGKILL);
  WaitFor(mapper_, 5.0);
  watcher_->Spin(0.3);  // the killed mapper's last MAP_UPDATEs, still queued, go to the old receiver
  map_.receiver = msgs::MapReceiver();
  StartMapper({"--checkpoint", journal});
  ASSERT_TRUE(watcher_->SpinUntil([&] { return map_.receiver.has_map(); }, 10.0)) << ReadText(dir_ + "/mapper.txt");
  const VoxelStateCounts after = CountsOf(map_.receiver);
  EXPECT_EQ(after.occupied, last.occupied);
  EXPECT_EQ(after.free, last.free);
  EXPECT_GE(after.occupied, before.occupied / 2);
  EXPECT_GE(map_.FaceXOccupied(2.8, -1.4, 1.4, 0.05, 1.15), 0.95);
  EXPECT_LE(map_.FaceYOccupied(2.0, -0.45, 0.45, 0.15, 0.75), 0.05);
  EXPECT_NE(ReadText(dir_ + "/mapper.txt").find("map of the journal"), std::string::npos) << ReadText(dir_ + "/mapper.txt");
}

TEST_F(MapperProcess, BadCloudsAreCountedAndSkipped) {
  config_ = dir_ + "/small_clouds.yaml";
  WriteText(config_, "filter:\n  input:\n    max_points: 1000\n");
  StartMapper();
  point_cloud_t cloud{};
  cloud.sensor_frame = "lidar";
  cloud.quat_WS[0] = 1.0;
  cloud.p_WS[2] = 0.5;
  cloud.num_coords = 6;
  cloud.p_SP = {2.0f, 0.0f, 0.5f, std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f};
  watcher_->lcm().publish(std::string(channels::POINT_CLOUD), &cloud);  // one NaN point: dropped
  cloud.p_WS[0] = std::numeric_limits<double>::quiet_NaN();
  watcher_->lcm().publish(std::string(channels::POINT_CLOUD), &cloud);  // NaN sensor pose
  cloud.p_WS[0] = 0.0;
  cloud.num_coords = 3 * 2000;  // more points than this mapper accepts
  cloud.p_SP.assign(cloud.num_coords, 1.0f);
  watcher_->lcm().publish(std::string(channels::POINT_CLOUD), &cloud);
  const char garbage[] = "not an LCM message at all";
  watcher_->lcm().publish(std::string(channels::POINT_CLOUD), garbage, sizeof(garbage));
  watcher_->Spin(2.5);
  EXPECT_NE(watcher_->last["mapper"].status.find("rejecting clouds"), std::string::npos) << watcher_->last["mapper"].status;
  ASSERT_TRUE(launch::ProcessAlive(mapper_));
  const int status = StopMapper();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const std::string out = ReadText(dir_ + "/mapper.txt");
  EXPECT_NE(out.find("3 clouds (2 rejected, 1 NaN points dropped"), std::string::npos) << out;
  EXPECT_NE(out.find("p_WS"), std::string::npos) << out;         // the NaN pose's field named
  EXPECT_NE(out.find("max_points"), std::string::npos) << out;   // the huge cloud's
}

TEST(MapperProcessErrors, ExitCodesForBadFilesAndFlags) {
  const std::string dir = TestDir("mapper_errors");
  WriteText(dir + "/bad.yaml", "map:\n  resolution_m: -1\n");
  WriteText(dir + "/typo.yaml", "publish:\n  snapshot_perod_s: 2\n");
  WriteText(dir + "/garbage.bt", "this is not an octree");
  auto run = [&](std::vector<std::string> argv) {
    const pid_t pid = Spawn(argv, dir + "/out.txt");
    const int status = WaitFor(pid, 20.0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(run({Bin("topay-mapper"), "--config", dir + "/bad.yaml"}), 1);
  EXPECT_NE(ReadText(dir + "/out.txt").find("resolution_m"), std::string::npos) << ReadText(dir + "/out.txt");
  EXPECT_EQ(run({Bin("topay-mapper"), "--config", dir + "/typo.yaml"}), 1);
  EXPECT_NE(ReadText(dir + "/out.txt").find("snapshot_perod_s"), std::string::npos) << ReadText(dir + "/out.txt");
  EXPECT_EQ(run({Bin("topay-mapper"), "--prior", dir + "/garbage.bt"}), 1);
  EXPECT_NE(ReadText(dir + "/out.txt").find("garbage.bt"), std::string::npos) << ReadText(dir + "/out.txt");
  EXPECT_EQ(run({Bin("topay-mapper"), "--checkpoint", dir + "/garbage.bt"}), 1);
  EXPECT_NE(ReadText(dir + "/out.txt").find("map journal"), std::string::npos) << ReadText(dir + "/out.txt");
  EXPECT_EQ(run({Bin("topay-mapper"), "--no-such-flag"}), 2);
}

}  // namespace
}  // namespace topay::test
