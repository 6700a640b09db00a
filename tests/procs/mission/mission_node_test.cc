// The mission sequencer's logic (procs/mission/mission_node.h) driven by direct calls: fake
// planner statuses, robot states and tracker statuses in, the goals, gripper commands and
// mission statuses it publishes recorded.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/mission/mission_node.h"
#include "procs/msgs/convert_robot_state.h"
#include "tests/common/arm_state.h"

namespace topay::mission {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;  // us
constexpr std::int64_t kFirstGoalId = 100;

std::string ConfigFile(const std::string& rel) { return std::string(TOPAY_SOURCE_DIR) + "/config/" + rel; }
std::int64_t At(double seconds) { return kT0 + static_cast<std::int64_t>(seconds * 1e6); }

class MissionNodeTest : public testing::Test {
 protected:
  MissionStep Goto(const WholeBodyState& state, const std::string& label) const {
    MissionStep step;
    step.type = StepType::kGoto;
    step.label = label;
    step.X_WE = kinematics_.EndEffectorPose(state);
    step.hint = state;
    return step;
  }
  static MissionStep Gripper(double position) {
    MissionStep step;
    step.type = StepType::kGripper;
    step.gripper_position = position;
    return step;
  }
  static MissionStep Wait(double seconds) {
    MissionStep step;
    step.type = StepType::kWait;
    step.duration_s = seconds;
    return step;
  }
  static MissionStep Home() {
    MissionStep step;
    step.type = StepType::kHome;
    return step;
  }
  void Make(std::vector<MissionStep> steps) {
    Mission mission;
    mission.name = "test";
    mission.steps = std::move(steps);
    MissionOutputs outputs;
    outputs.goal = [this](const goal_t& m) { goals_.push_back(m); };
    outputs.gripper = [this](const gripper_command_t& m) { grippers_.push_back(m); };
    outputs.status = [this](const mission_status_t& m) { statuses_.push_back(m); };
    node_ = std::make_unique<MissionNode>(mission, kinematics_, options_, outputs, kFirstGoalId);
  }
  // The robot at `state` at t_s. It moves between calls by jumps, so each call is a short
  // stream (kStreamLength states 1 ms apart, ending at t_s) that the node's continuity gate
  // takes as a new anchor.
  void Robot(const WholeBodyState& state, double t_s) {
    constexpr int kStreamLength = StateContinuityGateOptions{}.reanchor_after;
    msgs::RobotStateEstimate estimate;
    estimate.state = state;
    estimate.qdot_radps = Eigen::VectorXd::Zero(state.num_joints());
    for (int k = kStreamLength - 1; k >= 0; --k) {
      estimate.utime = std::max(At(t_s) - 1000 * k, last_state_utime_ + 1);
      last_state_utime_ = estimate.utime;
      node_->OnRobotState(msgs::ToMessage(estimate), At(t_s));
    }
  }
  std::int64_t last_state_utime_ = 0;
  void Planner(std::int64_t goal_id, std::int8_t state, double t_s, const std::string& detail = "",
               const std::string& reason = "") {
    planner_status_t m{};
    m.utime = At(t_s);
    m.state = state;
    m.goal_id = goal_id;
    m.detail = detail;
    m.failure_reason = reason;
    node_->OnPlannerStatus(m, At(t_s));
  }
  void Tracker(std::int64_t goal_id, std::int8_t state, double t_s, std::int64_t trajectory_id = 1) {
    tracker_status_t m{};
    m.utime = At(t_s);
    m.state = state;
    m.goal_id = goal_id;
    m.trajectory_id = trajectory_id;
    node_->OnTrackerStatus(m, At(t_s));
  }
  // Starts the mission at t = 0 with the robot at start_.
  void Start() {
    node_->Tick(At(0.0));
    Robot(start_, 0.0);
    EXPECT_EQ(node_->state(), mission_status_t::IDLE) << "waits for the planner";
    Planner(0, planner_status_t::IDLE, 0.0);
    EXPECT_EQ(node_->state(), mission_status_t::RUNNING);
  }
  // The planner reports the goal's trajectory ended and the robot stands at `state`.
  void Arrive(std::int64_t goal_id, const WholeBodyState& state, double t_s) {
    Planner(goal_id, planner_status_t::PLANNING, t_s - 0.5, "goal");
    Planner(goal_id, planner_status_t::SUCCEEDED, t_s - 0.4, "trajectory 1 out");
    Robot(state, t_s - 0.1);
    Planner(goal_id, planner_status_t::SUCCEEDED, t_s, "trajectory 1 ended");
  }

