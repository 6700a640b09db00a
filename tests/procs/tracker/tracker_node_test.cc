// topay-tracker's node logic, in-process with the times the test chooses: a future trajectory
// becomes active at its start, older ids are ignored, a stale robot state makes it stop within
// the acceleration limits, the gripper target is forwarded, malformed input is counted (and,
// through the process loop on memq://, undecodable bytes never reach the node); an ideal
// delayed-free plant closed around it reaches the end and reports FINISHED.

#include "procs/tracker/tracker_node.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/common/angles.h"
#include "core/io/robot_loader.h"
#include "tracker_test_trajectory.h"
#include "tests/common/sanitizer_build.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::tracker {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;  // a wall-clock utime
constexpr std::int64_t kCycle = 20'000;              // 20 ms

const RobotModel& Robot() {
  static const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                                 std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  return model;
}

// The shipped options, the solve budget scaled by the build's slowdown (these tests check what
// the node does, not how fast: an over-budget solve falls back, and under ASan every one did).
TrackerOptions Options() {
  TrackerOptions o = LoadTrackerOptions(std::string(TOPAY_SOURCE_DIR) + "/config/tracker/tracker.yaml");
  o.nmpc.time_budget_s *= topay::testing::kBuildSlowdown;
  return o;
}

WholeBodyState Start() {
  WholeBodyState s;
  s.q_rad = Eigen::VectorXd::Zero(Robot().num_joints());
  return s;
}

robot_state_t StateMessage(const WholeBodyState& state, std::int64_t utime, double gripper = 0.3) {
  msgs::RobotStateEstimate e;
  e.utime = utime;
  e.state = state;
  e.qdot_radps = Eigen::VectorXd::Zero(state.q_rad.size());
  e.gripper = gripper;
  return msgs::ToMessage(e);
}

poly_trajectory_t Trajectory(std::int64_t id, std::int64_t start_utime, const WholeBodyState& from = Start()) {
  const Eigen::Vector2d p0(from.x_m, from.y_m);
  return test::TrackerTestMessage(test::TrackerTestTrajectory(p0, from.yaw_rad, from.q_rad), p0, start_utime, id);
}

// An ideal plant: the state moves by the command over dt (midpoint yaw for the base).
void MoveByCommand(const control_command_t& c, double dt, WholeBodyState* state) {
  const double yaw_mid = state->yaw_rad + 0.5 * c.omega_radps * dt;
  state->x_m += c.v_mps * dt * std::cos(yaw_mid);
  state->y_m += c.v_mps * dt * std::sin(yaw_mid);
  state->yaw_rad += c.omega_radps * dt;
  for (int j = 0; j < state->q_rad.size(); ++j) state->q_rad[j] += c.qdot_radps[j] * dt;
}

heartbeat_t PlannerBeat(std::int32_t pid, std::int64_t seq) {
  heartbeat_t m{};
  m.process_name = "planner";
  m.pid = pid;
  m.seq = seq;
  return m;
}

TEST(TrackerNode, IdleWithoutTrajectoryOrState) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  const TrackerCycle& c = node.Step(kT0);
  EXPECT_EQ(c.status.state, tracker_status_t::IDLE);
  EXPECT_EQ(c.command.v_mps, 0.0);
  EXPECT_EQ(c.command.num_joints, Robot().num_joints());
  EXPECT_EQ(c.command.trajectory_id, 0);
}

TEST(TrackerNode, FutureTrajectoryBecomesActiveAtItsStart) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnRobotState(StateMessage(Start(), kT0));
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  EXPECT_EQ(node.active_id(), 1);
  node.OnTrajectory(Trajectory(2, kT0 + 500'000), kT0 + 10'000);
  EXPECT_EQ(node.active_id(), 1);
  EXPECT_EQ(node.pending_id(), 2);
  std::int64_t now = kT0;
  for (; now < kT0 + 500'000; now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));
    const TrackerCycle& c = node.Step(now);
    EXPECT_EQ(c.status.trajectory_id, 1);
    EXPECT_EQ(c.command.trajectory_id, 1);
    EXPECT_EQ(c.status.state, tracker_status_t::TRACKING);
  }
  node.OnRobotState(StateMessage(Start(), now));
  const TrackerCycle& c = node.Step(now);  // its start: the switch
  EXPECT_EQ(node.active_id(), 2);
  EXPECT_EQ(node.pending_id(), 0);
  EXPECT_EQ(c.status.trajectory_id, 2);
  EXPECT_EQ(c.status.goal_id, 1);
  EXPECT_NEAR(c.status.t_along_s, 0.0, 1e-9);
  EXPECT_EQ(node.counts().switches, 2);
}

