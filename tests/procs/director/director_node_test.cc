// topay-director's node with direct calls: no box before its step runs or while the robot
// stands, one box once the step runs and the robot drives (on the trajectory ahead of it, an
// id clear of the room's), never a second; a step that ends first gives the event up. The
// placement runs on a worker thread: the tick that starts it never publishes, a later one
// takes its result (WaitForPlacement in between, so that the tests do not depend on timing).

#include "procs/director/director_node.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <vector>

#include "core/io/robot_loader.h"
#include "tests/procs/tracker/tracker_test_trajectory.h"

namespace topay::director {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;

class DirectorNodeTest : public testing::Test {
 protected:
  DirectorNodeTest() {
    room_.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6));
    OrientedBox far;  // one box of the room, far from the route
    far.center_W_m = Eigen::Vector3d(5, 8, 0.5);
    far.size_m = Eigen::Vector3d(0.5, 0.5, 1);
    room_.boxes.push_back(far);
    BoxOnRouteEvent event;
    event.during_step = "dropoff";
    options_.events.push_back(event);
  }

  DirectorNode MakeNode() {
    DirectorOutputs outputs;
    outputs.event = [this](const sim_event_t& m) { events_.push_back(m); };
    outputs.log = [this](bool warning, const std::string&) { warnings_ += warning ? 1 : 0; };
    return DirectorNode(options_, room_, kinematics_, outputs);
  }
  static mission_status_t Status(std::int8_t state, const std::string& step) {
    mission_status_t m{};
    m.state = state;
    m.step = step;
    return m;
  }
  // The robot on a straight 8 m trajectory from (-4, 0) along x (10 s), `t_s` into it.
  void Drive(DirectorNode* node, double t_s, double speed_mps) {
    const Eigen::Vector2d p0(-4.0, 0.0);
    const ArcYawTrajectory trajectory = test::TrackerTestTrajectory(p0, 0.0, Eigen::VectorXd::Zero(7), 8.0, 0.0,
                                                                    Eigen::VectorXd::Zero(7), 5.0);
    node->OnTrajectory(test::TrackerTestMessage(trajectory, p0, kT0, 7));
    TrajectorySample sample = trajectory.MakePoint();
    trajectory.Evaluate(t_s, &sample);
    robot_state_t state{};
    state.pose.x_m = p0.x() + sample.s_m;
    state.pose.y_m = 0.0;
    state.velocity.v_mps = speed_mps;
    // The robot jumps between calls: a short stream (1 ms apart) that the node's continuity
    // gate takes as a new anchor.
    for (int k = 0; k < StateContinuityGateOptions{}.reanchor_after; ++k) {
      state.utime = std::max(At(t_s), last_state_utime_ + 1000);
      last_state_utime_ = state.utime;
      node->OnRobotState(state);
    }
    x_robot_m_ = state.pose.x_m;
  }
  // The drop-off step runs and the robot drives at 0.8 m/s, `t_s` into the trajectory: the
  // tick starts a placement attempt.
  void DriveInTheStep(DirectorNode* node, double t_s) {
    node->OnMissionStatus(Status(mission_status_t::RUNNING, "goto dropoff"));
    Drive(node, t_s, 0.8);
    node->Tick(At(t_s));
  }
  std::int64_t last_state_utime_ = 0;
  static std::int64_t At(double t_s) { return kT0 + static_cast<std::int64_t>(t_s * 1e6); }

  RobotModel model_ = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                     std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  Scene room_;
  DirectorOptions options_;
  std::vector<sim_event_t> events_;
  int warnings_ = 0;
  double x_robot_m_ = 0.0;
};