  RobotModel model_ = LoadRobotModel(ConfigFile("robot/topay_mm.urdf"), ConfigFile("robot/topay_mm.yaml"));
  Kinematics kinematics_{model_};
  // The goal repeat is off here (these tests count the goals sent per attempt); its own test
  // below turns it on.
  MissionOptions options_ = [] {
    MissionOptions o;
    o.goal_repeat_period_s = 0.0;
    return o;
  }();
  WholeBodyState start_ = BentArmState(0.0, 0.0, 0.0);
  WholeBodyState a_ = BentArmState(3.0, 1.0, 0.5);
  WholeBodyState b_ = BentArmState(-2.0, 2.0, -1.0);
  std::unique_ptr<MissionNode> node_;
  std::vector<goal_t> goals_;
  std::vector<gripper_command_t> grippers_;
  std::vector<mission_status_t> statuses_;
};

TEST_F(MissionNodeTest, RunsTheStepsInOrder) {
  Make({Goto(a_, "pickup"), Gripper(1.0), Wait(1.0), Goto(b_, "dropoff")});
  Start();
  ASSERT_EQ(goals_.size(), 1u);
  EXPECT_EQ(goals_[0].goal_id, kFirstGoalId);
  EXPECT_TRUE(goals_[0].has_hint);
  EXPECT_DOUBLE_EQ(goals_[0].hint.x_m, a_.x_m);
  const Eigen::Vector3d p_a = kinematics_.EndEffectorPose(a_).translation();
  EXPECT_NEAR(goals_[0].p_WE[0], p_a.x(), 1e-12);
  EXPECT_EQ(statuses_.back().state, mission_status_t::RUNNING);
  EXPECT_EQ(statuses_.back().goal_id, kFirstGoalId);
  EXPECT_EQ(statuses_.back().step, "goto pickup");

  // The trajectory ended but the robot is still at the start: not arrived.
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 5.0, "trajectory 1 ended");
  node_->Tick(At(5.1));
  EXPECT_EQ(statuses_.back().step_index, 0);
  EXPECT_TRUE(grippers_.empty());
  // Another goal's status changes nothing.
  Robot(a_, 5.2);
  EXPECT_EQ(statuses_.back().step_index, 1) << "arrived: the gripper step";
  ASSERT_EQ(grippers_.size(), 1u);
  EXPECT_DOUBLE_EQ(grippers_[0].position, 1.0);
  EXPECT_EQ(grippers_[0].source, "mission");

  node_->Tick(At(5.7));
  EXPECT_EQ(statuses_.back().step_index, 1) << "the gripper settles for 1 s";
  node_->Tick(At(6.3));
  EXPECT_EQ(statuses_.back().step_index, 2);
  node_->Tick(At(6.9));
  EXPECT_EQ(statuses_.back().step_index, 2);
  node_->Tick(At(7.4));
  EXPECT_EQ(statuses_.back().step_index, 3);
  ASSERT_EQ(goals_.size(), 2u);
  EXPECT_EQ(goals_[1].goal_id, kFirstGoalId + 1) << "a fresh goal id";
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 7.5, "trajectory 1 ended");  // the old goal's repeat
  EXPECT_FALSE(node_->finished());
  Arrive(kFirstGoalId + 1, b_, 15.0);
  EXPECT_TRUE(node_->finished());
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
  EXPECT_EQ(statuses_.back().state, mission_status_t::SUCCEEDED);
  EXPECT_NEAR(statuses_.back().elapsed_s, 15.0, 1e-9);
  ASSERT_EQ(node_->steps().size(), 4u);
  EXPECT_NEAR(node_->steps()[0].duration_s, 5.2, 1e-9);
  EXPECT_EQ(node_->steps()[0].attempts, 1);
  EXPECT_NE(node_->Summary().find("SUCCEEDED"), std::string::npos);
  EXPECT_NE(node_->Summary().find("goto dropoff"), std::string::npos);
}