TEST(TrackerNode, IgnoresIdsNotNewerAndNewerPendingSupersedes) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnTrajectory(Trajectory(5, kT0), kT0);
  node.OnTrajectory(Trajectory(3, kT0), kT0);
  node.OnTrajectory(Trajectory(5, kT0), kT0);
  EXPECT_EQ(node.counts().trajectories_ignored, 2);
  EXPECT_EQ(node.active_id(), 5);
  node.OnTrajectory(Trajectory(8, kT0 + 1'000'000), kT0);
  node.OnTrajectory(Trajectory(7, kT0 + 200'000), kT0);  // older than the pending one
  EXPECT_EQ(node.counts().trajectories_ignored, 3);
  EXPECT_EQ(node.pending_id(), 8);
  node.OnTrajectory(Trajectory(9, kT0 + 300'000), kT0);
  EXPECT_EQ(node.pending_id(), 9);
  EXPECT_EQ(node.counts().pending_superseded, 1);
  node.Step(kT0 + 300'000);
  EXPECT_EQ(node.active_id(), 9);
  EXPECT_EQ(node.counts().trajectories_rejected, 0);
}

// The demo's sequence: a stop (5) running, a replan (6) pending from +600 ms, then the next
// replan (7), planned from where 6 leads at +1000 ms, arrives before 6 starts. 6 must still run
// from +600 ms to +1000 ms, then 7; a later arrival starting before both replaces both.
TEST(TrackerNode, PendingTrajectoriesThatStartEarlierRunInTurn) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnTrajectory(Trajectory(5, kT0), kT0);
  node.OnTrajectory(Trajectory(6, kT0 + 600'000), kT0 + 10'000);
  node.OnTrajectory(Trajectory(7, kT0 + 1'000'000), kT0 + 300'000);
  EXPECT_EQ(node.pending_id(), 6);
  EXPECT_EQ(node.counts().pending_superseded, 0);
  std::vector<std::int64_t> followed;
  for (std::int64_t now = kT0; now <= kT0 + 1'200'000; now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));
    const std::int64_t id = node.Step(now).status.trajectory_id;
    if (followed.empty() || followed.back() != id) followed.push_back(id);
    const std::int64_t expected = now < kT0 + 600'000 ? 5 : now < kT0 + 1'000'000 ? 6 : 7;
    ASSERT_EQ(id, expected) << "at +" << (now - kT0) / 1000 << " ms";
  }
  EXPECT_EQ(followed, (std::vector<std::int64_t>{5, 6, 7}));
  EXPECT_EQ(node.pending_id(), 0);
  EXPECT_EQ(node.counts().switches, 3);

  // 9 starts before 8 (pending): 8 would never run and is dropped; 10 starts at once and
  // replaces every pending one.
  const std::int64_t t = kT0 + 2'000'000;
  node.OnTrajectory(Trajectory(8, t + 800'000), t);
  node.OnTrajectory(Trajectory(9, t + 400'000), t);
  EXPECT_EQ(node.pending_id(), 9);
  EXPECT_EQ(node.counts().pending_superseded, 1);
  node.OnTrajectory(Trajectory(10, t + 100'000), t);
  node.OnTrajectory(Trajectory(11, t + 50'000), t + 60'000);  // its start has passed: at once
  EXPECT_EQ(node.active_id(), 11);
  EXPECT_EQ(node.pending_id(), 0);
  EXPECT_EQ(node.counts().pending_superseded, 3);
}

TEST(TrackerNode, StaleStateStopsWithinTheAccelerationLimits) {
  const TrackerLimits limits = MakeTrackerLimits(Robot());
  TrackerNode node(Options(), limits);
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  std::int64_t now = kT0;
  double v = 0.0;
  for (; now <= kT0 + 800'000; now += kCycle) {  // fresh states: tracking, moving
    node.OnRobotState(StateMessage(Start(), now));
    const TrackerCycle& c = node.Step(now);
    EXPECT_EQ(c.status.state, tracker_status_t::TRACKING);
    v = c.command.v_mps;
  }
  ASSERT_GT(v, 0.05);
  const std::int64_t last_state = now - kCycle;
  bool stopping = false;
  int held_cycles = 0;
  for (int i = 0; i < 100; ++i, now += kCycle) {  // no more states
    const TrackerCycle& c = node.Step(now);
    const double age_s = static_cast<double>(now - last_state) * 1e-6;
    if (c.status.state == tracker_status_t::HELD) {  // at rest: the trajectory dropped
      EXPECT_TRUE(stopping);
      EXPECT_EQ(c.command.v_mps, 0.0);
      EXPECT_EQ(c.status.trajectory_id, 0);
      ++held_cycles;
    } else if (age_s > 0.1 + 1e-9) {
      EXPECT_EQ(c.status.state, tracker_status_t::STOPPING) << age_s;
      EXPECT_LE(std::abs(c.command.v_mps), std::abs(v) + 1e-12);
      EXPECT_GE(std::abs(c.command.v_mps), std::abs(v) - limits.base.a_max_mps2 * 0.02 - 1e-9);
      stopping = true;
    } else if (age_s < 0.1 - 1e-9) {
      EXPECT_EQ(c.status.state, tracker_status_t::TRACKING) << age_s;
    }
    v = c.command.v_mps;
  }
  EXPECT_TRUE(stopping);
  EXPECT_GT(held_cycles, 50);
  EXPECT_EQ(v, 0.0);
  EXPECT_EQ(node.counts().stops_stale, 1);
  EXPECT_EQ(node.counts().stale_holds, 1);
  EXPECT_EQ(node.active_id(), 0);
  EXPECT_TRUE(node.held());
  EXPECT_EQ(node.Health(), heartbeat_t::WARN);
  EXPECT_NE(node.StatusLine().find("held: robot state stale"), std::string::npos) << node.StatusLine();
}

TEST(TrackerNode, AfterAStaleStopAFreshStateNeverResumesTheOldTrajectory) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  std::int64_t now = kT0;
  for (; now <= kT0 + 800'000; now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));
    node.Step(now);
  }
  for (int i = 0; i < 100; ++i, now += kCycle) node.Step(now);  // 2 s without a state: stopped, held
  ASSERT_TRUE(node.held());
  node.OnTrajectory(Trajectory(2, now), now);  // planned before the planner saw HELD: dropped
  EXPECT_EQ(node.active_id(), 0);
  WholeBodyState moved = Start();  // the state comes back 1.7 m away (localisation re-anchored)
  moved.x_m = 1.7;
  int released = 0;
  for (int i = 0; i < 20; ++i, now += kCycle) {  // held until the intake takes the jump (5 states)
    node.OnRobotState(StateMessage(moved, now));
    const TrackerCycle& c = node.Step(now);
    EXPECT_EQ(c.command.v_mps, 0.0);
    EXPECT_EQ(c.command.omega_radps, 0.0);
    if (node.held()) {
      EXPECT_EQ(released, 0);
      EXPECT_EQ(c.status.state, tracker_status_t::HELD);
      continue;
    }
    EXPECT_EQ(c.status.state, tracker_status_t::IDLE);  // released at rest: no trajectory to chase
    ++released;
  }
  EXPECT_GE(released, 10);
  node.OnTrajectory(Trajectory(3, now, moved), now);  // planned from where the robot is: followed
  EXPECT_EQ(node.active_id(), 3);
  node.OnRobotState(StateMessage(moved, now + kCycle));
  EXPECT_EQ(node.Step(now + kCycle).status.state, tracker_status_t::TRACKING);
}

// Tracking lost: the robot state jumps 0.6 m from the reference (a simulator restarted at its
// checkpoint, a state re-anchored): the trajectory is dropped, the command brakes within the
// acceleration limits under status HELD (trajectories meanwhile dropped), and at rest the tracker
// is released, IDLE, and follows a new trajectory. Before, the NMPC drove straight at the
// reference (fault campaign: the base into a box).
TEST(TrackerNode, TrackingLostBrakesWithinTheLimitsHeldThenReleasesAtRest) {
  const TrackerLimits limits = MakeTrackerLimits(Robot());
  TrackerOptions options = Options();
  options.jump_position_m = 0.0;  // the loss by the error alone (the jump check would see it first)
  TrackerNode node(options, limits);
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  std::int64_t now = kT0;
  double v = 0.0;
  for (; now <= kT0 + 800'000; now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));  // the robot stays behind: the error grows
    const TrackerCycle& c = node.Step(now);
    if (c.status.state != tracker_status_t::TRACKING) break;
    v = c.command.v_mps;
  }
  ASSERT_EQ(node.counts().losses, 0) << "the robot 0.8 s behind is not yet lost";
  ASSERT_GT(v, 0.05);
  WholeBodyState off = Start();
  off.x_m = -0.6;  // the state jumps 0.6 m back
  bool held = false, released = false;
  for (int i = 0; i < 200 && !released; ++i, now += kCycle) {
    node.OnRobotState(StateMessage(off, now));
    const TrackerCycle& c = node.Step(now);
    if (c.status.state == tracker_status_t::HELD) {
      held = true;
      EXPECT_EQ(c.status.trajectory_id, 0);
      EXPECT_LE(std::abs(c.command.v_mps), std::abs(v) + 1e-12);  // braking, within the limits
      EXPECT_GE(std::abs(c.command.v_mps), std::abs(v) - limits.base.a_max_mps2 * 0.02 - 1e-9);
      if (node.held()) {  // still braking: a trajectory meanwhile is dropped
        node.OnTrajectory(Trajectory(2 + i, now), now);
        EXPECT_EQ(node.active_id(), 0);
      }
    } else if (held) {
      EXPECT_EQ(c.status.state, tracker_status_t::IDLE);
      EXPECT_EQ(c.command.v_mps, 0.0);
      released = true;
    }
    v = c.command.v_mps;
  }
  EXPECT_TRUE(held);
  EXPECT_TRUE(released);
  EXPECT_EQ(node.counts().losses, 1);
  EXPECT_FALSE(node.held());
  node.OnTrajectory(Trajectory(1000, now, off), now);  // planned from where the robot stopped
  EXPECT_EQ(node.active_id(), 1000);
  node.OnRobotState(StateMessage(off, now + kCycle));
  EXPECT_EQ(node.Step(now + kCycle).status.state, tracker_status_t::TRACKING);
}

// lost_position_m 0: the tracker never gives up on a reference (the option's off switch).
TEST(TrackerNode, TrackingLossCanBeSwitchedOff) {
  TrackerOptions options = Options();
  options.lost_position_m = 0.0;
  options.jump_position_m = 0.0;
  TrackerNode node(options, MakeTrackerLimits(Robot()));
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  WholeBodyState off = Start();
  off.x_m = -0.6;
  std::int64_t now = kT0;
  for (int i = 0; i < 5; ++i, now += kCycle) {  // the intake takes the jump after 5 states
    node.OnRobotState(StateMessage(Start(), now));
    node.Step(now);
  }
  for (int i = 0; i < 20; ++i, now += kCycle) {
    node.OnRobotState(StateMessage(off, now));
    node.Step(now);
  }
  EXPECT_EQ(node.counts().losses, 0);
  EXPECT_EQ(node.active_id(), 1);
}

// Finding 22: the robot state jumps 0.07 m and 0.17 rad in 10 ms (an estimator re-initialised
// after a simulator restart), within the continuity gate's slack but far beyond the robot's
// limits: the tracker brakes off the trajectory (HELD, then IDLE at rest) instead of steering
// back onto a reference that is no longer where the robot is. The same stream without the jump
// tracks on; jump_* 0 switches the check off.
TEST(TrackerNode, AJumpOfTheRobotStateBrakesOffTheTrajectory) {
  for (const bool enabled : {true, false}) {
    TrackerOptions options = Options();
    options.nmpc.latency_s = 0.0;
    if (!enabled) options.jump_position_m = options.jump_yaw_rad = 0.0;
    TrackerNode node(options, MakeTrackerLimits(Robot()));
    node.OnTrajectory(Trajectory(1, kT0), kT0);
    WholeBodyState state = Start();
    std::int64_t now = kT0;
    for (; now <= kT0 + 1'000'000; now += kCycle) {  // two states per cycle: 100 Hz
      node.OnRobotState(StateMessage(state, now - kCycle / 2));
      node.OnRobotState(StateMessage(state, now));
      const TrackerCycle& c = node.Step(now);
      ASSERT_EQ(c.status.state, tracker_status_t::TRACKING);
      MoveByCommand(c.command, 0.02, &state);
    }
    EXPECT_EQ(node.counts().jumps, 0) << "smooth driving is no jump";
    state.x_m += 0.05;
    state.y_m -= 0.05;
    state.yaw_rad += 0.17;
    node.OnRobotState(StateMessage(state, now - kCycle / 2));
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    if (!enabled) {
      EXPECT_EQ(c.status.state, tracker_status_t::TRACKING);
      EXPECT_EQ(node.counts().jumps, 0);
      continue;
    }
    EXPECT_EQ(c.status.state, tracker_status_t::HELD);
    EXPECT_EQ(node.counts().jumps, 1);
    EXPECT_EQ(node.active_id(), 0);
    EXPECT_NE(node.StatusLine().find("the robot state jumped"), std::string::npos) << node.StatusLine();
    bool released = false;
    for (int i = 0; i < 200 && !released; ++i) {
      now += kCycle;
      node.OnRobotState(StateMessage(state, now));
      const TrackerCycle& braking = node.Step(now);
      released = braking.status.state == tracker_status_t::IDLE;
      MoveByCommand(braking.command, 0.02, &state);
    }
    EXPECT_TRUE(released);
    EXPECT_EQ(node.counts().losses, 0);
  }
}

// Finding 24: the planner restarted (a HEARTBEAT from a new process) while the robot drove on its
// predecessor's trajectory, which nobody checks against the map any more: the trajectories are
// dropped, the robot brakes within the limits under HELD (a trajectory meanwhile dropped), and at
// rest the tracker is IDLE and follows the new planner's trajectory.
TEST(TrackerNode, APlannerRestartBrakesOffTheTrajectoriesItNoLongerGuards) {
  const TrackerLimits limits = MakeTrackerLimits(Robot());
  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode node(options, limits);
  node.OnHeartbeat(PlannerBeat(100, 0), kT0);
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  node.OnTrajectory(Trajectory(2, kT0 + 3'000'000), kT0);  // pending
  WholeBodyState state = Start();
  std::int64_t now = kT0;
  double v = 0.0;
  for (; now <= kT0 + 700'000; now += kCycle) {
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    ASSERT_EQ(c.status.state, tracker_status_t::TRACKING);
    v = c.command.v_mps;
    MoveByCommand(c.command, 0.02, &state);
  }
  ASSERT_GT(v, 0.05);
  node.OnHeartbeat(PlannerBeat(100 ^ 1, 0), now);  // another pid, the live planner's seq 0.7 s on
  EXPECT_EQ(node.counts().unguarded, 0) << "a stray (bit-flipped) copy is not a restart";
  node.OnHeartbeat(PlannerBeat(100, 1), now);
  node.OnHeartbeat(PlannerBeat(250, 0), now + 1000);  // kill -9, restarted: counts from 0
  EXPECT_EQ(node.counts().unguarded, 1);
  EXPECT_TRUE(node.held());
  EXPECT_EQ(node.active_id(), 0);
  EXPECT_EQ(node.pending_id(), 0);
  EXPECT_NE(node.StatusLine().find("the planner restarted"), std::string::npos) << node.StatusLine();
  bool released = false;
  int held_cycles = 0;
  for (int i = 0; i < 200 && !released; ++i, now += kCycle) {
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    if (c.status.state == tracker_status_t::HELD) {
      ++held_cycles;
      EXPECT_LE(std::abs(c.command.v_mps), std::abs(v) + 1e-12);  // braking, within the limits
      EXPECT_GE(std::abs(c.command.v_mps), std::abs(v) - limits.base.a_max_mps2 * 0.02 - 1e-9);
      if (node.held()) {
        node.OnTrajectory(Trajectory(10 + i, now, state), now);  // meanwhile: dropped
        EXPECT_EQ(node.active_id(), 0);
      }
    } else {
      EXPECT_EQ(c.status.state, tracker_status_t::IDLE);
      EXPECT_EQ(c.command.v_mps, 0.0);
      released = true;
    }
    v = c.command.v_mps;
    MoveByCommand(c.command, 0.02, &state);
  }
  EXPECT_GT(held_cycles, 3);
  EXPECT_TRUE(released);
  node.OnTrajectory(Trajectory(1000, now, state), now);  // the new planner's, from rest
  EXPECT_EQ(node.active_id(), 1000);
  node.OnRobotState(StateMessage(state, now + kCycle));
  EXPECT_EQ(node.Step(now + kCycle).status.state, tracker_status_t::TRACKING);
  EXPECT_EQ(node.counts().losses, 0);
  EXPECT_NE(node.Report().find("1 unguarded"), std::string::npos) << node.Report();
}

// A planner heard once and then silent for planner_watch.silence_s guards nothing: the robot
// brakes off its trajectory; a planner that keeps its heartbeat does not stop it.
TEST(TrackerNode, ASilentPlannerBrakesTheRobotOffItsTrajectory) {
  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode node(options, MakeTrackerLimits(Robot()));
  node.OnHeartbeat(PlannerBeat(100, 0), kT0);
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  WholeBodyState state = Start();
  std::int64_t now = kT0;
  std::int64_t braked_at = 0;
  for (; now <= kT0 + 3'800'000 && braked_at == 0; now += kCycle) {
    if (now <= kT0 + 500'000 && (now - kT0) % 250'000 == 0) {
      node.OnHeartbeat(PlannerBeat(100, (now - kT0) / 250'000), now);  // the last at kT0 + 0.5 s
    }
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    if (c.status.state == tracker_status_t::HELD) braked_at = now;
    MoveByCommand(c.command, 0.02, &state);
  }
  ASSERT_NE(braked_at, 0) << node.StatusLine();
  EXPECT_GT(braked_at, kT0 + 3'500'000) << "3 s after the last heartbeat at 0.5 s, not before";
  EXPECT_LE(braked_at, kT0 + 3'500'000 + 2 * kCycle);
  EXPECT_EQ(node.counts().unguarded, 1);
  EXPECT_EQ(node.counts().losses, 0);
  EXPECT_NE(node.StatusLine().find("the planner is silent"), std::string::npos) << node.StatusLine();
}

// A restart while the robot is at rest at a finished trajectory's end, or with no trajectory,
// stops nothing; a tracker that never heard a planner (fed by a tool) is never stopped by it.
TEST(TrackerNode, APlannerRestartWithNothingUnderWayStopsNothing) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnHeartbeat(PlannerBeat(100, 0), kT0);
  node.OnHeartbeat(PlannerBeat(100, 1), kT0 + 1'000'000);
  node.OnHeartbeat(PlannerBeat(200, 0), kT0 + 1'500'000);
  EXPECT_EQ(node.planner_watch().restarts(), 1);
  EXPECT_EQ(node.counts().unguarded, 0);
  EXPECT_FALSE(node.held());

  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode unwatched(options, MakeTrackerLimits(Robot()));
  unwatched.OnTrajectory(Trajectory(1, kT0), kT0);
  WholeBodyState state = Start();
  for (std::int64_t now = kT0; now < kT0 + 3'600'000; now += kCycle) {
    unwatched.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = unwatched.Step(now);
    ASSERT_EQ(c.status.state, tracker_status_t::TRACKING) << (now - kT0) * 1e-6 << " s";
    MoveByCommand(c.command, 0.02, &state);
  }
  EXPECT_EQ(unwatched.counts().unguarded, 0);
}

drive_status_t Drives(std::int8_t state, const std::string& reason = "") {
  drive_status_t m{};
  m.state = state;
  m.stop_reason = reason;
  return m;
}

TEST(TrackerNode, DrivesNotRunningHoldAtExactZeroAndDropTrajectories) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnDriveStatus(Drives(drive_status_t::RUNNING));
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  node.OnTrajectory(Trajectory(2, kT0 + 2'000'000), kT0);  // pending
  std::int64_t now = kT0;
  for (; now <= kT0 + 600'000; now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));
    node.Step(now);
  }
  ASSERT_GT(node.Step(now).command.v_mps, 0.05);  // moving
  node.OnDriveStatus(Drives(drive_status_t::STOPPED, "no CAN heartbeat from node 3"));
  EXPECT_TRUE(node.held());
  EXPECT_EQ(node.active_id(), 0);
  EXPECT_EQ(node.pending_id(), 0);
  node.OnTrajectory(Trajectory(3, now), now);  // arrives while held: dropped too
  EXPECT_EQ(node.active_id(), 0);
  EXPECT_EQ(node.counts().holds, 1);
  EXPECT_EQ(node.counts().trajectories_dropped_held, 3);
  for (int i = 0; i < 10; ++i, now += kCycle) {
    node.OnRobotState(StateMessage(Start(), now));
    const TrackerCycle& c = node.Step(now);
    EXPECT_EQ(c.status.state, tracker_status_t::HELD);
    EXPECT_EQ(c.status.trajectory_id, 0);
    EXPECT_EQ(c.command.v_mps, 0.0);  // exact zeros: what the bridge waits for
    EXPECT_EQ(c.command.omega_radps, 0.0);
    for (double qd : c.command.qdot_radps) EXPECT_EQ(qd, 0.0);
    EXPECT_EQ(c.command.gripper, 0.3);  // the measured gripper, kept
  }
  EXPECT_EQ(node.Health(), heartbeat_t::WARN);
  EXPECT_NE(node.StatusLine().find("no CAN heartbeat from node 3"), std::string::npos) << node.StatusLine();
  node.OnDriveStatus(Drives(drive_status_t::FAULT, "EMCY 0x8130"));  // still held, counted once
  node.OnDriveStatus(Drives(drive_status_t::RECOVERING));
  EXPECT_EQ(node.counts().holds, 1);
  node.OnDriveStatus(Drives(drive_status_t::RUNNING));
  EXPECT_FALSE(node.held());
  node.OnRobotState(StateMessage(Start(), now));
  const TrackerCycle& idle = node.Step(now);
  EXPECT_EQ(idle.status.state, tracker_status_t::IDLE);
  EXPECT_EQ(idle.command.v_mps, 0.0);
  node.OnTrajectory(Trajectory(4, now), now);  // the planner's new one: followed
  EXPECT_EQ(node.active_id(), 4);
  now += kCycle;
  node.OnRobotState(StateMessage(Start(), now));
  EXPECT_EQ(node.Step(now).status.state, tracker_status_t::TRACKING);
}

TEST(TrackerNode, ReplayedDriveStatusNeverHolds) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnDriveStatus(Drives(drive_status_t::REPLAY));
  EXPECT_FALSE(node.held());
  node.OnDriveStatus(Drives(drive_status_t::STARTING));  // a bridge starting: held until RUNNING
  EXPECT_TRUE(node.held());
  EXPECT_EQ(node.Step(kT0).status.state, tracker_status_t::HELD);
}

TEST(TrackerNode, NoStateEverStopsToo) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  const TrackerCycle& c = node.Step(kT0 + kCycle);
  EXPECT_EQ(c.status.state, tracker_status_t::STOPPING);
  EXPECT_EQ(c.command.v_mps, 0.0);
}

TEST(TrackerNode, ForwardsTheLatestGripperTarget) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  node.OnRobotState(StateMessage(Start(), kT0, 0.3));
  EXPECT_DOUBLE_EQ(node.Step(kT0).command.gripper, 0.3);  // none asked yet: hold the measured one
  gripper_command_t g{};
  g.position = 1.0;
  g.source = "test";
  node.OnGripper(g);
  EXPECT_DOUBLE_EQ(node.Step(kT0 + kCycle).command.gripper, 1.0);
  g.position = 2.0;  // out of [0, 1]: rejected
  node.OnGripper(g);
  g.position = std::nan("");
  node.OnGripper(g);
  EXPECT_DOUBLE_EQ(node.Step(kT0 + 2 * kCycle).command.gripper, 1.0);
  EXPECT_EQ(node.counts().grippers, 1);
  EXPECT_EQ(node.counts().grippers_rejected, 2);
  g.position = 0.0;
  node.OnGripper(g);
  EXPECT_DOUBLE_EQ(node.Step(kT0 + 3 * kCycle).command.gripper, 0.0);
}

TEST(TrackerNode, MalformedMessagesAreCountedNeverFollowed) {
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  poly_trajectory_t counts = Trajectory(1, kT0);
  counts.num_coeffs -= 1;  // disagrees with the array
  counts.coeffs.pop_back();
  node.OnTrajectory(counts, kT0);
  poly_trajectory_t not_minco = Trajectory(2, kT0);
  not_minco.coeffs[(0 * 9 + 4) * 6 + 5] += 0.1;
  node.OnTrajectory(not_minco, kT0);
  poly_trajectory_t nan = Trajectory(3, kT0);
  nan.coeffs[7] = std::nan("");
  node.OnTrajectory(nan, kT0);
  EXPECT_EQ(node.counts().trajectories_rejected, 3);
  EXPECT_EQ(node.active_id(), 0);
  robot_state_t state = StateMessage(Start(), kT0);
  state.pose.x_m = std::nan("");
  node.OnRobotState(state);
  robot_state_t joints = StateMessage(Start(), kT0);
  joints.joints.num_joints = 2;
  joints.joints.position_rad.resize(2);
  joints.joints.velocity_radps.resize(2);
  joints.joints.effort_Nm.resize(2);
  joints.joints.names.resize(2);
  node.OnRobotState(joints);
  EXPECT_EQ(node.counts().states_rejected, 2);
  EXPECT_EQ(node.counts().states, 0);
  EXPECT_EQ(node.Step(kT0).status.state, tracker_status_t::IDLE);
  // A good one after the bad ones is followed.
  node.OnTrajectory(Trajectory(4, kT0), kT0);
  EXPECT_EQ(node.active_id(), 4);
}

TEST(TrackerNode, UndecodableBytesAreCountedByTheLoop) {
  procs::ProcessOptions process;
  process.lcm_url = "memq://";
  process.name = "tracker-test";
  procs::ProcessLoop loop(process);
  ASSERT_TRUE(loop.ok());
  TrackerNode node(Options(), MakeTrackerLimits(Robot()));
  ConnectTrackerNode(&loop, &node, 0.02);
  const std::vector<std::uint8_t> garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  for (const char* channel : {"TRAJECTORY", "ROBOT_STATE", "GRIPPER_COMMAND"}) {
    loop.lcm().publish(channel, garbage.data(), static_cast<unsigned>(garbage.size()));
  }
  const poly_trajectory_t good = Trajectory(1, procs::NowUtime());
  loop.lcm().publish(std::string(channels::TRAJECTORY), &good);
  loop.RunUntil(procs::ProcessLoop::Clock::now() + std::chrono::milliseconds(100));
  EXPECT_EQ(loop.stats().Of("TRAJECTORY").malformed, 1);
  EXPECT_EQ(loop.stats().Of("ROBOT_STATE").malformed, 1);
  EXPECT_EQ(loop.stats().Of("GRIPPER_COMMAND").malformed, 1);
  EXPECT_EQ(node.counts().trajectories, 1);
  EXPECT_EQ(node.active_id(), 1);
  EXPECT_GE(node.counts().cycles, 3);  // the timer ran, publishing commands
}

// A new trajectory (here one from rest where the moving robot is: the reference jumps) switches
// over without a jump in the command: every input changes by at most its acceleration limit
// times the control period, across the switch too.
TEST(TrackerNode, SwitchingDoesNotJumpTheCommand) {
  const TrackerLimits limits = MakeTrackerLimits(Robot());
  TrackerNode node(Options(), limits);
  WholeBodyState state = Start();
  node.OnTrajectory(Trajectory(1, kT0), kT0);
  control_command_t last{};
  last.qdot_radps.assign(7, 0.0);
  bool switched = false;
  double v_at_switch = 0.0;
  for (std::int64_t now = kT0; now < kT0 + 3'000'000; now += kCycle) {
    if (now == kT0 + 1'500'000) node.OnTrajectory(Trajectory(2, now + 200'000, state), now);
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    if (!switched && c.command.trajectory_id == 2) {
      switched = true;
      v_at_switch = last.v_mps;
    }
    EXPECT_LE(std::abs(c.command.v_mps - last.v_mps), limits.base.a_max_mps2 * 0.02 + 1e-9) << now - kT0;
    EXPECT_LE(std::abs(c.command.omega_radps - last.omega_radps), limits.base.beta_max_radps2 * 0.02 + 1e-9);
    for (int j = 0; j < 7; ++j) {
      EXPECT_LE(std::abs(c.command.qdot_radps[j] - last.qdot_radps[j]), limits.qdd_max_radps2[j] * 0.02 + 1e-9);
    }
    last = c.command;
    MoveByCommand(c.command, 0.02, &state);
  }
  EXPECT_TRUE(switched);
  EXPECT_GT(v_at_switch, 0.1);  // it was moving when the new one took over
  EXPECT_EQ(node.active_id(), 2);
}

// An ideal plant (the commands integrated exactly, no latency) closed around the node.
TEST(TrackerNode, ClosedLoopOnAnIdealPlantReachesTheEndAndFinishes) {
  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode node(options, MakeTrackerLimits(Robot()));
  WholeBodyState state = Start();
  const ArcYawTrajectory trajectory = test::TrackerTestTrajectory(Eigen::Vector2d::Zero(), 0.0, state.q_rad);
  node.OnTrajectory(Trajectory(1, kT0 + 100'000), kT0);
  double max_position_error = 0.0;
  std::int8_t last_state = -1;
  for (std::int64_t now = kT0; now < kT0 + 6'000'000; now += kCycle) {
    node.OnRobotState(StateMessage(state, now));
    const TrackerCycle& c = node.Step(now);
    last_state = c.status.state;
    if (c.status.state == tracker_status_t::TRACKING) {
      max_position_error = std::max(max_position_error, c.status.position_error_m);
    }
    MoveByCommand(c.command, 0.02, &state);
  }
  TrajectorySample end = trajectory.MakePoint();
  trajectory.Evaluate(trajectory.duration_s(), &end);
  EXPECT_EQ(last_state, tracker_status_t::FINISHED);
  EXPECT_LT(std::hypot(state.x_m - end.state.x_m, state.y_m - end.state.y_m), 0.01);
  EXPECT_LT(std::abs(WrapAngle(state.yaw_rad - end.state.yaw_rad)), 0.01);
  EXPECT_LT((state.q_rad - end.state.q_rad).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_LT(max_position_error, 0.03);
  EXPECT_EQ(node.counts().stops_ended, 1);
  EXPECT_NE(node.Report().find("topay-tracker: 300 cycles"), std::string::npos) << node.Report();
}

// The protective field (finding 30): a wall of LiDAR points across (or beside) the test
// trajectory, which turns left 0.5 rad over its 1 m: in W, the sensor at the origin.
point_cloud_t WallScan(double x_from, double x_to, double y_from, double y_to, std::int64_t utime) {
  point_cloud_t msg{};
  msg.utime = utime;
  msg.sensor_frame = "lidar";
  msg.quat_WS[0] = 1.0;
  const int n = 30;
  for (int i = 0; i <= n; ++i) {
    for (const double z : {0.1, 0.2, 0.3}) {
      msg.p_SP.push_back(static_cast<float>(x_from + (x_to - x_from) * i / n));
      msg.p_SP.push_back(static_cast<float>(y_from + (y_to - y_from) * i / n));
      msg.p_SP.push_back(static_cast<float>(z));
    }
  }
  msg.num_coords = static_cast<std::int32_t>(msg.p_SP.size());
  return msg;
}

struct FieldRun {
  WholeBodyState state;
  std::int8_t last_state = -1;
  double max_speed_step = 0.0;  // largest |v_k - v_k-1|, m/s
};

// The ideal plant closed around the node for 6 s, a scan of `wall` every 100 ms.
FieldRun RunWithWall(TrackerNode* node, const point_cloud_t& wall) {
  FieldRun run;
  run.state = Start();
  node->OnTrajectory(Trajectory(1, kT0 + 100'000), kT0);
  double v_before = 0.0;
  for (std::int64_t now = kT0; now < kT0 + 6'000'000; now += kCycle) {
    node->OnRobotState(StateMessage(run.state, now));
    if ((now - kT0) % 100'000 == 0) {
      point_cloud_t scan = wall;
      scan.utime = now;
      node->OnPointCloud(scan);
    }
    const TrackerCycle& c = node->Step(now);
    run.last_state = c.status.state;
    run.max_speed_step = std::max(run.max_speed_step, std::abs(c.command.v_mps - v_before));
    v_before = c.command.v_mps;
    MoveByCommand(c.command, 0.02, &run.state);
  }
  return run;
}

TEST(TrackerNode, AnObstacleOnThePathAheadBrakesTheRobotShortOfIt) {
  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode node(options, Robot());
  ASSERT_NE(node.protective_field(), nullptr);
  const FieldRun run = RunWithWall(&node, WallScan(0.9, 0.9, -0.6, 0.9, kT0));
  EXPECT_EQ(node.counts().protective_stops, 1);
  EXPECT_EQ(node.counts().scans, 60);
  EXPECT_EQ(node.counts().scans_rejected, 0);
  // Braked within the limits and stopped with the bumper short of the wall (x = 0.9).
  EXPECT_LE(run.max_speed_step, Robot().base_limits.a_max_mps2 * 0.02 + 1e-9);
  EXPECT_LT(run.state.x_m + Robot().base_cylinder.radius_m, 0.9);
  EXPECT_GT(run.state.x_m, 0.1);  // it drove until the field reached the wall
  EXPECT_EQ(run.last_state, tracker_status_t::IDLE);  // released at rest, the trajectory dropped
  EXPECT_EQ(node.active_id(), 0);
  EXPECT_NE(node.Report().find("protective field: on, 60 scans (0 not used), 1 stops"), std::string::npos)
      << node.Report();
}

TEST(TrackerNode, AnObstacleBesideThePathOrAFieldTurnedOffDoesNotStopTheRobot) {
  TrackerOptions options = Options();
  options.nmpc.latency_s = 0.0;
  TrackerNode beside(options, Robot());  // a wall along the path, 0.5 m to its right
  const FieldRun run_beside = RunWithWall(&beside, WallScan(-0.5, 1.5, -0.5, -0.5, kT0));
  EXPECT_EQ(beside.counts().protective_stops, 0);
  EXPECT_EQ(run_beside.last_state, tracker_status_t::FINISHED);
  EXPECT_GT(beside.counts().scans, 0);

  options.protective_field.enabled = false;
  TrackerNode off(options, Robot());
  EXPECT_EQ(off.protective_field(), nullptr);
  const FieldRun run_off = RunWithWall(&off, WallScan(0.9, 0.9, -0.6, 0.9, kT0));
  EXPECT_EQ(off.counts().protective_stops, 0);
  EXPECT_EQ(off.counts().scans, 0);
  EXPECT_EQ(run_off.last_state, tracker_status_t::FINISHED);  // through the wall: no field
  EXPECT_GT(run_off.state.x_m + Robot().base_cylinder.radius_m, 0.9);
  TrackerNode no_model(Options(), MakeTrackerLimits(Robot()));
  EXPECT_EQ(no_model.protective_field(), nullptr);
}

TEST(TrackerNode, ScansTheFieldCannotUseAreCounted) {
  TrackerNode node(Options(), Robot());
  node.OnPointCloud(WallScan(0.9, 0.9, -0.6, 0.9, kT0));  // no robot state yet
  point_cloud_t bad = WallScan(0.9, 0.9, -0.6, 0.9, kT0);
  bad.num_coords = 7;
  node.OnRobotState(StateMessage(Start(), kT0));
  node.OnPointCloud(bad);
  EXPECT_EQ(node.counts().scans_rejected, 2);
  EXPECT_EQ(node.counts().scans, 0);
  EXPECT_EQ(node.protective_field()->num_kept(), 0);
}

}  // namespace
}  // namespace topay::tracker
