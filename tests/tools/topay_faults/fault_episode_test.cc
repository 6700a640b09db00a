// FaultEpisode and FaultInjector on a real LCM bus in a private network namespace (skipped,
// with the reason, where none can be made), with the test playing the graph: it answers the
// injected fault the way the bridge would (DRIVE_STATUS STOPPED some ms later, then RUNNING and
// moving again), and the episode must time the stop and the recovery from what it saw on the
// bus. A kill -9 episode kills a real process named topay-tracker (a copy of sleep) and sees the
// "launcher's" restart (a new process whose heartbeat the test publishes).

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <mutex>
#include <optional>
#include <filesystem>
#include <thread>

#include "tests/procs/graph_test_support.h"
#include "tools/topay_faults/fault_episode.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::tools {
namespace {

using test::Clock;
using test::SecondsSince;

constexpr const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";

// Plays the graph on the bus every 5 ms: a moving robot (ACTUATOR_COMMAND) under a running bridge
// (DRIVE_STATUS, at once on a change) and a running mission, and CONTROL_COMMAND if asked. Stop()
// makes the bridge STOPPED `delay_s` after now, or after the last command once commands have
// stopped; Resume() makes it RUNNING and moving again.
class PlayedGraph {
 public:
  explicit PlayedGraph(bool send_commands) : send_commands_(send_commands), thread_([this] { Run(); }) {}
  ~PlayedGraph() {
    quit_ = true;
    thread_.join();
  }
  void Stop(const std::string& reason, double delay_s) {
    std::lock_guard<std::mutex> lock(mutex_);
    reason_ = reason;
    const Clock::time_point from = commands_stopped_ ? last_command_ : Clock::now();
    stop_at_ = from + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(delay_s));
    stopping_ = true;
  }
  void StopCommands() {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_stopped_ = true;
  }
  void Resume() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = false, commands_stopped_ = false;
  }
  // HEARTBEAT of a process with this pid every 100 ms from now on (a restarted process at work).
  void Heartbeat(pid_t pid) {
    std::lock_guard<std::mutex> lock(mutex_);
    heartbeat_pid_ = pid;
  }

 private:
  void Run() {
    lcm::LCM bus(kUrl);
    int last_state = -1;
    for (int cycle = 0; !quit_; ++cycle) {
      std::unique_lock<std::mutex> lock(mutex_);
      const Clock::time_point now = Clock::now();
      const bool halted = stopping_ && now >= stop_at_;
      const bool commands = send_commands_ && !commands_stopped_;
      if (commands) last_command_ = now;
      const std::string reason = halted ? reason_ : "";
      const pid_t heartbeat_pid = heartbeat_pid_;
      lock.unlock();
      if (heartbeat_pid > 0 && cycle % 20 == 0) {
        heartbeat_t beat{};
        beat.process_name = "tracker";
        beat.pid = heartbeat_pid;
        bus.publish("HEARTBEAT", &beat);
      }
      control_command_t command{};
      command.num_joints = 7;
      command.qdot_radps.assign(7, 0.0);
      command.v_mps = halted ? 0.0 : 0.3;
      const int state = halted ? drive_status_t::STOPPED : drive_status_t::RUNNING;
      if (state != last_state || cycle % 20 == 0) {  // the bridge: on every change, and at 10 Hz
        drive_status_t status{};
        status.state = static_cast<std::int8_t>(state);
        status.stop_reason = reason;
        bus.publish("DRIVE_STATUS", &status);
        mission_status_t mission{};
        mission.state = mission_status_t::RUNNING;
        mission.step_index = 1;
        bus.publish("MISSION_STATUS", &mission);
        last_state = state;
      }
      if (commands) bus.publish("CONTROL_COMMAND", &command);
      bus.publish("ACTUATOR_COMMAND", &command);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

  const bool send_commands_;
  std::atomic<bool> quit_{false};
  std::mutex mutex_;
  bool stopping_ = false, commands_stopped_ = false;
  Clock::time_point stop_at_{}, last_command_{};
  pid_t heartbeat_pid_ = 0;
  std::string reason_;
  std::thread thread_;
};

// The first GOAL on the bus (the injector's) and when it came, for a played planner to answer.
struct FirstGoal {
  std::mutex mutex;
  std::optional<Clock::time_point> at;
  std::int64_t id = 0;
  void On(const lcm::ReceiveBuffer*, const std::string&, const goal_t* g) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!at) at = Clock::now(), id = g->goal_id;
  }
};

FaultEpisodeOptions QuickOptions() {
  FaultEpisodeOptions options;
  options.ready_timeout_s = 10.0;
  options.recover_timeout_s = 10.0;
  options.settle_s = 0.2;
  return options;
}

