// The closed loop through real processes over real LCM in a private network namespace (skipped,
// with the reason, where none can be made): topay-sim NOT in follow mode (its plant integrates
// CONTROL_COMMAND with 20 ms command latency and first-order actuator lag, config/sim/sim.yaml)
// and topay-tracker. The test plays the planner: a smooth whole-body trajectory (1 m of arc,
// a 0.5 rad turn, joints 2-7 +0.3 rad
// and joint 1 +0.15 rad (its limit is 3.1 rad, the stow pose 2.899), 4 s) from the robot's state, starting 0.3 s later. The
// robot follows it: the final state is within a few cm / hundredths of a radian of the end,
// TRACKER_STATUS reports small errors and FINISHED, and the collision monitor saw no contact.

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/angles.h"
#include "tracker_test_trajectory.h"
#include "graph_test_support.h"
#include "tests/common/real_time_skip.h"
#include "procs/runtime/process_loop.h"
#include "topay/control_command_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::test {
namespace {

struct Received {
  std::vector<robot_state_t> states;
  std::vector<tracker_status_t> statuses;
  std::vector<sim_status_t> sims;
  int commands = 0;
  void OnState(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { states.push_back(*m); }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const tracker_status_t* m) { statuses.push_back(*m); }
  void OnSim(const lcm::ReceiveBuffer*, const std::string&, const sim_status_t* m) { sims.push_back(*m); }
  void OnCommand(const lcm::ReceiveBuffer*, const std::string&, const control_command_t*) { ++commands; }
};

Eigen::VectorXd Joints(const robot_state_t& s) {
  return Eigen::Map<const Eigen::VectorXd>(s.joints.position_rad.data(), s.joints.num_joints);
}

// From the stow pose: within the joint limits and clear of the chassis.
Eigen::VectorXd JointChange() {
  Eigen::VectorXd change = Eigen::VectorXd::Constant(7, 0.3);
  change[0] = 0.15;
  return change;
}

// topay-sim (driven by CONTROL_COMMAND, no LiDAR, an empty room) and topay-tracker, running in
// `dir`; returns once both heartbeat and the robot's state and the tracker's status come.
struct SimAndTracker {
  pid_t sim = 0, tracker = 0;
  ProcessGuard guard;  // both stopped on every way out of the test (an ASSERT before StopSimAndTracker)
};
SimAndTracker StartSimAndTracker(const std::string& dir, HeartbeatWatcher* watcher, Received* rx) {
  WriteText(dir + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
  const std::string config = std::string(TOPAY_SOURCE_DIR) + "/config";
  // The shipped plant (latency, lag) and robot; no LiDAR (nothing to see, and it would take a
  // core of this 2-core machine from the loop under test).
  WriteText(dir + "/sim.yaml", "robot:\n  urdf: " + config + "/robot/topay_mm.urdf\n  yaml: " + config +
                                   "/robot/topay_mm.yaml\nlidar:\n  enabled: false\n");
  SimAndTracker p;
  p.sim = Spawn({BinDir() + "/topay-sim", "--config", dir + "/sim.yaml", "--scene", dir + "/empty.json", "--name", "sim"},
                dir + "/sim.txt");
  p.tracker = Spawn({BinDir() + "/topay-tracker", "--config", config + "/tracker/tracker.yaml", "--name", "tracker"},
                    dir + "/tracker.txt");
  p.guard.Add(p.sim);
  p.guard.Add(p.tracker);
  watcher->lcm().subscribe(std::string(channels::ROBOT_STATE), &Received::OnState, rx);
  watcher->lcm().subscribe(std::string(channels::TRACKER_STATUS), &Received::OnStatus, rx);
  watcher->lcm().subscribe(std::string(channels::SIM_STATUS), &Received::OnSim, rx);
  watcher->lcm().subscribe(std::string(channels::CONTROL_COMMAND), &Received::OnCommand, rx);
  const bool up = watcher->SpinUntil(
      [&] {
        return watcher->last.contains("sim") && watcher->last.contains("tracker") && rx->states.size() > 10 &&
               !rx->statuses.empty();
      },
      15.0);
  EXPECT_TRUE(up) << ReadText(dir + "/sim.txt") << ReadText(dir + "/tracker.txt");
  return p;
}

// SIGTERM to both: each exits 0.
void StopSimAndTracker(const SimAndTracker& p) {
  kill(p.tracker, SIGTERM);
  kill(p.sim, SIGTERM);
  const int tracker_status = WaitFor(p.tracker, 5.0);
  const int sim_status = WaitFor(p.sim, 5.0);
  EXPECT_TRUE(WIFEXITED(tracker_status) && WEXITSTATUS(tracker_status) == 0);
  EXPECT_TRUE(WIFEXITED(sim_status) && WEXITSTATUS(sim_status) == 0);
}

TEST(TrackerGraph, SimDrivenByTheTrackerFollowsATrajectory) {
  TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD();
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("tracker_graph");
  HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  Received rx;
  const SimAndTracker processes = StartSimAndTracker(dir, &watcher, &rx);
  ASSERT_FALSE(rx.statuses.empty());
  EXPECT_EQ(rx.statuses.back().state, tracker_status_t::IDLE);

  // The planner's part: a trajectory from the state just received, starting 0.3 s later.
  const robot_state_t now = rx.states.back();
  const Eigen::Vector2d p0(now.pose.x_m, now.pose.y_m);
  const ArcYawTrajectory trajectory = TrackerTestTrajectory(p0, now.pose.yaw_rad, Joints(now), 1.0, 0.5, JointChange());
  const std::int64_t start_utime = now.utime + 300'000;
  const poly_trajectory_t msg = TrackerTestMessage(trajectory, p0, start_utime, 11);
  watcher.lcm().publish(std::string(channels::TRAJECTORY), &msg);
  rx.statuses.clear();
  watcher.Spin(trajectory.duration_s() + 0.3 + 1.5);  // past the end, the settle and the stop

  TrajectorySample end = trajectory.MakePoint();
  trajectory.Evaluate(trajectory.duration_s(), &end);
  ASSERT_FALSE(rx.states.empty());
  const robot_state_t& last = rx.states.back();
  const double position_error = std::hypot(last.pose.x_m - end.state.x_m, last.pose.y_m - end.state.y_m);
  const double yaw_error = std::abs(WrapAngle(last.pose.yaw_rad - end.state.yaw_rad));
  const double joint_error = (Joints(last) - end.state.q_rad).cwiseAbs().maxCoeff();
  double max_status_position = 0.0, max_status_yaw = 0.0, max_status_joint = 0.0;
  int tracking = 0;
  for (const tracker_status_t& s : rx.statuses) {
    if (s.state != tracker_status_t::TRACKING) continue;
    ++tracking;
    EXPECT_EQ(s.trajectory_id, 11);
    EXPECT_EQ(s.goal_id, 1);
    max_status_position = std::max(max_status_position, s.position_error_m);
    max_status_yaw = std::max(max_status_yaw, s.yaw_error_rad);
    max_status_joint = std::max(max_status_joint, s.joint_error_rad);
  }
  std::printf("closed loop: final error %.4f m, %.4f rad yaw, %.4f rad joints; TRACKER_STATUS max while tracking "
              "%.4f m, %.4f rad, %.4f rad (%d statuses)\n",
              position_error, yaw_error, joint_error, max_status_position, max_status_yaw, max_status_joint, tracking);
  EXPECT_LT(position_error, 0.03);
  EXPECT_LT(yaw_error, 0.03);
  EXPECT_LT(joint_error, 0.02);
  EXPECT_GT(tracking, 80);  // 50 Hz over ~2.5 s (a few may be lost)
  EXPECT_LT(max_status_position, 0.05);
  EXPECT_LT(max_status_yaw, 0.05);
  EXPECT_LT(max_status_joint, 0.05);
  ASSERT_FALSE(rx.statuses.empty());
  EXPECT_EQ(rx.statuses.back().state, tracker_status_t::FINISHED);
  EXPECT_EQ(rx.statuses.back().trajectory_id, 11);
  ASSERT_FALSE(rx.sims.empty());
  EXPECT_EQ(rx.sims.back().contact_events, 0);
  EXPECT_EQ(rx.sims.back().commands_rejected, 0);
  EXPECT_GT(rx.sims.back().commands_accepted, 100);

  StopSimAndTracker(processes);
  const std::string tracker_out = ReadText(dir + "/tracker.txt");
  EXPECT_NE(tracker_out.find("TRAJECTORY 11 (goal 1) accepted"), std::string::npos) << tracker_out;
  EXPECT_NE(tracker_out.find("trajectory 11 ended"), std::string::npos) << tracker_out;
  EXPECT_NE(tracker_out.find("1 became active, 0 rejected"), std::string::npos) << tracker_out;
  const std::string sim_out = ReadText(dir + "/sim.txt");
  EXPECT_NE(sim_out.find("final: contacts 0"), std::string::npos) << sim_out;
  std::printf("%s", tracker_out.c_str());
}

heartbeat_t PlannerHeartbeat(std::int32_t pid, std::int64_t seq) {
  heartbeat_t m{};
  m.utime = procs::NowUtime();
  m.process_name = "planner";
  m.pid = pid;
  m.seq = seq;
  m.health = heartbeat_t::OK;
  return m;
}

// Finding 24 through the processes: the test plays a planner (its HEARTBEAT as "planner", a
// trajectory); mid-trajectory a HEARTBEAT of a new planner process (kill -9 and restart) comes:
// the tracker reports HELD within two cycles, commands a stop within the limits, and the robot
// (the simulated plant) comes to rest; then the tracker is IDLE and no contact was seen.
TEST(TrackerGraph, APlannerRestartBrakesTheRobotOffTheDeadPlannersTrajectory) {
  TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD();
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("tracker_graph_planner_restart");
  HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  Received rx;
  const SimAndTracker processes = StartSimAndTracker(dir, &watcher, &rx);
  ASSERT_FALSE(rx.states.empty());
  const std::string heartbeat(channels::HEARTBEAT);
  heartbeat_t beat = PlannerHeartbeat(4242, 0);
  watcher.lcm().publish(heartbeat, &beat);
  const robot_state_t now = rx.states.back();
  const Eigen::Vector2d p0(now.pose.x_m, now.pose.y_m);
  const ArcYawTrajectory trajectory = TrackerTestTrajectory(p0, now.pose.yaw_rad, Joints(now), 2.0, 0.5, JointChange());
  const poly_trajectory_t msg = TrackerTestMessage(trajectory, p0, now.utime + 200'000, 21);
  watcher.lcm().publish(std::string(channels::TRAJECTORY), &msg);
  watcher.Spin(1.0);
  beat = PlannerHeartbeat(4242, 1);
  watcher.lcm().publish(heartbeat, &beat);
  watcher.Spin(0.6);
  ASSERT_FALSE(rx.states.empty());
  const double v_before = rx.states.back().velocity.v_mps;
  ASSERT_EQ(rx.statuses.back().state, tracker_status_t::TRACKING) << "moving on trajectory 21";
  ASSERT_GT(v_before, 0.1);

  beat = PlannerHeartbeat(4343, 0);  // the restarted planner's first heartbeat
  watcher.lcm().publish(heartbeat, &beat);
  const std::int64_t restart_utime = procs::NowUtime();
  rx.statuses.clear();
  rx.states.clear();
  ASSERT_TRUE(watcher.SpinUntil([&] { return !rx.statuses.empty() && rx.statuses.back().state == tracker_status_t::HELD; }, 1.0));
  const double held_after_s = 1e-6 * static_cast<double>(rx.statuses.back().utime - restart_utime);
  EXPECT_LT(held_after_s, 0.1) << "HELD within a few cycles of the restart";
  EXPECT_EQ(rx.statuses.back().trajectory_id, 0);
  ASSERT_TRUE(watcher.SpinUntil(
      [&] { return !rx.statuses.empty() && rx.statuses.back().state == tracker_status_t::IDLE; }, 5.0))
      << ReadText(dir + "/tracker.txt");
  const double rest_after_s = 1e-6 * static_cast<double>(rx.statuses.back().utime - restart_utime);
  watcher.Spin(0.3);
  ASSERT_FALSE(rx.states.empty());
  EXPECT_LT(std::abs(rx.states.back().velocity.v_mps), 0.02) << "the robot at rest";
  EXPECT_LT(std::abs(rx.states.back().velocity.omega_radps), 0.02);
  std::printf("planner restart at %.2f m/s: HELD after %.3f s, released at rest after %.3f s\n", v_before,
              held_after_s, rest_after_s);
  ASSERT_FALSE(rx.sims.empty());
  EXPECT_EQ(rx.sims.back().contact_events, 0);
  StopSimAndTracker(processes);
  const std::string tracker_out = ReadText(dir + "/tracker.txt");
  EXPECT_NE(tracker_out.find("the planner restarted (pid 4242 -> 4343"), std::string::npos) << tracker_out;
  EXPECT_NE(tracker_out.find("1 unguarded"), std::string::npos) << tracker_out;
}

}  // namespace
}  // namespace topay::test

namespace topay::test {
namespace {

// Exit codes of the stack: 1 for a config error (a misspelt key, named), 2 for a usage error.
TEST(TrackerProcess, ConfigAndUsageErrorsExitWithTheirCodes) {
  const std::string dir = TestDir("tracker_errors");
  WriteText(dir + "/typo.yaml", "nmpc:\n  horizon_step: 30\n");
  const pid_t config = Spawn({BinDir() + "/topay-tracker", "--config", dir + "/typo.yaml", "--lcm-url", "memq://"},
                             dir + "/config.txt");
  const int config_status = WaitFor(config, 10.0);
  EXPECT_TRUE(WIFEXITED(config_status) && WEXITSTATUS(config_status) == 1);
  EXPECT_NE(ReadText(dir + "/config.txt").find("nmpc.horizon_step"), std::string::npos) << ReadText(dir + "/config.txt");
  const pid_t usage = Spawn({BinDir() + "/topay-tracker", "--no-such-flag"}, dir + "/usage.txt");
  const int usage_status = WaitFor(usage, 10.0);
  EXPECT_TRUE(WIFEXITED(usage_status) && WEXITSTATUS(usage_status) == 2) << ReadText(dir + "/usage.txt");
}

}  // namespace
}  // namespace topay::test