TEST_F(MissionNodeTest, PublishesItsStatusAtTwoHertz) {
  Make({Wait(10.0)});
  Start();
  const std::size_t before = statuses_.size();
  for (double t = 0.05; t < 5.0; t += 0.05) node_->Tick(At(t));
  EXPECT_NEAR(static_cast<double>(statuses_.size() - before), 10.0, 1.0);
}

// A planner killed and restarted lost the goal (and a GOAL can be lost on the bus): the goal in
// hand goes out again unchanged every goal_repeat_period_s while its step waits, never while a
// retry waits, and no more once the step is done.
TEST_F(MissionNodeTest, TheGoalInHandIsRepeatedUnchangedWhileItsStepWaits) {
  options_.goal_repeat_period_s = 1.0;
  options_.retry_delay_s = 2.0;
  Make({Goto(a_, "pickup"), Wait(10.0)});
  Start();
  ASSERT_EQ(goals_.size(), 1u);
  node_->Tick(At(0.5));
  EXPECT_EQ(goals_.size(), 1u);
  node_->Tick(At(1.0));
  node_->Tick(At(1.5));
  node_->Tick(At(2.05));
  ASSERT_EQ(goals_.size(), 3u);
  for (const goal_t& g : goals_) {
    EXPECT_EQ(g.goal_id, kFirstGoalId);
    EXPECT_EQ(g.utime, goals_[0].utime);  // the same message
    EXPECT_EQ(g.p_WE[0], goals_[0].p_WE[0]);
  }
  Planner(kFirstGoalId, planner_status_t::FAILED, 2.1, "", "no path");
  for (double t = 2.2; t < 4.0; t += 0.1) node_->Tick(At(t));
  EXPECT_EQ(goals_.size(), 3u) << "no repeat of a failed goal while its retry waits";
  node_->Tick(At(4.15));
  ASSERT_EQ(goals_.size(), 4u);
  EXPECT_EQ(goals_.back().goal_id, kFirstGoalId + 1);
  Arrive(kFirstGoalId + 1, a_, 4.9);
  EXPECT_EQ(statuses_.back().step_index, 1);
  for (double t = 5.0; t < 8.0; t += 0.1) node_->Tick(At(t));
  EXPECT_EQ(goals_.size(), 4u) << "the step is done: no more repeats";
}

TEST_F(MissionNodeTest, AFailedPlanIsRetriedWithANewGoalId) {
  options_.retry_delay_s = 0.5;
  Make({Goto(a_, "pickup")});
  Start();
  Planner(kFirstGoalId, planner_status_t::FAILED, 1.0, "", "no path");
  Planner(kFirstGoalId, planner_status_t::FAILED, 1.1, "", "no path");  // repeated: one retry
  node_->Tick(At(1.2));
  EXPECT_EQ(goals_.size(), 1u) << "after the retry delay";
  node_->Tick(At(1.6));
  ASSERT_EQ(goals_.size(), 2u);
  EXPECT_EQ(goals_[1].goal_id, kFirstGoalId + 1);
  EXPECT_EQ(statuses_.back().attempts, 2);
  Arrive(kFirstGoalId + 1, a_, 10.0);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
  EXPECT_EQ(node_->steps()[0].attempts, 2);
}

TEST_F(MissionNodeTest, RetriesRunOutIntoAFailedMissionWithTheReason) {
  options_.max_attempts = 2;
  options_.retry_delay_s = 0.0;
  Make({Goto(a_, "pickup"), Home()});
  Start();
  Planner(kFirstGoalId, planner_status_t::FAILED, 1.0, "", "target in an obstacle");
  node_->Tick(At(1.1));
  ASSERT_EQ(goals_.size(), 2u);
  Planner(kFirstGoalId + 1, planner_status_t::FAILED, 2.0, "", "target in an obstacle");
  EXPECT_TRUE(node_->finished());
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_EQ(statuses_.back().state, mission_status_t::FAILED);
  EXPECT_NE(statuses_.back().detail.find("target in an obstacle"), std::string::npos) << statuses_.back().detail;
  EXPECT_NE(statuses_.back().detail.find("2 attempts"), std::string::npos) << statuses_.back().detail;
  node_->Tick(At(3.0));
  EXPECT_EQ(goals_.size(), 2u) << "nothing more after the end";
}