class FaultEpisodeTest : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!test::EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = test::TestDir("episode");
  }
  FaultInjectorOptions InjectorOptions() const {
    FaultInjectorOptions options;
    options.lcm_url = kUrl;
    options.work_dir = dir_;
    options.graph_ancestor = getpid();
    options.room_max_m = Eigen::Vector3d(10, 10, 1.6);
    return options;
  }
  // Ticks the episode every ms until it is over (20 s at most).
  static void RunEpisode(FaultEpisode* episode, GraphMonitor* monitor,
                         const std::function<void(const GraphView&)>& on_tick = nullptr) {
    const Clock::time_point start = Clock::now();
    while (SecondsSince(start) < 20.0) {
      const GraphView view = monitor->View();
      if (on_tick) on_tick(view);
      if (episode->Tick(view)) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    FAIL() << "the episode did not end within 20 s";
  }
  // One episode of a goal fault against a played graph; `answer(listener, goal)` plays the
  // planner on every tick once the injector's goal has come (under the goal's lock).
  EpisodeResult RunGoalEpisode(const std::string& fault, int seed, const FaultInjectorOptions& options,
                               const std::function<void(lcm::LCM&, const FirstGoal&)>& answer) {
    GraphMonitor monitor(kUrl);
    FaultInjector injector(options, &monitor);
    PlayedGraph graph(false);
    lcm::LCM listener(kUrl);
    FirstGoal goal;
    listener.subscribe("GOAL", &FirstGoal::On, &goal);
    std::thread listen([&] {
      for (int k = 0; k < 500; ++k) listener.handleTimeout(10);
    });
    FaultEpisode episode(SelectFaults({fault})[0], seed, &injector, getpid(), QuickOptions());
    RunEpisode(&episode, &monitor, [&](const GraphView&) {
      std::lock_guard<std::mutex> lock(goal.mutex);
      if (goal.at) answer(listener, goal);
    });
    listen.join();
    return episode.Result();
  }
  // goal-nan with the played planner's refusal `after_s` after the goal and, if
  // `then_mission_goal`, the mission's goal's PLANNING status right behind it.
  EpisodeResult RefusedNanGoal(double after_s, bool then_mission_goal, bool* refused) {
    *refused = false;
    return RunGoalEpisode("goal-nan", 3, InjectorOptions(), [&](lcm::LCM& bus, const FirstGoal& goal) {
      if (*refused || SecondsSince(*goal.at) < after_s) return;
      planner_status_t status{};
      status.state = planner_status_t::FAILED;
      status.goal_id = goal.id;
      status.failure_reason = "bad goal: goal_t.p_WE: not finite";
      bus.publish("PLANNER_STATUS", &status);
      if (then_mission_goal) {
        status.state = planner_status_t::PLANNING;
        status.goal_id = 1796000000000001;
        status.failure_reason = "";
        bus.publish("PLANNER_STATUS", &status);
      }
      *refused = true;
    });
  }

  std::string dir_;
};


TEST_F(FaultEpisodeTest, TimesTheBridgesStopAndTheRecoveryFromTheBus) {
  GraphMonitor monitor(kUrl);
  FaultInjector injector(InjectorOptions(), &monitor);
  PlayedGraph graph(false);
  lcm::LCM listener(kUrl);
  std::atomic<int> faults_seen{0};
  struct Counter {
    std::atomic<int>* n;
    PlayedGraph* graph;
    void On(const lcm::ReceiveBuffer*, const std::string&, const motorsim_fault_t* f) {
      if (f->kind == motorsim_fault_t::BUS_OFF) ++*n, graph->Stop("bus-off", 0.05);
    }
  } counter{&faults_seen, &graph};
  listener.subscribe("MOTORSIM_FAULT", &Counter::On, &counter);
  std::thread listen([&] {
    for (int k = 0; k < 300; ++k) listener.handleTimeout(10);
  });
  FaultEpisode episode(SelectFaults({"can-bus-off"})[0], 7, &injector, getpid(), QuickOptions());
  std::optional<Clock::time_point> stopped_at;
  bool resumed = false;
  RunEpisode(&episode, &monitor, [&](const GraphView& view) {
    if (view.drive_state == drive_status_t::STOPPED && !stopped_at) {
      stopped_at = Clock::now();
      tracker_status_t held{};  // the tracker, held by the stopped drives
      held.state = tracker_status_t::HELD;
      listener.publish("TRACKER_STATUS", &held);
    }
    if (stopped_at && !resumed && SecondsSince(*stopped_at) > 1.0) graph.Resume(), resumed = true;
  });
  listen.join();
  const EpisodeResult& r = episode.Result();
  EXPECT_EQ(faults_seen.load(), 1);
  ASSERT_TRUE(r.injected) << r.notes;
  EXPECT_NE(r.notes.find("MOTORSIM_FAULT kind 3"), std::string::npos) << r.notes;
  EXPECT_EQ(r.safe_evidence, "bridge STOPPED: bus-off");
  EXPECT_GE(r.safe_ms, 50.0);    // the bridge's answer came 50 ms after the fault was seen
  EXPECT_LT(r.safe_ms, 1000.0);
  EXPECT_TRUE(r.recovered) << r.reaction;
  EXPECT_NE(r.reaction.find("tracker HELD after"), std::string::npos) << r.reaction;
  EXPECT_GE(r.recover_s, 1.0);   // RUNNING and moving again only after 1 s stopped
  EXPECT_EQ(r.contacts, 0);
}

