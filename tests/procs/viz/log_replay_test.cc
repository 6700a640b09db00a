// The replay of a recorded log (procs/viz/log_replay.h) through the real feed and hub, to a
// recording transport: the page's play / pause / seek, the state after a seek (map, goal, robot
// as they stood then), and logs that cannot be read.

#include "procs/viz/log_replay.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"
#include "viz_test_support.h"

namespace topay::viz {
namespace {

using report::test::At;
using report::test::kT0Utime;

// 2 s: ROBOT_STATE every 100 ms, a goal at 0.2 s, a trajectory at 0.25 s, a map snapshot at
// 0.5 s and a delta at 1.5 s, in time order as lcm-logger writes them.
std::string WriteOrderedLog(const std::string& dir) {
  const std::string path = dir + "/run.lcmlog";
  report::test::CraftedLogWriter log(path);
  const GridGeometry3 g = report::test::MapGeometry();
  std::vector<std::uint8_t> states(g.NumCells(), static_cast<std::uint8_t>(VoxelState::kFree));
  states[g.Index(1, 25, 4)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
  const std::vector<VoxelChange> changes = {{Eigen::Vector3i(30, 2, 1), VoxelState::kOccupied}};
  goal_t goal{};
  goal.goal_id = 11;
  goal.quat_WE[0] = 1.0;
  for (int k = 0; k <= 20; ++k) {
    log.Publish(At(0.1 * k), "ROBOT_STATE", report::test::RobotState(k));
    if (k == 2) log.Publish(At(0.2), "GOAL", goal);
    if (k == 2) log.Publish(At(0.25), "TRAJECTORY", report::test::TrajectoryMessage(101, 0.25, 0.3));
    if (k == 5) log.Publish(At(0.5), "MAP_UPDATE", msgs::EncodeFullMap(g, states, At(0.5), 1));
    if (k == 15) log.Publish(At(1.5), "MAP_UPDATE", msgs::EncodeMapDelta(g, changes, At(1.5), 2));
  }
  return path;
}

class LogReplayTest : public ::testing::Test {
 protected:
  LogReplayTest()
      : robot_(test::ShippedRobot()),
        hub_({.replay = true},
             [this](HubClientId, std::shared_ptr<const std::string> bytes, bool binary) {
               if (binary && (*bytes)[0] == 0x01) frames_.push_back(*bytes);
             }),
        feed_(robot_, {}, &hub_),
        path_(WriteOrderedLog(report::test::FreshTestDir("viz_replay"))) {}

  // Opens a client subscribed to `topics` (subscription id = channel id).
  void Subscribe(std::initializer_list<Topic> topics) {
    hub_.OnOpen(1);
    nlohmann::json subs = nlohmann::json::array();
    for (Topic t : topics) subs.push_back({{"id", Index(t) + 1}, {"channelId", Index(t) + 1}});
    hub_.OnText(1, nlohmann::json{{"op", "subscribe"}, {"subscriptions", subs}}.dump());
  }
  // The payloads received on a channel, in order.
  std::vector<nlohmann::json> Received(Topic topic) const {
    std::vector<nlohmann::json> out;
    for (const std::string& f : frames_) {
      if (static_cast<std::uint8_t>(f[1]) == Index(topic) + 1) out.push_back(nlohmann::json::parse(f.substr(13)));
    }
    return out;
  }

  RobotView robot_;
  std::vector<std::string> frames_;
  FoxgloveHub hub_;
  VizFeed feed_;
  std::string path_;
};

TEST_F(LogReplayTest, PlaysAtTheClocksPaceUnderThePagesCommands) {
  LogReplay replay(path_, &feed_, /*paused=*/true, 1.0);
  hub_.SetPlaybackHandler([&](const PlaybackCommand& c) { replay.Command(c); });
  Subscribe({Topic::kRobotState, Topic::kGoal, Topic::kRobotDescription});
  replay.Tick(0);
  EXPECT_EQ(Received(Topic::kRobotDescription).size(), 1u);  // latched at once
  EXPECT_EQ(Received(Topic::kRobotState).size(), 1u);        // the event at the start
  replay.Tick(5'000'000);                                    // paused: nothing more
  EXPECT_EQ(Received(Topic::kRobotState).size(), 1u);
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"play"})");
  replay.Tick(5'000'000);
  replay.Tick(5'350'000);  // 0.35 s later
  EXPECT_EQ(Received(Topic::kRobotState).size(), 4u);  // 0, 0.1, 0.2, 0.3
  EXPECT_EQ(Received(Topic::kGoal).size(), 1u);
  const PlaybackState s = replay.State(5'350'000);
  EXPECT_TRUE(s.playing);
  EXPECT_NEAR(s.t, At(0.35) * 1e-6, 1e-6);
  EXPECT_NEAR(s.end_t - s.start_t, 2.0, 1e-9);
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"speed","speed":10})");
  replay.Tick(5'350'000);
  replay.Tick(10'000'000);  // far past the end: stops at the end
  EXPECT_EQ(Received(Topic::kRobotState).size(), 21u);
  EXPECT_FALSE(replay.State(10'000'000).playing);
  EXPECT_EQ(replay.events_fed(), 25);
}

