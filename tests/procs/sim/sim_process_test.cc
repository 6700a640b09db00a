// topay-sim as a real process over real LCM in a private network namespace (skipped, with the
// reason, where none can be made): ROBOT_STATE at ~100 Hz and SIM_STATUS; a NaN command is
// rejected and the robot brakes; run-time SIM_EVENT; SIGTERM prints the final counts; exit code
// 1 for a malformed scene, an unknown robot, a malformed event file, 2 for bad flags.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "graph_test_support.h"
#include "procs/runtime/process_loop.h"
#include "topay/control_command_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"

namespace topay::test {
namespace {

std::string SimBin() { return BinDir() + "/topay-sim"; }
std::string Config() { return std::string(TOPAY_SOURCE_DIR) + "/config/sim/sim.yaml"; }

struct Listener {
  std::vector<robot_state_t> states;
  std::vector<sim_status_t> statuses;
  int poses = 0;
  std::vector<point_cloud_t> clouds;
  void OnCloud(const lcm::ReceiveBuffer*, const std::string&, const point_cloud_t* m) { clouds.push_back(*m); }
  void OnState(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { states.push_back(*m); }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const sim_status_t* m) { statuses.push_back(*m); }
  void OnPose(const lcm::ReceiveBuffer*, const std::string&) { ++poses; }
};

control_command_t Command(double v) {
  control_command_t c{};
  c.v_mps = v;
  c.num_joints = 7;
  c.qdot_radps.assign(7, 0.0);
  return c;
}

class SimProcess : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("sim");
    // An empty room: nothing to hit while driving.
    WriteText(dir_ + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
    pid_ = Spawn({SimBin(), "--config", Config(), "--scene", dir_ + "/empty.json", "--name", "sim-under-test"},
                 dir_ + "/out.txt");
    watcher_ = std::make_unique<HeartbeatWatcher>();
    watcher_->lcm().subscribe(std::string(channels::ROBOT_STATE), &Listener::OnState, &listener_);
    watcher_->lcm().subscribe(std::string(channels::SIM_STATUS), &Listener::OnStatus, &listener_);
    watcher_->lcm().subscribe(std::string(channels::BASE_POSE), &Listener::OnPose, &listener_);
    watcher_->lcm().subscribe(std::string(channels::POINT_CLOUD), &Listener::OnCloud, &listener_);
    ASSERT_TRUE(watcher_->SpinUntil([&] { return watcher_->last.contains("sim-under-test"); }, 10.0))
        << ReadText(dir_ + "/out.txt");
  }
  void TearDown() override {
    if (pid_ > 0 && launch::ProcessAlive(pid_)) {
      kill(pid_, SIGKILL);
      WaitFor(pid_, 3.0);
    }
  }
  int Stop() {
    kill(pid_, SIGTERM);
    const int status = WaitFor(pid_, 5.0);
    pid_ = -1;
    return status;
  }
  void Drive(double v, double seconds) {
    const Clock::time_point start = Clock::now();
    while (SecondsSince(start) < seconds) {
      const control_command_t c = Command(v);
      watcher_->lcm().publish(std::string(channels::CONTROL_COMMAND), &c);
      watcher_->Spin(0.02);
    }
  }