// Hostile payloads (twenty-seventh session): two forged copies of the mission's goal and an
// injected goal each superseded the goal in hand, and the three CANCELLED statuses used up the
// step's three attempts. A goal superseded by another sender's is sent again without using an
// attempt; failed plans still count.
TEST_F(MissionNodeTest, ASupersededGoalIsSentAgainWithoutUsingAnAttempt) {
  options_.max_attempts = 2;
  options_.retry_delay_s = 0.0;
  Make({Goto(a_, "pickup")});
  Start();
  for (int k = 0; k < 5; ++k) {
    const std::int64_t id = goals_.back().goal_id;
    Planner(id, planner_status_t::CANCELLED, 1.0 + k, fmt::format("goal {} superseded by goal {}", id, 900000001 + k));
    node_->Tick(At(1.05 + k));
    ASSERT_EQ(goals_.size(), static_cast<std::size_t>(k + 2));
    EXPECT_NE(goals_.back().goal_id, id) << "a new goal id";
    EXPECT_EQ(statuses_.back().attempts, 1) << "after preemption " << k + 1;
  }
  EXPECT_FALSE(node_->finished());
  Planner(goals_.back().goal_id, planner_status_t::FAILED, 7.0, "", "no path");
  node_->Tick(At(7.1));
  EXPECT_EQ(statuses_.back().attempts, 2);
  Planner(goals_.back().goal_id, planner_status_t::FAILED, 8.0, "", "no path");
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_NE(statuses_.back().detail.find("2 attempts"), std::string::npos) << statuses_.back().detail;
}

TEST_F(MissionNodeTest, AGoalSupersededMoreThanMaxPreemptionsTimesFailsTheMissionClearly) {
  options_.max_preemptions = 2;
  options_.retry_delay_s = 0.0;
  Make({Goto(a_, "pickup")});
  Start();
  for (int k = 0; k < 3; ++k) {
    const std::int64_t id = goals_.back().goal_id;
    Planner(id, planner_status_t::CANCELLED, 1.0 + k, fmt::format("goal {} superseded by goal 77", id));
    node_->Tick(At(1.05 + k));
  }
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_EQ(goals_.size(), 3u) << "the first goal and 2 sent again";
  EXPECT_NE(statuses_.back().detail.find("goal superseded 3 times by other goals (max_preemptions 2)"),
            std::string::npos)
      << statuses_.back().detail;
  EXPECT_NE(statuses_.back().detail.find("superseded by goal 77"), std::string::npos) << statuses_.back().detail;
}

TEST_F(MissionNodeTest, AStepThatDoesNotArriveTimesOut) {
  options_.step_timeout_s = 5.0;
  Make({Goto(a_, "pickup")});
  Start();
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 1.0, "trajectory 1 out");
  node_->Tick(At(4.9));
  EXPECT_FALSE(node_->finished());
  node_->Tick(At(5.1));
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_NE(statuses_.back().detail.find("timed out"), std::string::npos) << statuses_.back().detail;
}

TEST_F(MissionNodeTest, HomeGoesToTheRecordedStart) {
  Make({Goto(a_, "pickup"), Home()});
  Start();
  Robot(b_, 0.5);  // the start is the first state, not a later one
  Arrive(kFirstGoalId, a_, 5.0);
  ASSERT_EQ(goals_.size(), 2u);
  const goal_t& home = goals_[1];
  const Eigen::Vector3d p_start = kinematics_.EndEffectorPose(start_).translation();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(home.p_WE[k], p_start(k), 1e-12);
  ASSERT_TRUE(home.has_hint);
  EXPECT_DOUBLE_EQ(home.hint.x_m, start_.x_m);
  EXPECT_DOUBLE_EQ(home.hint.yaw_rad, start_.yaw_rad);
  ASSERT_TRUE(node_->start_state().has_value());
  Arrive(kFirstGoalId + 1, start_, 10.0);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

TEST_F(MissionNodeTest, WithATrackerArrivalWaitsForItsFinished) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0);
  Arrive(kFirstGoalId, a_, 5.0);
  EXPECT_FALSE(node_->finished()) << "the tracker still tracks";
  Tracker(kFirstGoalId + 7, tracker_status_t::FINISHED, 5.1);  // another goal's
  EXPECT_FALSE(node_->finished());
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 5.2);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