TEST_F(FaultEpisodeTest, AKillIsTimedFromTheLastCommandAndTheRestartIsSeen) {
  const std::string tracker = dir_ + "/topay-tracker";
  std::filesystem::copy_file("/bin/sleep", tracker);
  std::filesystem::permissions(tracker, std::filesystem::perms::owner_all);
  pid_t first = test::Spawn({tracker, "60"}, dir_ + "/first.txt");
  GraphMonitor monitor(kUrl);
  FaultInjector injector(InjectorOptions(), &monitor);
  PlayedGraph graph(true);
  FaultEpisode episode(SelectFaults({"kill-tracker"})[0], 5, &injector, getpid(), QuickOptions());
  pid_t second = 0;
  Clock::time_point died{};
  RunEpisode(&episode, &monitor, [&](const GraphView&) {
    if (first > 0 && waitpid(first, nullptr, WNOHANG) == first) {  // the tracker died: no more commands
      graph.StopCommands();
      graph.Stop("stale command", 0.08);
      first = 0, died = Clock::now();
    }
    if (first == 0 && second == 0 && SecondsSince(died) > 0.5) {  // the launcher's restart
      second = test::Spawn({tracker, "60"}, dir_ + "/second.txt");
      graph.Heartbeat(second);
      graph.Resume();
    }
  });
  const EpisodeResult& r = episode.Result();
  ASSERT_TRUE(r.injected) << r.notes;
  EXPECT_NE(r.notes.find("(topay-tracker)"), std::string::npos) << r.notes;
  EXPECT_EQ(r.safe_evidence, "bridge STOPPED: stale command");
  EXPECT_GE(r.safe_ms, 75.0);  // 80 ms after the last command, on the test's clock
  EXPECT_LT(r.safe_ms, 1000.0);
  EXPECT_TRUE(r.recovered) << r.reaction;
  EXPECT_NE(r.reaction.find("restarted as pid " + std::to_string(second)), std::string::npos) << r.reaction;
  EXPECT_EQ(r.other_restarts, 0) << r.reaction;
  if (second > 0) kill(second, SIGKILL), waitpid(second, nullptr, 0);
}

// A goal-nan episode that recovered, naming the planner's refusal.
void ExpectTheRefusalSeen(const EpisodeResult& r, bool refused) {
  ASSERT_TRUE(r.injected) << r.notes;
  EXPECT_TRUE(refused);
  EXPECT_TRUE(r.recovered) << r.reaction;
  EXPECT_NE(r.reaction.find("planner: bad goal: goal_t.p_WE: not finite"), std::string::npos) << r.reaction;
}

// A refused goal stops nothing, so the robot "moves again" at once; the episode must still wait
// for the planner's refusal (it came late under load once, and the episode had ended without it).
TEST_F(FaultEpisodeTest, ARefusedGoalRecoversOnlyOnceThePlannerHasSaidWhy) {
  bool refused = false;
  const EpisodeResult r = RefusedNanGoal(1.0, false, &refused);
  ExpectTheRefusalSeen(r, refused);
  EXPECT_GE(r.recover_s, 1.0) << "recovered before the planner refused the goal";
}

// The refusal and the mission's goal's PLANNING status back to back (as the planner sends them:
// seen in FaultsSmoke under load, where the episode's poll saw only the second and waited 45 s
// for a refusal that had come): the refusal still counts.
TEST_F(FaultEpisodeTest, ARefusalTheNextGoalsStatusFollowedAtOnceIsSeen) {
  bool refused = false;
  const EpisodeResult r = RefusedNanGoal(0.5, true, &refused);
  ExpectTheRefusalSeen(r, refused);
}