TEST_F(DirectorNodeTest, OneBoxOnceTheStepRunsAndTheRobotDrives) {
  DirectorNode node = MakeNode();
  Drive(&node, 2.0, 0.8);
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "goto pickup"));
  node.Tick(At(2.0));
  EXPECT_TRUE(events_.empty()) << "not before its step";
  EXPECT_EQ(node.StatusLine(), "waiting for step dropoff");
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "goto dropoff"));
  Drive(&node, 2.0, 0.1);
  node.Tick(At(2.0));
  EXPECT_TRUE(events_.empty()) << "not while the robot is slow";
  Drive(&node, 2.0, 0.8);
  node.Tick(At(2.0));
  EXPECT_TRUE(node.placing());
  EXPECT_TRUE(events_.empty()) << "the tick that starts the attempt returns at once";
  EXPECT_EQ(node.StatusLine(), "step dropoff runs: checking a place for box 1000");
  node.WaitForPlacement();
  Drive(&node, 2.2, 0.8);  // the robot drove on meanwhile
  node.Tick(At(2.2));
  EXPECT_FALSE(node.placing());
  ASSERT_EQ(events_.size(), 1u);
  const sim_event_t& e = events_[0];
  EXPECT_EQ(e.action, sim_event_t::APPEAR);
  EXPECT_EQ(e.trigger, sim_event_t::NOW);
  EXPECT_TRUE(e.has_box);
  EXPECT_EQ(e.box_id, 1000);  // the room has 1 box: the first automatic id
  EXPECT_NEAR(e.center_m[1], 0.0, 1e-6);
  EXPECT_GE(e.center_m[0] - x_robot_m_, 2.0);
  EXPECT_LE(e.center_m[0] - x_robot_m_, 3.6);
  EXPECT_EQ(e.size_m[2], 1.0);
  EXPECT_EQ(node.boxes_placed(), 1);
  EXPECT_TRUE(node.all_done());
  EXPECT_NE(node.StatusLine().find("box 1000 placed at"), std::string::npos) << node.StatusLine();
  for (double t = 2.4; t < 4.0; t += 0.2) {
    Drive(&node, t, 0.8);
    node.Tick(At(t));
    node.WaitForPlacement();
  }
  EXPECT_EQ(events_.size(), 1u) << "once per event";
}

TEST_F(DirectorNodeTest, GivesUpWhenTheStepEndsFirst) {
  DirectorNode node = MakeNode();
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "goto dropoff"));
  Drive(&node, 8.5, 0.8);  // 1.5 s from the end: too near it for a box
  node.Tick(At(8.5));
  node.WaitForPlacement();
  node.Tick(At(8.7));
  EXPECT_TRUE(events_.empty());
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "gripper open"));
  node.Tick(At(9.0));
  EXPECT_TRUE(events_.empty());
  EXPECT_EQ(node.events_given_up(), 1);
  EXPECT_EQ(warnings_, 1);
  EXPECT_TRUE(node.all_done());
  EXPECT_NE(node.StatusLine().find("no place for box 1000"), std::string::npos) << node.StatusLine();
}

TEST_F(DirectorNodeTest, ConfiguredBoxIdAndNoBoxBeforeTheTrajectoryStarts) {
  options_.events[0].box_id = 42;
  DirectorNode node = MakeNode();
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "goto dropoff"));
  Drive(&node, 0.0, 0.8);
  node.Tick(kT0 - 100'000);  // a replan not joined yet
  EXPECT_FALSE(node.placing());
  node.Tick(At(1.0));
  node.WaitForPlacement();
  node.Tick(At(1.0));
  ASSERT_EQ(events_.size(), 1u);
  EXPECT_EQ(events_[0].box_id, 42);
}

TEST_F(DirectorNodeTest, AnAttemptWithEveryDrawRejectedIsTriedAgainOnlyAfterTheRetryPeriod) {
  options_.retry_period_s = 1.0;
  options_.events[0].box.min_robot_distance_m = 50.0;  // no box is ever that far from the robot
  DirectorNode node = MakeNode();
  DriveInTheStep(&node, 1.0);
  ASSERT_TRUE(node.placing());
  node.WaitForPlacement();
  node.Tick(At(1.2));  // takes the failed attempt: the next one from 2.2 s
  EXPECT_FALSE(node.placing());
  node.Tick(At(2.0));
  EXPECT_FALSE(node.placing()) << "retried before retry_period_s";
  node.Tick(At(2.2));
  EXPECT_TRUE(node.placing());
  node.WaitForPlacement();
  EXPECT_TRUE(events_.empty());
  EXPECT_EQ(node.boxes_placed(), 0);
}