TEST_F(LogReplayTest, ASeekShowsTheStateAsItStoodThen) {
  LogReplay replay(path_, &feed_, /*paused=*/false, 1.0);
  hub_.SetPlaybackHandler([&](const PlaybackCommand& c) { replay.Command(c); });
  Subscribe({Topic::kRobotState, Topic::kMapBlocks, Topic::kGoal, Topic::kTrajectory});
  replay.Tick(0);
  replay.Tick(1'800'000);  // 1.8 s: both map messages in
  frames_.clear();
  hub_.OnText(1, nlohmann::json{{"op", "x-topay-playback"}, {"command", "seek"}, {"t", At(0.55) * 1e-6}}.dump());
  replay.Tick(1'900'000);
  const std::vector<nlohmann::json> maps = Received(Topic::kMapBlocks);
  ASSERT_EQ(maps.size(), 1u);  // the map as it stood at 0.55 s: the snapshot only
  EXPECT_TRUE(maps[0]["reset"]);
  EXPECT_EQ(maps[0]["occupied_total"], 1);
  const std::vector<nlohmann::json> states = Received(Topic::kRobotState);
  ASSERT_FALSE(states.empty());
  EXPECT_NEAR(states.back()["x_m"].get<double>(), 1.5, 1e-12);  // ROBOT_STATE 5 at 0.5 s
  EXPECT_EQ(Received(Topic::kGoal).size(), 1u);
  ASSERT_EQ(Received(Topic::kTrajectory).size(), 1u);  // resent after the seek
  frames_.clear();
  hub_.OnText(1, nlohmann::json{{"op", "x-topay-playback"}, {"command", "seek"}, {"t", At(0.1) * 1e-6}}.dump());
  replay.Tick(2'000'000);
  EXPECT_TRUE(Received(Topic::kMapBlocks).empty());  // no map yet at 0.1 s: nothing to show
  EXPECT_TRUE(Received(Topic::kGoal).empty());
}

TEST(LogReplayErrors, NameTheFile) {
  const std::string dir = report::test::FreshTestDir("viz_replay_errors");
  try {
    ScanLog(dir + "/missing.lcmlog");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.lcmlog"), std::string::npos);
  }
  { report::test::CraftedLogWriter empty(dir + "/empty.lcmlog"); }
  EXPECT_THROW(ScanLog(dir + "/empty.lcmlog"), std::runtime_error);
  std::FILE* f = std::fopen((dir + "/garbage.lcmlog").c_str(), "wb");
  std::fputs("this is not an LCM log at all, just text", f);
  std::fclose(f);
  EXPECT_THROW(ScanLog(dir + "/garbage.lcmlog"), std::runtime_error);
}

}  // namespace
}  // namespace topay::viz