// goal-in-obstacle aimed at a box the planner's map lacks: the planner takes the goal (PLANNING
// naming it), and the mission's own goal replaces it 1 s later. No refusal can come; the episode
// recovers then (not before), saying so.
TEST_F(FaultEpisodeTest, AnObstacleGoalTheMissionsGoalReplacedRecoversWithoutARefusal) {
  FaultInjectorOptions options = InjectorOptions();
  options.box_centers_m = {Eigen::Vector3d(1.0, 1.0, 0.3)};
  int answered = 0;
  const EpisodeResult r = RunGoalEpisode("goal-in-obstacle", 5, options, [&](lcm::LCM& bus, const FirstGoal& goal) {
    planner_status_t status{};
    status.state = planner_status_t::PLANNING;
    if (answered == 0 && SecondsSince(*goal.at) >= 0.2) {
      status.goal_id = goal.id;  // the planner takes the injected goal
    } else if (answered == 1 && SecondsSince(*goal.at) >= 1.0) {
      status.goal_id = 1796000000000001;  // the mission's goal again
    } else {
      return;
    }
    bus.publish("PLANNER_STATUS", &status);
    ++answered;
  });
  ASSERT_TRUE(r.injected) << r.notes;
  EXPECT_EQ(answered, 2);
  EXPECT_TRUE(r.recovered) << r.reaction;
  EXPECT_NE(r.reaction.find("superseded by the mission's goal"), std::string::npos) << r.reaction;
  EXPECT_GE(r.recover_s, 1.0) << "recovered before the mission's goal replaced the injected one";
}

// kill-canbridge, room seed 8 of the twenty-fifth session's table: "every drive commanded to 0"
// only 23.1 s after the kill. A robot that has just come to rest (moving 0.2 s ago, every drive
// at 0 since) is not injected: its stop would be a run of zeros that began before the fault.
TEST_F(FaultEpisodeTest, ARobotThatHasJustComeToRestIsNotInjectedUntilItMovesAgain) {
  GraphMonitor monitor(kUrl);
  FaultInjector injector(InjectorOptions(), &monitor);
  FaultEpisode episode(SelectFaults({"can-bus-off"})[0], 1, &injector, getpid(), QuickOptions());
  GraphView view;
  view.now_s = 10.0;
  view.drive_state = drive_status_t::RUNNING;
  view.last_drive_status_s = 9.95;
  view.mission_state = mission_status_t::RUNNING;
  view.last_moving_s = 9.8;
  view.actuator_zero = true;
  view.actuator_zero_since_s = 9.9;
  EXPECT_FALSE(episode.Tick(view));
  EXPECT_FALSE(episode.Injected());
  view.now_s = 10.5;  // moving again
  view.last_moving_s = 10.49;
  view.actuator_zero = false;
  view.actuator_zero_since_s = 9.9;
  view.last_drive_status_s = 10.45;
  EXPECT_FALSE(episode.Tick(view));
  EXPECT_TRUE(episode.Injected());
  // Then the stop: the drives braking from 10.53 s (not yet long enough to count), ...
  view.now_s = 10.55;
  view.actuator_braking_since_s = 10.53;
  view.last_actuator_s = 10.55;
  episode.Tick(view);
  EXPECT_LT(episode.Result().safe_ms, 0.0);
  // ... and at 0 from 10.56 s: the stop began at 10.53 s and ended at 10.56 s.
  view.now_s = 10.6;
  view.last_actuator_s = 10.6;
  view.actuator_zero = true;
  view.actuator_zero_since_s = 10.56;
  episode.Tick(view);
  EXPECT_NEAR(episode.Result().safe_ms, 30.0, 1e-6);
  EXPECT_EQ(episode.Result().safe_evidence, "every drive braking");
  EXPECT_NEAR(episode.Result().zero_ms, 60.0, 1e-6);
}

TEST_F(FaultEpisodeTest, ARobotThatNeverMovesIsNotInjected) {
  GraphMonitor monitor(kUrl);
  FaultInjector injector(InjectorOptions(), &monitor);
  FaultEpisodeOptions options = QuickOptions();
  options.ready_timeout_s = 0.5;
  FaultEpisode episode(SelectFaults({"can-bus-off"})[0], 1, &injector, getpid(), options);
  RunEpisode(&episode, &monitor);
  EXPECT_FALSE(episode.Result().injected);
  EXPECT_FALSE(episode.Result().refused);  // owed again, not given up
  EXPECT_NE(episode.Result().notes.find("did not move"), std::string::npos);
}

}  // namespace
}  // namespace topay::tools