  std::string dir_;
  pid_t pid_ = -1;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  Listener listener_;
};

TEST_F(SimProcess, PublishesStateAt100HzAndStatusAt10Hz) {
  listener_.states.clear();
  listener_.statuses.clear();
  listener_.poses = 0;
  listener_.clouds.clear();
  watcher_->Spin(2.0);
  // The LiDAR at 10 Hz (a large message: LCM 1.3 may lose a fragmented one under load).
  EXPECT_GE(listener_.clouds.size(), 10u);
  EXPECT_LE(listener_.clouds.size(), 22u);
  if (!listener_.clouds.empty()) {
    const point_cloud_t& cloud = listener_.clouds.back();
    ASSERT_FALSE(listener_.statuses.empty());
    const std::int64_t start_utime = listener_.statuses.back().utime - std::llround(listener_.statuses.back().sim_time_s * 1e6);
    EXPECT_EQ((cloud.utime - start_utime) % 100'000, 0);  // on the 10 Hz grid of sim time
    EXPECT_GT(cloud.num_coords, 3 * 1000);  // the stowed arm and the chassis give self hits at least
    EXPECT_EQ(cloud.sensor_frame, "lidar");
  }
  const std::size_t n = listener_.states.size();
  EXPECT_GT(n, 160u);
  EXPECT_LT(n, 240u);
  EXPECT_NEAR(listener_.poses, static_cast<int>(n), 3);
  EXPECT_GE(listener_.statuses.size(), 15u);
  EXPECT_LE(listener_.statuses.size(), 25u);
  ASSERT_GT(n, 2u);
  // Consecutive states are 10 ms of sim time apart; utime tracks the wall clock at rate 1.
  EXPECT_EQ(listener_.states[n - 1].utime - listener_.states[n - 2].utime, 10'000);
  EXPECT_LT(std::abs(listener_.states.back().utime - procs::NowUtime()), 200'000);
  EXPECT_EQ(listener_.states.back().joints.num_joints, 7);
  EXPECT_EQ(listener_.states.back().joints.names[0], "joint1");
  const sim_status_t& s = listener_.statuses.back();
  EXPECT_GT(s.sim_time_s, 1.5);
  EXPECT_NEAR(s.real_time_factor, 1.0, 0.2);
  EXPECT_EQ(s.target_rate, 1.0);
  EXPECT_EQ(s.boxes_present, 1);
  EXPECT_EQ(Stop(), 0);
  EXPECT_NE(ReadText(dir_ + "/out.txt").find("final: sim time"), std::string::npos);
}

// A stall longer than the pacer catches up (1 s) used to leave the sim's clock behind the wall
// clock for good: the estimator then took every BASE_POSE for too old and held the robot.
TEST_F(SimProcess, AfterAStallItsStampsKeepTheWallClock) {
  watcher_->Spin(0.5);
  kill(pid_, SIGSTOP);
  std::this_thread::sleep_for(std::chrono::seconds(3));
  kill(pid_, SIGCONT);
  listener_.states.clear();
  watcher_->Spin(1.5);
  ASSERT_GT(listener_.states.size(), 2u);
  for (std::size_t k = 1; k < listener_.states.size(); ++k) {
    ASSERT_GT(listener_.states[k].utime, listener_.states[k - 1].utime) << "state " << k;
  }
  EXPECT_LT(std::abs(listener_.states.back().utime - procs::NowUtime()), 200'000)
      << "the stamps stayed behind the wall clock after the stall";
  EXPECT_EQ(Stop(), 0);
  EXPECT_NE(ReadText(dir_ + "/out.txt").find("the simulator stalled"), std::string::npos) << ReadText(dir_ + "/out.txt");
}

TEST_F(SimProcess, RejectsANaNCommandAndBrakes) {
  Drive(0.5, 1.5);
  ASSERT_FALSE(listener_.states.empty());
  EXPECT_NEAR(listener_.states.back().velocity.v_mps, 0.5, 0.02);
  // A broken tracker: NaN commands at 50 Hz from now on.
  listener_.states.clear();
  Drive(NAN, 1.5);
  ASSERT_FALSE(listener_.states.empty());
  EXPECT_EQ(listener_.states.back().velocity.v_mps, 0.0);
  for (std::size_t i = 1; i < listener_.states.size(); ++i) {
    EXPECT_LE(listener_.states[i].velocity.v_mps, listener_.states[i - 1].velocity.v_mps + 1e-4) << i;  // (the lag may still creep up before the brake)
  }
  ASSERT_TRUE(watcher_->SpinUntil([&] { return !listener_.statuses.empty() && listener_.statuses.back().commands_rejected > 50; }, 2.0));
  EXPECT_TRUE(launch::ProcessAlive(pid_));
  const Clock::time_point after = Clock::now();
  ASSERT_TRUE(watcher_->SpinUntil([&] { return watcher_->last["sim-under-test"].at > after; }, 3.0));
  EXPECT_NE(watcher_->last["sim-under-test"].status.find("rejected"), std::string::npos);
  EXPECT_NE(ReadText(dir_ + "/out.txt").find("v_mps is not finite"), std::string::npos);
}

TEST_F(SimProcess, AppliesRunTimeEvents) {
  sim_event_t e{};
  e.name = "test crate";
  e.action = sim_event_t::APPEAR;
  e.box_id = 500;
  e.has_box = true;
  e.center_m[0] = 5.0;
  e.center_m[2] = 0.5;
  for (double& s : e.size_m) s = 0.5;
  e.trigger = sim_event_t::NOW;
  watcher_->lcm().publish(std::string(channels::SIM_EVENT), &e);
  EXPECT_TRUE(watcher_->SpinUntil([&] { return !listener_.statuses.empty() && listener_.statuses.back().boxes_present == 2; }, 3.0));
  EXPECT_EQ(listener_.statuses.back().events_applied, 1);
  e.action = 7;  // malformed: refused, counted in the final report
  watcher_->lcm().publish(std::string(channels::SIM_EVENT), &e);
  watcher_->Spin(0.3);
  EXPECT_EQ(Stop(), 0);
  const std::string out = ReadText(dir_ + "/out.txt");
  EXPECT_NE(out.find("1 bad SIM_EVENT"), std::string::npos) << out;
  EXPECT_NE(out.find("test crate"), std::string::npos);
}

struct ContactListener {
  std::vector<sim_contact_t> contacts;
  void On(const lcm::ReceiveBuffer*, const std::string&, const sim_contact_t* m) { contacts.push_back(*m); }
};

TEST(SimProcessContact, ADriveIntoABoxIsReportedOnSimContact) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("sim_contact");
  WriteText(dir + "/wall.json", R"({"boxes": [{"center": [1.5, 0, 0.5], "size": [0.4, 3, 1], "yaw": 0}]})");
  const pid_t pid = Spawn({SimBin(), "--config", Config(), "--scene", dir + "/wall.json", "--name", "sim-contact"},
                          dir + "/out.txt");
  HeartbeatWatcher watcher;
  ContactListener contacts;
  Listener status;
  watcher.lcm().subscribe(std::string(channels::SIM_CONTACT), &ContactListener::On, &contacts);
  watcher.lcm().subscribe(std::string(channels::SIM_STATUS), &Listener::OnStatus, &status);
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last.contains("sim-contact"); }, 10.0)) << ReadText(dir + "/out.txt");
  const Clock::time_point start = Clock::now();
  while (SecondsSince(start) < 4.0 && contacts.contacts.empty()) {
    const control_command_t c = Command(0.5);
    watcher.lcm().publish(std::string(channels::CONTROL_COMMAND), &c);
    watcher.Spin(0.02);
  }
  ASSERT_FALSE(contacts.contacts.empty()) << ReadText(dir + "/out.txt");
  EXPECT_EQ(contacts.contacts[0].body, "base");
  EXPECT_EQ(contacts.contacts[0].box_id, 0);
  EXPECT_GT(contacts.contacts[0].depth_m, 0.0);
  // Keep pushing: the heartbeat turns ERROR (in contact), SIM_STATUS counts the event.
  const Clock::time_point pushing = Clock::now();
  while (SecondsSince(pushing) < 1.5) {
    const control_command_t c = Command(0.5);
    watcher.lcm().publish(std::string(channels::CONTROL_COMMAND), &c);
    watcher.Spin(0.02);
  }
  ASSERT_FALSE(status.statuses.empty());
  EXPECT_TRUE(status.statuses.back().in_contact);
  EXPECT_GE(status.statuses.back().contact_events, 1);
  EXPECT_GT(status.statuses.back().max_depth_m, 0.0);
  EXPECT_NE(watcher.last["sim-contact"].status.find("IN CONTACT"), std::string::npos) << watcher.last["sim-contact"].status;
  kill(pid, SIGTERM);
  const int code = WaitFor(pid, 5.0);
  EXPECT_TRUE(WIFEXITED(code) && WEXITSTATUS(code) == 0);
  const std::string out = ReadText(dir + "/out.txt");
  EXPECT_NE(out.find("CONTACT at t="), std::string::npos);
  EXPECT_NE(out.find("final: contacts"), std::string::npos) << out;
}

// kill -9 of topay-sim during a drive, restarted with the same --checkpoint: the robot is where
// it was (within the 0.1 s between checkpoints), not back at the start (docs/reliability.md
// finding 6).
TEST(SimProcessCheckpoint, ARestartedSimulatorContinuesWhereTheRobotWas) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("sim_checkpoint");
  WriteText(dir + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
  const std::string checkpoint = dir + "/checkpoint.json";
  std::remove(checkpoint.c_str());
  const std::vector<std::string> argv = {SimBin(), "--config", Config(), "--scene", dir + "/empty.json",
                                         "--name", "sim-checkpoint", "--checkpoint", checkpoint};
  pid_t pid = Spawn(argv, dir + "/out1.txt");
  HeartbeatWatcher watcher;
  Listener listener;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &Listener::OnState, &listener);
  ASSERT_TRUE(watcher.SpinUntil([&] { return !listener.states.empty(); }, 10.0)) << ReadText(dir + "/out1.txt");
  const double x0 = listener.states.back().pose.x_m;
  const Clock::time_point start = Clock::now();
  while (SecondsSince(start) < 2.0) {
    const control_command_t c = Command(0.5);
    watcher.lcm().publish(std::string(channels::CONTROL_COMMAND), &c);
    watcher.Spin(0.02);
  }
  const double x_killed = listener.states.back().pose.x_m;
  kill(pid, SIGKILL);
  WaitFor(pid, 3.0);
  ASSERT_GT(x_killed - x0, 0.5);
  // The dead simulator's last states may still wait in the socket (a loaded machine): read them
  // before the restart, or the first "new" state is an old one (still at 0.5 m/s).
  watcher.Spin(0.3);
  listener.states.clear();
  pid = Spawn(argv, dir + "/out2.txt");
  ASSERT_TRUE(watcher.SpinUntil([&] { return !listener.states.empty(); }, 10.0)) << ReadText(dir + "/out2.txt");
  // Within the 0.1 s between checkpoints at 0.5 m/s, plus what the test's own reception lags
  // behind the simulator on a loaded machine; far from the start either way.
  EXPECT_NEAR(listener.states.front().pose.x_m, x_killed, 0.15);
  EXPECT_GT(listener.states.front().pose.x_m - x0, 0.4);
  EXPECT_NEAR(listener.states.front().velocity.v_mps, 0.0, 1e-9);  // at rest
  EXPECT_NE(ReadText(dir + "/out2.txt").find("resumed from the plant checkpoint"), std::string::npos);
  kill(pid, SIGTERM);
  EXPECT_EQ(WaitFor(pid, 5.0), 0);
}