TEST_F(DirectorNodeTest, TheRetryPeriodOfOneEventDoesNotDelayTheNext) {
  options_.retry_period_s = 10.0;
  options_.events[0].box.min_robot_distance_m = 50.0;  // the first event's draws are all rejected
  BoxOnRouteEvent second;
  second.during_step = "pickup";
  options_.events.push_back(second);
  DirectorNode node = MakeNode();
  DriveInTheStep(&node, 1.0);
  ASSERT_TRUE(node.placing());
  node.WaitForPlacement();
  node.Tick(At(1.2));  // the first event's attempt failed: it would be tried again at 11.2 s
  EXPECT_FALSE(node.placing());
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "goto pickup"));
  node.Tick(At(1.3));  // the drop-off step has ended: the first event is given up
  EXPECT_EQ(node.events_given_up(), 1);
  node.Tick(At(1.4));
  EXPECT_TRUE(node.placing()) << "the second event waited for the first one's retry period";
  node.WaitForPlacement();
  node.Tick(At(1.5));
  ASSERT_EQ(events_.size(), 1u);
  EXPECT_EQ(node.boxes_placed(), 1);
}

TEST_F(DirectorNodeTest, AStepThatEndsWhileTheAttemptRunsDropsItsBox) {
  DirectorNode node = MakeNode();
  DriveInTheStep(&node, 1.0);
  ASSERT_TRUE(node.placing());
  node.OnMissionStatus(Status(mission_status_t::RUNNING, "gripper open"));
  node.Tick(At(1.2));
  EXPECT_EQ(node.events_given_up(), 1);
  node.WaitForPlacement();
  node.Tick(At(1.4));
  EXPECT_FALSE(node.placing());
  EXPECT_TRUE(events_.empty()) << "a box for a step that has ended";
  EXPECT_EQ(node.boxes_placed(), 0);
}

TEST_F(DirectorNodeTest, TheSameDrawsAsAnAttemptOnTheLoopWould) {
  // The worker draws from a copy of the node's generator and hands it back: same seed, same
  // box as PlaceRouteBox called directly with a generator of that seed.
  DirectorNode node = MakeNode();
  DriveInTheStep(&node, 1.0);
  node.WaitForPlacement();
  node.Tick(At(1.0));
  ASSERT_EQ(events_.size(), 1u);
  const ArcYawTrajectory trajectory = test::TrackerTestTrajectory(Eigen::Vector2d(-4.0, 0.0), 0.0,
                                                                  Eigen::VectorXd::Zero(7), 8.0, 0.0,
                                                                  Eigen::VectorXd::Zero(7), 5.0);
  std::string error;
  const std::optional<BasePath> path =
      SampleBasePath(test::TrackerTestMessage(trajectory, Eigen::Vector2d(-4.0, 0.0), kT0, 7), options_.path_sample_s,
                     &error);
  ASSERT_TRUE(path) << error;
  RouteQuery route;
  route.path_W_m = path->p_W_m;
  route.robot_index = *path->IndexAt(At(1.0));
  route.p_WR_m = Eigen::Vector2d(x_robot_m_, 0.0);
  Rng rng(options_.seed);
  const std::optional<RouteBox> direct = PlaceRouteBox(route, room_, kinematics_, options_.events[0].box, &rng);
  ASSERT_TRUE(direct);
  EXPECT_DOUBLE_EQ(events_[0].center_m[0], direct->box.center_W_m.x());
  EXPECT_DOUBLE_EQ(events_[0].size_m[0], direct->box.size_m.x());
}

}  // namespace
}  // namespace topay::director