TEST_F(MissionNodeTest, TheTrackerMustHaveFinishedTheTrajectoryThePlannerReportedEnded) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0, 4);
  Robot(a_, 4.0);
  planner_status_t ended{};
  ended.utime = At(5.0);
  ended.state = planner_status_t::SUCCEEDED;
  ended.goal_id = kFirstGoalId;
  ended.trajectory_id = 5;
  ended.replans = 2;
  ended.detail = "trajectory 5 ended";
  node_->OnPlannerStatus(ended, At(5.0));
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 5.1, 4);  // an earlier (stopping) trajectory
  EXPECT_FALSE(node_->finished());
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 5.2, 5);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
  EXPECT_EQ(node_->steps()[0].replans, 2);
  EXPECT_NE(node_->Summary().find("2 replans"), std::string::npos) << node_->Summary();
}

TEST_F(MissionNodeTest, ArrivalNeedsTheEndEffectorWithinTheTolerance) {
  Make({Goto(a_, "pickup")});
  Start();
  WholeBodyState off = a_;
  off.x_m += 0.05;  // 5 cm off: beyond the 3 cm default
  Arrive(kFirstGoalId, off, 5.0);
  EXPECT_FALSE(node_->finished());
  off.x_m = a_.x_m + 0.02;
  Robot(off, 5.5);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

// The planner says the goal is reached but the robot stands 5 cm off (e.g. the tracker's
// lateral offset after a corner): after arrival_settle_s the goal is sent again, and the new
// attempt arrives.
TEST_F(MissionNodeTest, AnArrivalOutsideTheToleranceIsRetriedAfterTheSettleTime) {
  options_.arrival_settle_s = 1.0;
  options_.retry_delay_s = 0.5;
  Make({Goto(a_, "pickup")});
  Start();
  WholeBodyState off = a_;
  off.x_m += 0.05;
  Arrive(kFirstGoalId, off, 5.0);
  node_->Tick(At(5.9));
  EXPECT_EQ(goals_.size(), 1u) << "within the settle time";
  node_->Tick(At(6.1));
  EXPECT_NE(statuses_.back().detail.find("ended with the end effector 0.050 m"), std::string::npos)
      << statuses_.back().detail;
  node_->Tick(At(6.7));
  ASSERT_EQ(goals_.size(), 2u);
  EXPECT_EQ(goals_[1].goal_id, kFirstGoalId + 1);
  Arrive(kFirstGoalId + 1, a_, 10.0);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
  EXPECT_EQ(node_->steps()[0].attempts, 2);
}

TEST_F(MissionNodeTest, AnArrivalOutsideTheToleranceOnTheLastAttemptFailsTheMission) {
  options_.max_attempts = 1;
  Make({Goto(a_, "pickup")});
  Start();
  WholeBodyState off = a_;
  off.y_m -= 0.04;
  Arrive(kFirstGoalId, off, 5.0);
  node_->Tick(At(6.5));
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_NE(statuses_.back().detail.find("not arrived after 1 attempt: ended with the end effector 0.040 m"),
            std::string::npos)
      << statuses_.back().detail;
}

// A goal the robot already held at rest (the planner's "goal reached at rest ...", no
// trajectory) counts as the planner's arrival too.
TEST_F(MissionNodeTest, APlannerGoalReachedAtRestCountsAsArrival) {
  Make({Goto(a_, "pickup")});
  Start();
  Robot(a_, 1.0);
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 1.1, "goal reached at rest: end effector 0.004 m / 0.001 rad");
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

// The drives stopped just before the robot reached its goal: the tracker was HELD (its
// trajectories dropped, its status naming no goal), then released at rest (IDLE), and the
// planner found the goal reached at rest, naming no trajectory: that is the arrival (before, the
// mission waited for a FINISHED that never came until its step timed out).
TEST_F(MissionNodeTest, AGoalReachedAtRestAfterATrackerHoldCountsAsArrival) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0, 3);
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 1.0, "trajectory 3 out");
  Robot(a_, 4.0);
  Tracker(0, tracker_status_t::HELD, 4.1, 0);
  Planner(kFirstGoalId, planner_status_t::PLANNING, 4.1, "waiting: the robot is held at rest (tracker HELD)");
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 4.8, "goal reached at rest: end effector 0.013 m / 0.025 rad");
  EXPECT_FALSE(node_->finished()) << "the tracker is still held";
  Tracker(0, tracker_status_t::IDLE, 4.9, 0);  // released, at rest
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