// The lockstep mode of the binary: a recorded command log replayed twice prints the same
// digests; another scene seed gives other scans. (No LCM traffic: no namespace needed.)
TEST(SimProcessLockstep, ReplayingARecordedLogTwiceGivesTheSameDigests) {
  const std::string dir = TestDir("sim_lockstep");
  const std::string log_path = dir + "/commands.lcmlog";
  {
    lcm::LogFile log(log_path, "w");
    ASSERT_TRUE(log.good());
    for (int i = 0; i < 150; ++i) {
      control_command_t c = Command(0.4);
      c.utime = 1'800'000'000'000'000 + i * 20'000;
      c.omega_radps = 0.3;
      std::vector<std::uint8_t> bytes(c.getEncodedSize());
      c.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      lcm::LogEvent event;
      event.eventnum = i;
      event.timestamp = c.utime;
      event.channel = std::string(channels::CONTROL_COMMAND);
      event.datalen = static_cast<std::int32_t>(bytes.size());
      event.data = bytes.data();
      log.writeEvent(&event);
    }
  }
  const auto digest_line = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> argv = {SimBin(), "--config", Config(), "--replay-commands", log_path};
    argv.insert(argv.end(), extra.begin(), extra.end());
    const int status = WaitFor(Spawn(argv, dir + "/" + name), 30.0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadText(dir + "/" + name);
    const std::string out = ReadText(dir + "/" + name);
    const std::size_t at = out.find("digest states");
    return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
  };
  const std::string a = digest_line({}, "a.txt"), b = digest_line({}, "b.txt");
  const std::string other = digest_line({"--scene", "cuboids", "--seed", "9"}, "c.txt");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, other);
  EXPECT_NE(a.find("(398)"), std::string::npos) << a;  // 100 Hz states to 1 s after the last command (2.98 s)
  EXPECT_NE(ReadText(dir + "/a.txt").find("core step (plant, events, monitor, localisation): median"), std::string::npos);
}

