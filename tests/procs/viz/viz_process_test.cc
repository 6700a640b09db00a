// topay-viz as a process: a recorded log served to a Foxglove client and the page's files over
// HTTP; the live graph's messages forwarded in a private network namespace while it publishes
// nothing but its heartbeat; clear errors and exit codes for bad flags, files and ports.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <set>

#include "tests/procs/graph_test_support.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/runtime/process_loop.h"
#include "tests/tools/report/crafted_run_log.h"
#include "viz_test_support.h"
#include "ws_test_client.h"

namespace topay::viz {
namespace {

using topay::test::BinDir;
using topay::test::ReadText;
using topay::test::Spawn;
using topay::test::TestDir;
using topay::test::WaitFor;
using topay::test::WriteText;

std::string Viz() { return BinDir() + "/topay-viz"; }

// The port topay-viz printed ("serving http://127.0.0.1:PORT/"), waiting up to 10 s.
int PortFrom(const std::string& output_path) {
  const std::regex serving(R"(serving http://[^:]+:(\d+)/)");
  for (int i = 0; i < 200; ++i) {
    std::smatch m;
    const std::string text = ReadText(output_path);
    if (std::regex_search(text, m, serving)) return std::stoi(m[1]);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return -1;
}

// Subscribes to every advertised channel; returns the channel ids by topic.
std::map<std::string, int> SubscribeAll(test::WsTestClient* client) {
  std::map<std::string, int> ids;
  for (int i = 0; i < 2; ++i) {
    const std::optional<test::WsMessage> m = client->Read(5.0);
    if (!m) break;
    const nlohmann::json j = nlohmann::json::parse(m->bytes);
    if (j["op"] != "advertise") continue;
    nlohmann::json subs = nlohmann::json::array();
    for (const auto& c : j["channels"]) {
      ids[c["topic"]] = c["id"];
      subs.push_back({{"id", c["id"]}, {"channelId", c["id"]}});
    }
    client->SendText(nlohmann::json{{"op", "subscribe"}, {"subscriptions", subs}}.dump());
  }
  return ids;
}

// The topics of the message data frames read within `seconds` (subscription id = channel id).
std::map<int, int> FramesPerChannel(test::WsTestClient* client, double seconds) {
  std::map<int, int> count;
  const auto start = topay::test::Clock::now();
  while (topay::test::SecondsSince(start) < seconds) {
    const std::optional<test::WsMessage> m = client->Read(seconds);
    if (!m) break;
    if (m->binary && m->bytes.size() >= 13 && m->bytes[0] == 0x01) ++count[static_cast<std::uint8_t>(m->bytes[1])];
  }
  return count;
}

TEST(VizProcess, ServesARecordedLogAndThePage) {
  const std::string dir = TestDir("replay");
  const std::string log = dir + "/run.lcmlog";
  {
    report::test::CraftedLogWriter writer(log);
    for (int k = 0; k <= 20; ++k) writer.Publish(report::test::At(0.1 * k), "ROBOT_STATE", report::test::RobotState(k));
  }
  std::filesystem::create_directories(dir + "/web");
  WriteText(dir + "/web/index.html", "<html>topay viewer test page</html>");
  const pid_t viz = Spawn({Viz(), "--log", log, "--port", "0", "--web-root", dir + "/web"}, dir + "/viz.out");
  const int port = PortFrom(dir + "/viz.out");
  ASSERT_GT(port, 0) << ReadText(dir + "/viz.out");
  const auto [status, body] = test::HttpGet(port, "/");
  EXPECT_EQ(status, 200);
  EXPECT_NE(body.find("topay viewer test page"), std::string::npos);
  EXPECT_EQ(test::HttpGet(port, "/../../etc/passwd").first / 100, 4);
  test::WsTestClient client(port);
  const std::map<std::string, int> ids = SubscribeAll(&client);
  ASSERT_EQ(ids.size(), kNumTopics);
  const std::map<int, int> frames = FramesPerChannel(&client, 3.0);
  EXPECT_GE(frames.count(ids.at("/robot/description")), 1u);
  EXPECT_GE(frames.count(ids.at("/robot/state")), 1u);
  EXPECT_GE(frames.count(ids.at("/viz/playback")), 1u);
  kill(viz, SIGINT);
  const int wait_status = WaitFor(viz, 10.0);
  ASSERT_TRUE(WIFEXITED(wait_status)) << ReadText(dir + "/viz.out");
  EXPECT_EQ(WEXITSTATUS(wait_status), 0);
}

TEST(VizProcess, ForwardsTheLiveGraphAndPublishesNothingButItsHeartbeat) {
  std::string why;
  if (!topay::test::EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("live");
  const pid_t viz = Spawn({Viz(), "--port", "0"}, dir + "/viz.out");
  const int port = PortFrom(dir + "/viz.out");
  ASSERT_GT(port, 0) << ReadText(dir + "/viz.out");
  test::WsTestClient client(port);
  const std::map<std::string, int> ids = SubscribeAll(&client);
  ASSERT_EQ(ids.size(), kNumTopics);
  // A client that subscribes to everything and never reads, and one that sends junk: neither
  // may hold up the LCM loop (heartbeats) nor the well-behaved client.
  test::WsTestClient stalled(port);
  SubscribeAll(&stalled);
  test::WsTestClient hostile(port);
  for (int i = 0; i < 500; ++i) hostile.SendText(i % 2 ? "{\"op\":\"subscribe\",\"subscriptions\":7}" : "not json");
  topay::test::HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  std::set<std::string> channels_seen;
  struct Any {
    std::set<std::string>* seen;
    void On(const lcm::ReceiveBuffer*, const std::string& channel) { seen->insert(channel); }
  } any{&channels_seen};
  watcher.lcm().subscribe(".*", &Any::On, &any);
  for (int k = 0; k < 100; ++k) {  // 2 s of ROBOT_STATE at 50 Hz
    robot_state_t msg = report::test::RobotState(k % 21);
    msg.utime = procs::NowUtime();
    watcher.lcm().publish("ROBOT_STATE", &msg);
    watcher.Spin(0.02);
  }
  const std::map<int, int> frames = FramesPerChannel(&client, 1.5);
  EXPECT_GE(frames.count(ids.at("/robot/state")), 1u);
  watcher.Spin(1.0);
  EXPECT_GE(watcher.last["topay-viz"].count, 2);  // its loop kept its 1 Hz over the 3 s
  channels_seen.erase("ROBOT_STATE");
  channels_seen.erase("HEARTBEAT");
  EXPECT_TRUE(channels_seen.empty()) << "topay-viz published on " << *channels_seen.begin();
  kill(viz, SIGINT);
  EXPECT_EQ(WEXITSTATUS(WaitFor(viz, 10.0)), 0);
}

TEST(VizProcess, ExitsWithAClearErrorOnBadFlagsFilesAndPorts) {
  const std::string dir = TestDir("errors");
  WriteText(dir + "/bad.yaml", "server:\n  prot: 80\n");
  pid_t p = Spawn({Viz(), "--config", dir + "/bad.yaml", "--log", dir + "/bad.yaml"}, dir + "/config.out");
  EXPECT_EQ(WEXITSTATUS(WaitFor(p, 10.0)), 1);
  EXPECT_NE(ReadText(dir + "/config.out").find("server.prot"), std::string::npos) << ReadText(dir + "/config.out");
  p = Spawn({Viz(), "--log", dir + "/missing.lcmlog"}, dir + "/missing.out");
  EXPECT_EQ(WEXITSTATUS(WaitFor(p, 10.0)), 2);
  EXPECT_NE(ReadText(dir + "/missing.out").find("missing.lcmlog"), std::string::npos);
  p = Spawn({Viz(), "--log", dir + "/bad.yaml", "--port", "0"}, dir + "/notalog.out");
  EXPECT_EQ(WEXITSTATUS(WaitFor(p, 10.0)), 1);
  EXPECT_NE(ReadText(dir + "/notalog.out").find("bad.yaml"), std::string::npos);
  // A port already taken: a clear error naming it, not a crash.
  const std::string log = dir + "/one.lcmlog";
  {
    report::test::CraftedLogWriter writer(log);
    writer.Publish(report::test::At(0.0), "ROBOT_STATE", report::test::RobotState(0));
  }
  const pid_t first = Spawn({Viz(), "--log", log, "--port", "0"}, dir + "/first.out");
  const int port = PortFrom(dir + "/first.out");
  ASSERT_GT(port, 0);
  p = Spawn({Viz(), "--log", log, "--port", std::to_string(port)}, dir + "/second.out");
  EXPECT_EQ(WEXITSTATUS(WaitFor(p, 10.0)), 1);
  EXPECT_NE(ReadText(dir + "/second.out").find(std::to_string(port)), std::string::npos) << ReadText(dir + "/second.out");
  kill(first, SIGINT);
  EXPECT_EQ(WEXITSTATUS(WaitFor(first, 10.0)), 0);
}

}  // namespace
}  // namespace topay::viz