// Finding 23 of docs/reliability.md: the planner restarted while the robot ran a trajectory of
// the goal's first attempt; that trajectory took the robot to the target, and the second
// attempt's goal was found reached at rest, naming no trajectory, with the tracker FINISHED on
// the first attempt's trajectory. Before: the mission waited for a FINISHED of its own until
// the step timed out (120 s).
TEST_F(MissionNodeTest, AGoalReachedAtRestWithTheTrackerFinishedOnAnEarlierAttemptCountsAsArrival) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0, 3);
  Planner(kFirstGoalId, planner_status_t::SUCCEEDED, 1.0, "trajectory 3 out");
  Planner(kFirstGoalId, planner_status_t::FAILED, 6.0, "", "moving start: the lead-in collides");
  node_->Tick(At(6.6));  // the second attempt goes out
  ASSERT_EQ(goals_.size(), 2u);
  const std::int64_t second = goals_.back().goal_id;
  ASSERT_NE(second, kFirstGoalId);
  Robot(a_, 7.0);
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 7.0, 3);  // the first attempt's trajectory
  EXPECT_FALSE(node_->finished());
  Planner(second, planner_status_t::SUCCEEDED, 7.2, "goal reached at rest: end effector 0.006 m / 0.003 rad");
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

// Finding 28 (a goal flood): the planner's "goal reached at rest" status for the third attempt
// still carried its last trajectory's id (the first attempt's, FINISHED by the tracker): the
// robot at rest at the target with the tracker FINISHED is arrival; the mission waited 120 s.
TEST_F(MissionNodeTest, AGoalReachedAtRestNamingAnEarlierGoalsTrajectoryCountsAsArrival) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0, 3);
  Planner(kFirstGoalId, planner_status_t::CANCELLED, 2.0, "goal superseded by goal 900000018");
  node_->Tick(At(2.6));
  ASSERT_EQ(goals_.size(), 2u);
  const std::int64_t second = goals_.back().goal_id;
  Robot(a_, 3.0);
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 3.0, 3);
  planner_status_t m{};
  m.utime = At(3.2);
  m.state = planner_status_t::SUCCEEDED;
  m.goal_id = second;
  m.trajectory_id = 3;  // the planner's last trajectory, of the first attempt
  m.detail = "goal reached at rest: end effector 0.016 m / 0.008 rad from the target";
  node_->OnPlannerStatus(m, At(3.2));
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

// A trajectory the planner reported ended still needs the tracker's FINISHED: an IDLE tracker
// (e.g. between trajectories) is not enough there.
TEST_F(MissionNodeTest, AnEndedTrajectoryIsNotArrivedByAnIdleTracker) {
  Make({Goto(a_, "pickup")});
  Start();
  Tracker(kFirstGoalId, tracker_status_t::TRACKING, 1.0, 1);
  Arrive(kFirstGoalId, a_, 5.0);
  Tracker(0, tracker_status_t::IDLE, 5.1, 0);
  EXPECT_FALSE(node_->finished());
  Tracker(kFirstGoalId, tracker_status_t::FINISHED, 5.2, 1);
  EXPECT_EQ(node_->state(), mission_status_t::SUCCEEDED);
}

TEST_F(MissionNodeTest, AbortEndsTheMissionAsAborted) {
  Make({Goto(a_, "pickup")});
  Start();
  node_->Abort("stopped by a signal", At(2.0));
  EXPECT_EQ(node_->state(), mission_status_t::ABORTED);
  EXPECT_EQ(statuses_.back().state, mission_status_t::ABORTED);
  EXPECT_EQ(statuses_.back().detail, "stopped by a signal");
}

TEST_F(MissionNodeTest, NoPlannerMeansNoStartAndAFailureAfterTheStartTimeout) {
  options_.start_timeout_s = 3.0;
  Make({Wait(1.0)});
  node_->Tick(At(0.0));
  Robot(start_, 0.1);
  node_->Tick(At(2.0));
  EXPECT_EQ(node_->state(), mission_status_t::IDLE);
  node_->Tick(At(3.5));
  EXPECT_EQ(node_->state(), mission_status_t::FAILED);
  EXPECT_NE(statuses_.back().detail.find("PLANNER_STATUS"), std::string::npos) << statuses_.back().detail;
}

}  // namespace
}  // namespace topay::mission