TEST(SimProcessErrors, ExitCodesForBadFilesAndFlags) {
  const std::string dir = TestDir("sim_errors");
  const auto run = [&](const std::vector<std::string>& args, const std::string& name) {
    std::vector<std::string> argv = {SimBin(), "--lcm-url", "memq://"};
    argv.insert(argv.end(), args.begin(), args.end());
    const int status = WaitFor(Spawn(argv, dir + "/" + name), 20.0);
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, ReadText(dir + "/" + name));
  };
  WriteText(dir + "/bad_scene.json", R"({"boxes": [{"center": [0, 0, 0], "size": [1, 1], "yaw": 0}]})");
  auto [code, out] = run({"--scene", dir + "/bad_scene.json"}, "scene.txt");
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find(dir + "/bad_scene.json: boxes[0].size"), std::string::npos) << out;

  std::tie(code, out) = run({"--robot", dir + "/nonexistent.urdf"}, "robot.txt");
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("nonexistent.urdf"), std::string::npos) << out;

  WriteText(dir + "/events.yaml", "events:\n  - {at_s: 2, disappear: {id: 3}, appear: {id: 4}}\n");
  std::tie(code, out) = run({"--events", dir + "/events.yaml"}, "events.txt");
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find(dir + "/events.yaml: events[0]: needs exactly one action"), std::string::npos) << out;

  WriteText(dir + "/bad_config.yaml", "plant: {step_s: -1}\n");
  std::tie(code, out) = run({"--config", dir + "/bad_config.yaml"}, "config.txt");
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("plant.step_s"), std::string::npos) << out;

  std::tie(code, out) = run({"--rate", "2", "--max-speed"}, "usage.txt");
  EXPECT_EQ(code, 2) << out;
  std::tie(code, out) = run({"--help"}, "help.txt");
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("--replay-commands"), std::string::npos);
}

}  // namespace
}  // namespace topay::test
