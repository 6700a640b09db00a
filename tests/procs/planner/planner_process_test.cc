// topay-planner as a real process over real LCM in a private network namespace (skipped, with
// the reason, where none can be made). The test plays the mapper (MAP_UPDATE snapshots and
// deltas of a small room), the robot (ROBOT_STATE at rest) and the mission (GOAL): a goal gets a
// trajectory with its id, every bad goal a FAILED status with its reason at once, a box put on
// the route triggers a replan, a flood of goals leaves the loop responsive and the last goal
// planned.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "graph_test_support.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/convert_goal.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/map_codec.h"
#include "procs/msgs/planner_status_text.h"
#include "procs/runtime/process_loop.h"
#include "tests/common/arm_state.h"
#include "tests/procs/planner/planner_test_support.h"
#include "topay/planner_status_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608";

struct PlannerListener {
  std::vector<poly_trajectory_t> trajectories;
  std::vector<planner_status_t> statuses;
  void OnTrajectory(const lcm::ReceiveBuffer*, const std::string&, const poly_trajectory_t* m) { trajectories.push_back(*m); }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const planner_status_t* m) { statuses.push_back(*m); }
  // The last status for goal_id in `state` (nullptr if none).
  const planner_status_t* Last(std::int64_t goal_id, std::int8_t state) const {
    for (auto it = statuses.rbegin(); it != statuses.rend(); ++it) {
      if (it->goal_id == goal_id && it->state == state) return &*it;
    }
    return nullptr;
  }
};

class PlannerProcess : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("planner");
    // Generous plan time: the tests share two cores with the rest of the suite. No drift
    // trigger or drift check: the test's robot stays at its start while the planner's
    // trajectories run.
    WriteText(dir_ + "/planner.yaml", "planner_config: " + std::string(TOPAY_SOURCE_DIR) +
                                          "/config/planner/topay.yaml\ntiming: {from_rest_time_limit_s: 20.0}\n"
                                          "triggers: {drift_position_m: 100, drift_yaw_rad: 100, drift_joint_rad: 100, "
                                          "drift_check_position_m: 100, drift_check_yaw_rad: 100, "
                                          "drift_check_joint_rad: 100}\n"
                                          "map: {stale_stop_s: 0}\n");  // one snapshot plays the mapper
    watcher_ = std::make_unique<HeartbeatWatcher>(kLcmUrl);
    watcher_->lcm().subscribe(std::string(channels::TRAJECTORY), &PlannerListener::OnTrajectory, &out_);
    watcher_->lcm().subscribe(std::string(channels::PLANNER_STATUS), &PlannerListener::OnStatus, &out_);
    boxes_ = planner::testing::RoomBoxes();
    boxes_.push_back(MakeBox({1.0, 0.0, 0.6}, {0.1, 8.0, 1.2}));  // splits the room at x = 1
    StartPlanner();
  }
  // Starts the planner with dir_/planner.yaml and (with_map) sends it the room's map.
  void StartPlanner(bool with_map = true) {
    planner_ = Spawn({BinDir() + "/topay-planner", "--config", dir_ + "/planner.yaml", "--name", "planner",
                      "--lcm-url", kLcmUrl},
                     dir_ + "/planner.txt");
    ASSERT_TRUE(watcher_->SpinUntil([&] { return watcher_->last.contains("planner") &&
                                                  watcher_->last["planner"].pid == planner_; }, 10.0))
        << ReadText(dir_ + "/planner.txt");
    if (with_map) SendMap();
  }
  void SendMap() {
    const GridGeometry3 g = planner::testing::RoomGeometry();
    const map_update_t map = msgs::EncodeFullMap(g, planner::testing::StatesOf(g, boxes_), 1, 1);
    watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &map);
  }
  void RestartPlanner() {
    kill(planner_, SIGKILL);
    WaitFor(planner_, 3.0);
    StartPlanner();
  }  // Restarts the planner with the test YAML's "stale_stop_s: 0}" replaced by `map_tail`.
  void RestartWithStaleOptions(const std::string& map_tail) {
    std::string yaml = ReadText(dir_ + "/planner.yaml");
    const std::size_t at = yaml.find("stale_stop_s: 0}");
    ASSERT_NE(at, std::string::npos) << yaml;
    yaml.replace(at, std::string("stale_stop_s: 0}").size(), map_tail);
    WriteText(dir_ + "/planner.yaml", yaml);
    RestartPlanner();
  }
  // A mapper stand-in for the stale-map tests: an empty MAP_UPDATE delta stamped now every
  // period_s while `on` (RestartPlanner's snapshot is map_seq 1, stamped long ago: stale).
  struct MapperStandIn {
    double period_s = 0.2;
    bool on = true;
    std::int64_t seq = 1;
    Clock::time_point last = Clock::now();
  };
  void Tick(MapperStandIn* mapper) {
    if (!mapper->on || SecondsSince(mapper->last) < mapper->period_s) return;
    const map_update_t delta =
        msgs::EncodeMapDelta(planner::testing::RoomGeometry(), {}, procs::NowUtime(), ++mapper->seq);
    watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &delta);
    mapper->last = Clock::now();
  }
  // `pred`, with the stand-in mapper publishing meanwhile (for SpinWithRobot).
  template <typename Pred>
  auto WithMapper(MapperStandIn* mapper, Pred pred) {
    return [this, mapper, pred] {
      Tick(mapper);
      return pred();
    };
  }

  // Stops the planner with SIGTERM (its output flushed, its report written) and returns it.
  std::string StopPlannerAndReadLog() {
    kill(planner_, SIGTERM);
    EXPECT_NE(WaitFor(planner_, 10.0), -1);
    return ReadText(dir_ + "/planner.txt");
  }
  void TearDown() override {
    if (planner_ > 0 && launch::ProcessAlive(planner_)) {
      kill(planner_, SIGKILL);
      WaitFor(planner_, 3.0);
    }
  }
  // Spins until pred() or the timeout, publishing ROBOT_STATE (the robot at rest at start_)
  // every 50 ms.
  template <class Pred>
  bool SpinWithRobot(Pred pred, double timeout_s) {
    const Clock::time_point start = Clock::now();
    Clock::time_point last = start - std::chrono::seconds(1);
    while (!pred() && SecondsSince(start) < timeout_s) {
      if (SecondsSince(last) >= 0.05) {
        msgs::RobotStateEstimate robot;
        robot.utime = procs::NowUtime() - static_cast<std::int64_t>(1e6 * state_age_s_);
        robot.state = start_;
        robot.v_mps = v_mps_;
        robot.qdot_radps = Eigen::VectorXd::Zero(7);
        const robot_state_t msg = msgs::ToMessage(robot);
        watcher_->lcm().publish(std::string(channels::ROBOT_STATE), &msg);
        last = Clock::now();
      }
      watcher_->lcm().handleTimeout(5);
    }
    return pred();
  }
  goal_t Goal(std::int64_t id, const Eigen::Vector3d& p_WE) const {
    msgs::PlanGoal goal;
    goal.utime = procs::NowUtime();
    goal.goal_id = id;
    goal.X_WE = kinematics_.EndEffectorPose(BentArmState(-1.0, 2.0, 1.0));
    goal.X_WE.translation() = p_WE;
    return msgs::ToMessage(goal);
  }
  goal_t ReachableGoal(std::int64_t id) const {
    msgs::PlanGoal goal;
    goal.utime = procs::NowUtime();
    goal.goal_id = id;
    goal.hint = BentArmState(-1.0, 2.0, 1.0);
    goal.X_WE = kinematics_.EndEffectorPose(*goal.hint);
    return msgs::ToMessage(goal);
  }
  // The voxels over the outermost arm sphere of the robot at start_ (centres above its centre
  // by above_radii of its radius, the sphere reaching at least 3 mm into each) whose deepest
  // overlap with any arm sphere (m) passes `keep`; *deepest_m (if given) the largest kept.
  template <class Keep>
  std::vector<VoxelChange> VoxelsOnTheArm(double above_radii, Keep keep, double* deepest_m) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(start_, &cache);
    const std::size_t outer = cache.p_WS.size() - 1;
    const Eigen::Vector3d p_WS = cache.p_WS[outer];
    const double r = model_.spheres[outer].radius_m;
    const GridGeometry3 g = planner::testing::RoomGeometry();
    const double half = 0.5 * g.resolution_m;
    const auto depth = [&](std::size_t s, const Eigen::Vector3d& c) {  // how far sphere s reaches into the voxel at c
      return model_.spheres[s].radius_m - ((cache.p_WS[s] - c).cwiseAbs().array() - half).max(0.0).matrix().norm();
    };
    std::vector<VoxelChange> cap;
    const CellBox cells = VoxelsOverlapping(g, {p_WS - Eigen::Vector3d::Constant(r), p_WS + Eigen::Vector3d::Constant(r)});
    for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz)
      for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy)
        for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) {
          const Eigen::Vector3d c = g.CellCenter(ix, iy, iz);
          if (c.z() < p_WS.z() + above_radii * r || depth(outer, c) < 0.003) continue;
          double most = 0.0;
          for (std::size_t s = 0; s < cache.p_WS.size(); ++s) most = std::max(most, depth(s, c));
          if (!keep(most)) continue;
          cap.push_back({{ix, iy, iz}, VoxelState::kOccupied});
          if (deepest_m != nullptr) *deepest_m = std::max(*deepest_m, most);
        }
    return cap;
  }
  void Send(const goal_t& goal) { watcher_->lcm().publish(std::string(channels::GOAL), &goal); }
  // Plays the tracker: a TRACKER_STATUS in `state` (for goal_id's trajectory_id; 0: none).
  void Tracker(std::int8_t state, std::int64_t goal_id = 0, std::int64_t trajectory_id = 0) {
    tracker_status_t t{};
    t.utime = procs::NowUtime();
    t.state = state;
    t.goal_id = goal_id;
    t.trajectory_id = trajectory_id;
    watcher_->lcm().publish(std::string(channels::TRACKER_STATUS), &t);
  }
  // The base positions at n + 1 times evenly over [0, t_end]: x, y integrated numerically from
  // p0 along s and yaw.
  static std::vector<Eigen::Vector2d> BasePath(const msgs::PolyTrajectory& t, double t_end, int n) {
    std::vector<Eigen::Vector2d> path{t.p0_W_m};
    for (int k = 0; k < n; ++k) {
      const Eigen::VectorXd a = t.Evaluate(t_end * k / n), b = t.Evaluate(t_end * (k + 1) / n);
      const double yaw = 0.5 * (a(1) + b(1));
      path.push_back(path.back() + (b(0) - a(0)) * Eigen::Vector2d(std::cos(yaw), std::sin(yaw)));
    }
    return path;
  }
  static Eigen::Vector2d BaseAt(const msgs::PolyTrajectory& t, double t_s) { return BasePath(t, t_s, 2000).back(); }
  // A 0.3 x 0.3 x 1.0 m pillar at p, as a map delta with sequence number `seq`.
  void SendPillar(const Eigen::Vector2d& p, std::int64_t seq) { SendPillars({p}, seq); }
  // Such pillars (height_m tall) at every point, as one map delta.
  void SendPillars(const std::vector<Eigen::Vector2d>& points, std::int64_t seq, double height_m = 1.0) {
    const GridGeometry3 g = planner::testing::RoomGeometry();
    std::vector<VoxelChange> pillar;
    for (const Eigen::Vector2d& p : points) {
      const CellBox cells = VoxelsOverlapping(g, {Eigen::Vector3d(p.x() - kPillarHalf_m, p.y() - kPillarHalf_m, 0.0),
                                                  Eigen::Vector3d(p.x() + kPillarHalf_m, p.y() + kPillarHalf_m, height_m)});
      for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz)
        for (int iy = cells.begin.y(); iy < cells.end.y(); ++iy)
          for (int ix = cells.begin.x(); ix < cells.end.x(); ++ix) pillar.push_back({{ix, iy, iz}, VoxelState::kOccupied});
    }
    const map_update_t delta = msgs::EncodeMapDelta(g, pillar, procs::NowUtime(), seq);
    watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &delta);
  }
  // The least distance (m) from the trajectory's base axis to the pillar at p (its square).
  static double BaseDistanceToPillar(const msgs::PolyTrajectory& t, const Eigen::Vector2d& p) {
    double least = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& base : BasePath(t, t.durations_s.sum(), 4000)) {
      least = std::min(least, Eigen::Vector2d(((base - p).cwiseAbs().array() - kPillarHalf_m).max(0.0)).norm());
    }
    return least;
  }
  static constexpr double kPillarHalf_m = 0.15;

  RobotModel model_ = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                     TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  WholeBodyState start_ = BentArmState(-2.5, -2.5, 0.0);
  double v_mps_ = 0.0;  // the published robot state's forward speed
  double state_age_s_ = 0.0;  // how old the published robot state is when sent (s)
  std::vector<OrientedBox> boxes_;
  std::string dir_;
  pid_t planner_ = -1;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  PlannerListener out_;
};

TEST_F(PlannerProcess, AGoalGetsATrajectoryWithItsIdStartingAtTheRobot) {
  Send(ReachableGoal(11));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(11, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  ASSERT_FALSE(out_.trajectories.empty());
  const poly_trajectory_t& t = out_.trajectories.back();
  EXPECT_EQ(t.goal_id, 11);
  EXPECT_EQ(out_.Last(11, planner_status_t::SUCCEEDED)->trajectory_id, t.trajectory_id);
  std::string error;
  const auto poly = msgs::FromMessage(t, &error);
  ASSERT_TRUE(poly.has_value()) << error;
  EXPECT_NEAR(poly->p0_W_m.x(), start_.x_m, 1e-3);
  EXPECT_NEAR(poly->p0_W_m.y(), start_.y_m, 1e-3);
  EXPECT_NEAR(poly->yaw0_rad, start_.yaw_rad, 1e-3);
  EXPECT_NEAR((poly->Evaluate(0.0).tail(7) - start_.q_rad).cwiseAbs().maxCoeff(), 0.0, 1e-3);
  EXPECT_GT(out_.Last(11, planner_status_t::SUCCEEDED)->total_ms, 0.0);
}

// The CAN bridge stops the drives (a lost heartbeat, bus-off) and the tracker, HELD, drops every
// trajectory: the planner forgets them and waits, saying so; a goal meanwhile waits too; when
// the tracker is released it waits for the robot at rest and plans the goal from rest where the
// robot stopped (not from where the dropped trajectory, or its braking, would have led).
TEST_F(PlannerProcess, AHeldTrackerMakesItWaitAndPlanFromRestWhereTheRobotStopped) {
  Send(ReachableGoal(21));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  const std::int64_t first_id = out_.trajectories.back().trajectory_id;
  const auto tracker = [&](std::int8_t state) { Tracker(state); };
  tracker(tracker_status_t::HELD);
  start_.x_m += 0.3;  // where the robot was stopped
  start_.yaw_rad += 0.2;
  const auto waiting = [&] {
    const planner_status_t* s = out_.Last(22, planner_status_t::PLANNING);
    return s != nullptr && s->detail.find("waiting: the robot is held at rest (tracker HELD)") != std::string::npos;
  };
  Send(ReachableGoal(22));
  ASSERT_TRUE(SpinWithRobot(waiting, 10.0)) << ReadText(dir_ + "/planner.txt");
  const std::size_t before = out_.trajectories.size();
  SpinWithRobot([&] { tracker(tracker_status_t::HELD); return false; }, 1.0);  // still held: no plan
  EXPECT_EQ(out_.trajectories.size(), before);
  EXPECT_EQ(out_.Last(22, planner_status_t::FAILED), nullptr);
  v_mps_ = 0.2;  // still braking when released: the plan waits for the robot at rest
  SpinWithRobot([] { return false; }, 0.3);
  tracker(tracker_status_t::IDLE);  // released
  const auto braking = [&] {
    const planner_status_t* s = out_.Last(22, planner_status_t::PLANNING);
    return s != nullptr && s->detail.find("coming to rest after the tracker's hold") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(braking, 10.0)) << ReadText(dir_ + "/planner.txt");
  SpinWithRobot([] { return false; }, 1.0);
  EXPECT_EQ(out_.trajectories.size(), before);
  v_mps_ = 0.0;  // at rest
  ASSERT_TRUE(SpinWithRobot([&] { return out_.trajectories.size() > before; }, 60.0)) << ReadText(dir_ + "/planner.txt");
  const poly_trajectory_t& t = out_.trajectories.back();
  EXPECT_EQ(t.goal_id, 22);
  EXPECT_GT(t.trajectory_id, first_id);
  std::string error;
  const auto poly = msgs::FromMessage(t, &error);
  ASSERT_TRUE(poly.has_value()) << error;
  EXPECT_NEAR(poly->p0_W_m.x(), start_.x_m, 1e-3);  // from rest at the robot
  EXPECT_NEAR(poly->p0_W_m.y(), start_.y_m, 1e-3);
  EXPECT_NEAR(poly->yaw0_rad, start_.yaw_rad, 1e-3);
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("tracker released"), std::string::npos) << log;
  EXPECT_NE(log.find("cannot plan yet: the robot is coming to rest after the tracker's hold"), std::string::npos) << log;
  EXPECT_EQ(log.find("moving start"), std::string::npos) << log;
}

// A moving robot whose ROBOT_STATE is stale (stamped 5 s ago: a replayed log, a stuck
// estimator) is not planned from that state extrapolated 6 s at its rates: the goal waits,
// saying why, and is planned from rest once a fresh state shows the robot at rest.
TEST_F(PlannerProcess, AStaleStateOfAMovingRobotIsNotExtrapolated) {
  v_mps_ = 0.2;
  state_age_s_ = 5.0;
  Send(ReachableGoal(24));
  const auto waiting = [&] {
    const planner_status_t* s = out_.Last(24, planner_status_t::PLANNING);
    return s != nullptr && s->detail.find("not extrapolated") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(waiting, 10.0)) << ReadText(dir_ + "/planner.txt");
  SpinWithRobot([] { return false; }, 1.0);
  EXPECT_TRUE(out_.trajectories.empty());
  v_mps_ = 0.0;
  state_age_s_ = 0.0;
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::string error;
  const auto poly = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(poly.has_value()) << error;
  EXPECT_NEAR(poly->p0_W_m.x(), start_.x_m, 1e-3);  // from rest at the robot
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("its state is 5."), std::string::npos) << log;
  EXPECT_EQ(log.find("moving start"), std::string::npos) << log;
}

// The goal's trajectory ends on the planner's clock while the tracker is still closing on its end,
// and then the drives stop (a bus-off): the goal is open again and, once the tracker is released,
// planned from rest where the robot stopped. Before, the goal stayed SUCCEEDED and the mission
// waited 120 s for the tracker's FINISHED.
TEST_F(PlannerProcess, AGoalHeldBeforeTheTrackerFinishedItIsPlannedAgainOnRelease) {
  Send(ReachableGoal(23));
  const auto tracker = [&](std::int8_t state) {
    Tracker(state, 23, out_.trajectories.empty() ? 0 : out_.trajectories.back().trajectory_id);
  };
  const auto ended = [&] {
    const planner_status_t* s = out_.Last(23, planner_status_t::SUCCEEDED);
    return s != nullptr && msgs::ReportsTrajectoryEnded(*s);
  };
  ASSERT_TRUE(SpinWithRobot([&] { tracker(tracker_status_t::TRACKING); return ended(); }, 90.0))
      << ReadText(dir_ + "/planner.txt");
  const std::size_t before = out_.trajectories.size();
  tracker(tracker_status_t::HELD);
  const auto waiting = [&] {
    const planner_status_t* s = out_.Last(23, planner_status_t::PLANNING);
    return s != nullptr && s->detail.find("tracker HELD") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(waiting, 10.0)) << ReadText(dir_ + "/planner.txt");
  tracker(tracker_status_t::IDLE);  // released, the robot at rest short of the goal
  ASSERT_TRUE(SpinWithRobot([&] { return out_.trajectories.size() > before; }, 60.0)) << ReadText(dir_ + "/planner.txt");
  EXPECT_EQ(out_.trajectories.back().goal_id, 23);
  std::string error;
  const auto poly = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(poly.has_value()) << error;
  EXPECT_NEAR(poly->p0_W_m.x(), start_.x_m, 1e-3);  // from rest where the robot stopped
  EXPECT_NEAR(poly->p0_W_m.y(), start_.y_m, 1e-3);
}

// A goal the tracker had finished stays done when the tracker is held later (no motion after it).
TEST_F(PlannerProcess, AGoalTheTrackerFinishedStaysDoneThroughAHold) {
  Send(ReachableGoal(24));
  const auto tracker = [&](std::int8_t state) { Tracker(state); };
  const auto ended = [&] {
    const planner_status_t* s = out_.Last(24, planner_status_t::SUCCEEDED);
    return s != nullptr && msgs::ReportsTrajectoryEnded(*s);
  };
  ASSERT_TRUE(SpinWithRobot(ended, 90.0)) << ReadText(dir_ + "/planner.txt");
  SpinWithRobot([&] { tracker(tracker_status_t::FINISHED); return false; }, 0.3);
  const std::size_t before = out_.trajectories.size();
  tracker(tracker_status_t::HELD);
  SpinWithRobot([] { return false; }, 0.5);
  tracker(tracker_status_t::IDLE);
  SpinWithRobot([] { return false; }, 5.0);
  EXPECT_EQ(out_.trajectories.size(), before);
  for (const planner_status_t& s : out_.statuses) {
    if (s.goal_id == 24) {
      EXPECT_EQ(s.detail.find("tracker HELD"), std::string::npos) << s.detail;
    }
  }
}

// Goal ids are issued once: a repeat of the goal in hand changes nothing, and another target
// under its id (a corrupted copy, a foreign sender) neither cancels it nor moves the robot.
TEST_F(PlannerProcess, AGoalIdIsNotReusedForAnotherTarget) {
  const goal_t goal = ReachableGoal(31);
  Send(goal);
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  goal_t repeat = goal;
  repeat.utime += 1000;
  goal_t other = goal;
  other.p_WE[0] += 0.5;
  Send(repeat);
  Send(other);
  SpinWithRobot([] { return false; }, 1.5);  // handled meanwhile (nothing to wait for: they change nothing)
  EXPECT_EQ(out_.trajectories.size(), 1u);  // one plan: neither copy replanned
  EXPECT_EQ(out_.Last(31, planner_status_t::CANCELLED), nullptr);
  EXPECT_EQ(out_.Last(31, planner_status_t::FAILED), nullptr);
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("GOAL 31 ignored: a repeat of the goal in hand"), std::string::npos) << log;
  EXPECT_NE(log.find("GOAL 31 ignored: its id was issued before with a different target"), std::string::npos) << log;
  EXPECT_NE(log.find("3 goals (1 refused, 0 failed as the map came to refuse them, 1 repeats ignored, 0 cancelled)"), std::string::npos) << log;
}

// Finding 36 (hostile payloads, fault table of the twenty-fifth session): a copy of the mission's
// goal with its id bit-flipped replaced the goal in hand, then a copy under the mission's id
// with a bit-flipped quaternion was taken for a new goal and failed the mission's goal ("bad
// goal"). Now the goal in hand is reported CANCELLED when another replaces it (the sender
// knows at once, also with its trajectory under way), and a copy under any id taken before is
// ignored, not only under the last one's.
TEST_F(PlannerProcess, AGoalIdTakenBeforeTheLastIsNotReusedAndAReplacedGoalIsCancelled) {
  const goal_t goal = ReachableGoal(32);
  Send(goal);
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  goal_t forged = goal;  // its id bit-flipped
  forged.goal_id = 32 ^ (1 << 20);
  Send(forged);
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(32, planner_status_t::CANCELLED) != nullptr; }, 10.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_NE(out_.Last(32, planner_status_t::CANCELLED)->detail.find("goal 32 superseded by goal 1048608"),
            std::string::npos)
      << out_.Last(32, planner_status_t::CANCELLED)->detail;
  goal_t corrupted = goal;  // the first goal's id, its quaternion bit-flipped
  corrupted.quat_WE[0] = 2.0;
  Send(corrupted);
  SpinWithRobot([] { return false; }, 1.0);  // handled meanwhile (nothing to wait for: it changes nothing)
  EXPECT_EQ(out_.Last(32, planner_status_t::FAILED), nullptr) << "the copy failed goal 32";
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("GOAL 32 ignored: its id was issued before with a different target"), std::string::npos) << log;
}

// Fault table of the twenty-seventh session: a NaN goal, an unreachable one and one inside an
// obstacle (the fault tool's, another sender's) each superseded the mission's goal before it was
// refused, so three of them failed the mission's three attempts. A refused goal now leaves the
// goal in hand alone: FAILED under its own id, nothing said against the goal in hand.
TEST_F(PlannerProcess, ARefusedGoalLeavesTheGoalInHand) {
  Send(ReachableGoal(33));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  const std::size_t planned = out_.trajectories.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Send(Goal(34, {nan, 0.0, 0.5}));
  Send(Goal(35, {0.0, 0.0, 0.4}));   // inside an obstacle
  Send(Goal(36, {-1.0, 2.0, 3.0}));  // outside the arm's reach
  for (const std::int64_t id : {34, 35, 36}) {
    ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(id, planner_status_t::FAILED) != nullptr; }, 10.0))
        << "goal " << id << "\n" << ReadText(dir_ + "/planner.txt");
    const planner_status_t& refused = *out_.Last(id, planner_status_t::FAILED);
    EXPECT_FALSE(refused.failure_reason.empty());
    EXPECT_NE(refused.detail.find("goal 33 in hand goes on"), std::string::npos) << refused.detail;
  }
  const std::size_t after_refusals = out_.statuses.size();
  ASSERT_TRUE(SpinWithRobot([&] { return out_.statuses.size() > after_refusals; }, 5.0));  // the periodic status
  EXPECT_EQ(out_.statuses.back().goal_id, 33);
  EXPECT_NE(out_.statuses.back().state, planner_status_t::FAILED);
  EXPECT_EQ(out_.Last(33, planner_status_t::CANCELLED), nullptr);
  EXPECT_EQ(out_.Last(33, planner_status_t::FAILED), nullptr);
  for (std::size_t k = planned; k < out_.trajectories.size(); ++k) EXPECT_EQ(out_.trajectories[k].goal_id, 33);
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("4 goals (3 refused, 0 failed as the map came to refuse them, 0 repeats ignored, 0 cancelled)"),
            std::string::npos)
      << log;
}

// The mapper stops (its MAP_UPDATEs lost): once the map's newest scan is older than
// map.stale_stop_s the trajectory under way is stopped (STOPPING, a stopping trajectory) and no
// plan goes out; when fresh updates come back the goal is planned again.
TEST_F(PlannerProcess, AStaleMapStopsTheRobotUntilItIsFreshAgain) {
  RestartWithStaleOptions("stale_stop_s: 0.5}");
  MapperStandIn mapper;
  const auto with_map = [&](auto pred) { return WithMapper(&mapper, pred); };
  Send(ReachableGoal(41));
  ASSERT_TRUE(SpinWithRobot(with_map([&] { return !out_.trajectories.empty(); }), 60.0)) << ReadText(dir_ + "/planner.txt");
  const std::size_t planned = out_.trajectories.size();
  mapper.on = false;  // the map freezes
  const auto stopping = [&] {
    const planner_status_t* s = out_.Last(41, planner_status_t::STOPPING);
    return s != nullptr && s->detail.find("the map is stale") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(stopping, 5.0)) << ReadText(dir_ + "/planner.txt");
  EXPECT_EQ(out_.trajectories.size(), planned + 1);  // the stopping trajectory
  SpinWithRobot([] { return false; }, 1.0);
  EXPECT_EQ(out_.trajectories.size(), planned + 1) << "no plan on a stale map";
  mapper.on = true;
  ASSERT_TRUE(SpinWithRobot(with_map([&] { return out_.trajectories.size() > planned + 1; }), 30.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_EQ(out_.trajectories.back().goal_id, 41);
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("resume: the map is fresh again"), std::string::npos) << log;
  EXPECT_NE(log.find("(1 on a stale map)"), std::string::npos) << log;
}

// Finding 30: while the robot moves, the map is stale after map.stale_blind_distance_m / v
// (here 0.3 m), not after the whole map.stale_stop_s (here 3 s): the stop comes within about
// half a second of the map freezing, its detail naming the shorter limit.
TEST_F(PlannerProcess, AMapThatFreezesWhileTheRobotMovesIsStaleAfterSoManyMetres) {
  RestartWithStaleOptions("stale_stop_s: 3.0, stale_blind_distance_m: 0.3, stale_min_s: 0.3}");
  MapperStandIn mapper;
  mapper.period_s = 0.1;
  const auto with_map = [&](auto pred) { return WithMapper(&mapper, pred); };
  Send(ReachableGoal(42));
  ASSERT_TRUE(SpinWithRobot(with_map([&] { return !out_.trajectories.empty(); }), 60.0)) << ReadText(dir_ + "/planner.txt");
  v_mps_ = 0.8;  // on its way (measured): the limit 0.3 m / 0.8 m/s = 0.375 s
  SpinWithRobot(with_map([] { return false; }), 0.5);
  mapper.on = false;  // the map freezes
  const Clock::time_point frozen = Clock::now();
  const auto stopping = [&] {
    const planner_status_t* s = out_.Last(42, planner_status_t::STOPPING);
    return s != nullptr && s->detail.find("the map is stale") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(stopping, 5.0)) << ReadText(dir_ + "/planner.txt");
  EXPECT_LT(SecondsSince(frozen), 1.5);  // 3 s without the distance limit
  const std::string detail = out_.Last(42, planner_status_t::STOPPING)->detail;
  EXPECT_EQ(detail.find("(limit 3.00 s)"), std::string::npos) << detail;
}

// At start-up a goal can come before the mapper's first snapshot (the mission starts as soon as
// the planner heartbeats): it waits for the map, saying so, and is planned once the map is there.
TEST_F(PlannerProcess, AGoalBeforeTheFirstMapWaitsForItAndIsPlanned) {
  kill(planner_, SIGKILL);
  WaitFor(planner_, 3.0);
  StartPlanner(/*with_map=*/false);
  Send(ReachableGoal(12));
  const auto waiting = [&] {
    const planner_status_t* s = out_.Last(12, planner_status_t::PLANNING);
    return s != nullptr && s->detail.find("waiting: no map yet") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(waiting, 10.0)) << ReadText(dir_ + "/planner.txt");
  SpinWithRobot([] { return false; }, 1.0);  // retries meanwhile: still waiting, never failed
  EXPECT_EQ(out_.Last(12, planner_status_t::FAILED), nullptr) << ReadText(dir_ + "/planner.txt");
  SendMap();
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(12, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_EQ(out_.trajectories.back().goal_id, 12);
}

// A goal whose target the robot's end effector already holds, at rest (e.g. a safe stop that
// ended at the goal, whose surroundings the map now shows too close for a plan to it): reached,
// no plan, no trajectory.
TEST_F(PlannerProcess, AGoalTheRobotAlreadyHoldsAtRestIsReachedWithoutAPlan) {
  msgs::PlanGoal goal;
  goal.utime = procs::NowUtime();
  goal.goal_id = 13;
  goal.X_WE = kinematics_.EndEffectorPose(start_);
  goal.X_WE.translation().x() += 0.01;  // within goals.reached_position_m (0.02 m)
  Send(msgs::ToMessage(goal));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(13, planner_status_t::SUCCEEDED) != nullptr; }, 10.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_NE(out_.Last(13, planner_status_t::SUCCEEDED)->detail.find("goal reached at rest: end effector 0.010 m"),
            std::string::npos)
      << out_.Last(13, planner_status_t::SUCCEEDED)->detail;
  EXPECT_TRUE(out_.trajectories.empty());
}

// A robot that came to rest with its base 12 mm into a map voxel (a stop that braked into a
// table leg's 5 cm voxels, the real leg not touched) is planned from rest out of it: the plan
// leaves the voxels it stands in out of the start check, and its base never goes deeper into
// them than it stood (the leg dead ahead, the goal straight on beyond it). Before the reach reports were
// one contract, a graph test took such a stop at the goal for a goal never reached.
TEST_F(PlannerProcess, ABaseStoppedJustInsideAVoxelIsPlannedOutWithoutGoingDeeper) {
  // The voxel column x in [-2.10, -2.05], y in [-2.50, -2.45], 0.65 m tall; the base axis
  // 0.388 m from its face (radius 0.400 m), facing it.
  start_.x_m = -2.488;
  const GridGeometry3 g = planner::testing::RoomGeometry();
  const Eigen::AlignedBox2d leg(Eigen::Vector2d(-2.10, -2.50), Eigen::Vector2d(-2.05, -2.45));
  std::vector<VoxelChange> column;
  const CellBox cells = VoxelsOverlapping(g, {Eigen::Vector3d(-2.09, -2.49, 0.0), Eigen::Vector3d(-2.06, -2.46, 0.64)});
  for (int iz = cells.begin.z(); iz < cells.end.z(); ++iz) column.push_back({{cells.begin.x(), cells.begin.y(), iz}, VoxelState::kOccupied});
  ASSERT_EQ(cells.end.x() - cells.begin.x(), 1);
  ASSERT_EQ(cells.end.y() - cells.begin.y(), 1);
  const map_update_t delta = msgs::EncodeMapDelta(g, column, procs::NowUtime(), 2);
  watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &delta);
  const auto depth_m = [&](const Eigen::Vector2d& p_WB) {  // how far the base reaches into the column
    return model_.base_cylinder.radius_m - leg.exteriorDistance(p_WB);
  };
  const double start_depth_m = depth_m({start_.x_m, start_.y_m});
  ASSERT_NEAR(start_depth_m, 0.012, 1e-9);
  msgs::PlanGoal goal;  // straight on, past the leg
  goal.utime = procs::NowUtime();
  goal.goal_id = 14;
  goal.hint = BentArmState(-0.8, -2.5, 0.0);
  goal.X_WE = kinematics_.EndEffectorPose(*goal.hint);
  Send(msgs::ToMessage(goal));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::string error;
  const auto poly = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(poly.has_value()) << error;
  EXPECT_EQ(out_.trajectories.back().goal_id, 14);
  EXPECT_NEAR(poly->p0_W_m.x(), start_.x_m, 1e-3);  // from where it stands
  double deepest_m = -1.0;
  for (const Eigen::Vector2d& p_WB : BasePath(*poly, poly->durations_s.sum(), 4000)) deepest_m = std::max(deepest_m, depth_m(p_WB));
  EXPECT_LE(deepest_m, start_depth_m + 1e-3) << "the base went deeper into the voxels it stood in";
}

// A goal that had its trajectory, whose robot is then walled in (pillars all round it, closer
// than the route's first metre): the trajectory is stopped, and after
// timing.max_failed_plans_from_rest plans from rest in a row fail, the goal FAILS ("stuck")
// instead of being retried for ever.
TEST_F(PlannerProcess, AGoalWhoseRobotIsWalledInFailsAsStuckAfterItsPlansFromRest) {
  std::string yaml = ReadText(dir_ + "/planner.yaml");  // its timing map gets the limit
  const std::size_t at = yaml.find("from_rest_time_limit_s: 20.0");
  ASSERT_NE(at, std::string::npos) << yaml;
  yaml.replace(at, std::string("from_rest_time_limit_s: 20.0").size(),
               "from_rest_time_limit_s: 5.0, max_failed_plans_from_rest: 3");
  WriteText(dir_ + "/planner.yaml", yaml);
  RestartPlanner();
  Send(ReachableGoal(51));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::vector<Eigen::Vector2d> ring;
  for (int k = 0; k < 16; ++k) {
    const double a = 2.0 * M_PI * k / 16.0;
    ring.emplace_back(start_.x_m + 0.9 * std::cos(a), start_.y_m + 0.9 * std::sin(a));
  }
  SendPillars(ring, 2);
  const auto stuck = [&] {
    const planner_status_t* s = out_.Last(51, planner_status_t::FAILED);
    return s != nullptr && s->failure_reason.find("stuck: 3 plans from rest failed in a row") != std::string::npos;
  };
  ASSERT_TRUE(SpinWithRobot(stuck, 90.0)) << ReadText(dir_ + "/planner.txt");
  EXPECT_TRUE(launch::ProcessAlive(planner_));
}

TEST_F(PlannerProcess, EveryBadGoalFailsAtOnceWithItsReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    goal_t goal;
    std::string reason;
  };
  std::vector<Case> cases;
  cases.push_back({Goal(21, {nan, 0.0, 0.5}), "bad goal"});
  goal_t skew = Goal(22, {-1.0, 2.0, 0.5});
  skew.quat_WE[0] = 2.0;
  cases.push_back({skew, "bad goal"});
  cases.push_back({Goal(23, {9.0, 0.0, 0.5}), "outside the map"});
  cases.push_back({Goal(24, {0.0, 0.0, 0.4}), "inside an obstacle"});
  cases.push_back({Goal(25, {-1.0, 2.0, 3.0}), "outside the arm's reach"});
  cases.push_back({Goal(26, {3.0, 0.0, 0.5}), "unreachable"});  // beyond the wall at x = 1
  for (const Case& c : cases) {
    Send(c.goal);
    const std::int64_t id = c.goal.goal_id;
    ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(id, planner_status_t::FAILED) != nullptr; }, 30.0))
        << "goal " << id << "\n" << ReadText(dir_ + "/planner.txt");
    EXPECT_NE(out_.Last(id, planner_status_t::FAILED)->failure_reason.find(c.reason), std::string::npos)
        << "goal " << id << ": " << out_.Last(id, planner_status_t::FAILED)->failure_reason;
  }
  EXPECT_TRUE(out_.trajectories.empty());
  EXPECT_TRUE(launch::ProcessAlive(planner_));
}

// Finding 35: a target inside a body the map shows only from outside (its rim occupied, its
// inside never seen) is refused at once; a goal in hand fails, and the robot on its way stops,
// when the map comes to show its target inside such a body.
TEST_F(PlannerProcess, ATargetInsideABodySeenOnlyFromOutsideIsRefusedOrFailsWhenSeen) {
  const GridGeometry3 g = planner::testing::RoomGeometry();
  const map_update_t body = msgs::EncodeMapDelta(
      g, planner::testing::UnseenBody(g, MakeBox({-3.0, 1.0, 0.4}, {0.5, 0.6, 0.8})), procs::NowUtime(), 2);
  watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &body);
  Send(Goal(61, {-3.0, 1.0, 0.4}));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(61, planner_status_t::FAILED) != nullptr; }, 30.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_NE(out_.Last(61, planner_status_t::FAILED)->failure_reason.find("seen only from outside"), std::string::npos)
      << out_.Last(61, planner_status_t::FAILED)->failure_reason;
  EXPECT_TRUE(out_.trajectories.empty());

  Send(ReachableGoal(62));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  const std::size_t planned = out_.trajectories.size();
  const Eigen::Vector3d p_WT = kinematics_.EndEffectorPose(BentArmState(-1.0, 2.0, 1.0)).translation();
  const map_update_t seen = msgs::EncodeMapDelta(
      g, planner::testing::UnseenBody(g, MakeBox(p_WT, {0.4, 0.4, 0.3})), procs::NowUtime(), 3);
  watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &seen);
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(62, planner_status_t::FAILED) != nullptr; }, 10.0))
      << ReadText(dir_ + "/planner.txt");
  const planner_status_t& failed = *out_.Last(62, planner_status_t::FAILED);
  EXPECT_NE(failed.failure_reason.find("seen only from outside"), std::string::npos) << failed.failure_reason;
  EXPECT_NE(failed.detail.find("the robot is stopping"), std::string::npos) << failed.detail;
  ASSERT_EQ(out_.trajectories.size(), planned + 1);  // the stopping trajectory
  EXPECT_EQ(out_.trajectories.back().goal_id, 62);
  EXPECT_NE(out_.Last(62, planner_status_t::STOPPING), nullptr);
  EXPECT_TRUE(launch::ProcessAlive(planner_));
}

TEST_F(PlannerProcess, ABoxOnTheRouteTriggersAReplanThatAvoidsIt) {
  Send(ReachableGoal(31));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::string error;
  const auto first = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(first.has_value()) << error;
  // A pillar where the first trajectory's base is 60 % of the way (still ahead of the robot,
  // which the planner believes is driving it).
  const Eigen::Vector2d p = BaseAt(*first, 0.6 * first->durations_s.sum());
  SendPillar(p, 2);
  const std::size_t before = out_.trajectories.size();
  ASSERT_TRUE(SpinWithRobot([&] { return out_.trajectories.size() > before; }, 30.0)) << ReadText(dir_ + "/planner.txt");
  const poly_trajectory_t& second = out_.trajectories.back();
  EXPECT_EQ(second.goal_id, 31);
  EXPECT_GT(second.trajectory_id, out_.trajectories[before - 1].trajectory_id);
  bool said_why = false;
  for (const planner_status_t& s : out_.statuses) said_why |= s.detail.find("collides") != std::string::npos;
  EXPECT_TRUE(said_why);
  EXPECT_GE(out_.statuses.back().replans, 1);
}

// A plan whose fields do not yet hold an obstacle far from its start (the background has not got
// to it, and it is outside the plan's fresh region; here a plan from rest, told not to flush
// the whole map first, stands in for a moving replan) is checked against the newest map before it
// goes out: it collides, so the planner replans with the obstacle's surroundings brought into
// its fields (going out first if the collision is far enough ahead), and the robot's last
// trajectory goes around it.
TEST_F(PlannerProcess, AnObstacleTheFieldsLackIsCaughtBeforeThePlanGoesOutAndAvoided) {
  std::string yaml = ReadText(dir_ + "/planner.yaml");  // its map options join stale_stop_s
  const std::size_t at = yaml.find("map: {stale_stop_s: 0}");
  ASSERT_NE(at, std::string::npos) << yaml;
  yaml.replace(at, std::string("map: {stale_stop_s: 0}").size(),
               "map: {stale_stop_s: 0, fresh_radius_m: 1.0, field_update_period_s: 60.0, flush_all_from_rest: false}");
  WriteText(dir_ + "/planner.yaml", yaml);
  RestartPlanner();
  Send(ReachableGoal(41));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::string error;
  const auto first = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(first.has_value()) << error;
  // A pillar where that route's base is 70 % of the way, far beyond the fresh region (1 m).
  const Eigen::Vector2d p = BaseAt(*first, 0.7 * first->durations_s.sum());
  ASSERT_GT((p - Eigen::Vector2d(start_.x_m, start_.y_m)).norm(), 2.0);
  // A fresh planner (no trajectory under way to check the pillar against), its fields built
  // from the room's map; then the pillar, pending (the background waits 60 s), then the goal.
  RestartPlanner();
  SpinWithRobot([] { return false; }, 1.5);
  SendPillar(p, 2);
  SpinWithRobot([] { return false; }, 0.2);
  Send(ReachableGoal(42));
  const auto avoided = [&] {
    if (out_.trajectories.empty() || out_.trajectories.back().goal_id != 42) return false;
    const auto t = msgs::FromMessage(out_.trajectories.back(), &error);
    return t && BaseDistanceToPillar(*t, p) > model_.base_cylinder.radius_m;
  };
  ASSERT_TRUE(SpinWithRobot(avoided, 60.0)) << ReadText(dir_ + "/planner.txt");
  bool caught = false;
  for (const planner_status_t& s : out_.statuses) caught |= s.detail.find("collides with the newer map") != std::string::npos;
  EXPECT_TRUE(caught) << "the first plan for goal 42 was not caught colliding\n" << ReadText(dir_ + "/planner.txt");
}

// kill -9 of the planner: the restarted planner's trajectory ids continue above the dead one's
// (the tracker takes only a newer id; a restarted planner counting from 1 again had every
// trajectory ignored while the tracker kept the dead planner's last one, which drove the robot,
// moved back by a simulator restart, into a box: finding 13).
TEST_F(PlannerProcess, ARestartedPlannersTrajectoryIdsAreAboveTheDeadOnes) {
  Send(ReachableGoal(61));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(61, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  const std::int64_t before = out_.trajectories.back().trajectory_id;
  RestartPlanner();
  Send(ReachableGoal(62));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(62, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  EXPECT_EQ(out_.trajectories.back().goal_id, 62);
  EXPECT_GT(out_.trajectories.back().trajectory_id, before);
  EXPECT_EQ(out_.Last(62, planner_status_t::SUCCEEDED)->trajectory_id, out_.trajectories.back().trajectory_id);
}

// The robot stopped with its arm a few millimetres into voxels the map sensed since (a cap of
// voxels on top of its outermost arm sphere, no sphere deeper than 2 cm in any): a plan from rest
// is validated without the robot's own shallow overlaps (map.start_arm_overlap_m 0.03 m), and so
// is its check against the newest map, so it goes out. Before, every such plan was refused as
// "colliding with the newer map at 0.00 s", plan after plan (a PlannerGraph test stuck 60 s).
TEST_F(PlannerProcess, APlanFromRestWithTheArmJustInsideNewlySensedVoxelsGoesOut) {
  // Above the outermost sphere's middle, no sphere deeper than 2 cm in any.
  const std::vector<VoxelChange> cap =
      VoxelsOnTheArm(0.5, [](double deepest_m) { return deepest_m < 0.02; }, nullptr);
  ASSERT_FALSE(cap.empty());
  SpinWithRobot([] { return false; }, 0.5);
  const map_update_t delta = msgs::EncodeMapDelta(planner::testing::RoomGeometry(), cap, procs::NowUtime(), 2);
  watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &delta);
  SpinWithRobot([] { return false; }, 0.3);
  Send(ReachableGoal(51));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(51, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << cap.size() << " voxels on the arm\n" << ReadText(dir_ + "/planner.txt");
  ASSERT_FALSE(out_.trajectories.empty());
  EXPECT_EQ(out_.trajectories.back().goal_id, 51);
  for (const planner_status_t& s : out_.statuses) {
    EXPECT_EQ(s.detail.find("collides with the newer map"), std::string::npos) << s.detail;
  }
}

// Finding 18: the robot stopped with its arm in voxels deeper than a plan from rest leaves out
// (map.start_arm_overlap_m 0.03 m; the fault campaign: link7 4.8 cm in a table edge's voxels,
// no contact, a voxel being up to 5 cm larger than its surface). The first plan fails on its
// start (an arm sphere in a box of the map); the planner plans from rest again leaving out the voxels the arm
// reaches into by at most map.start_arm_escape_overlap_m (0.06 m), and that plan goes out.
// Before, every plan from rest failed on its start and the goal failed ("stuck").
TEST_F(PlannerProcess, AnArmStoppedDeepInVoxelsIsPlannedOutOfThem) {
  double deepest = 0.0;  // above a quarter of the outermost sphere, none as deep as the escape's 6 cm
  const std::vector<VoxelChange> cap =
      VoxelsOnTheArm(0.25, [](double deepest_m) { return deepest_m < 0.055; }, &deepest);
  ASSERT_GT(deepest, 0.035) << "deeper than a plan from rest leaves out (3 cm)";
  SpinWithRobot([] { return false; }, 0.5);
  const map_update_t delta = msgs::EncodeMapDelta(planner::testing::RoomGeometry(), cap, procs::NowUtime(), 2);
  watcher_->lcm().publish(std::string(channels::MAP_UPDATE), &delta);
  SpinWithRobot([] { return false; }, 0.3);
  Send(ReachableGoal(52));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(52, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << cap.size() << " voxels on the arm, " << deepest << " m deep\n" << ReadText(dir_ + "/planner.txt");
  ASSERT_FALSE(out_.trajectories.empty());
  EXPECT_EQ(out_.trajectories.back().goal_id, 52);
  const std::string log = ReadText(dir_ + "/planner.txt");
  EXPECT_NE(log.find("start state: the arm sphere"), std::string::npos) << log;
  EXPECT_NE(log.find("(an escape)"), std::string::npos) << log;
}

// Finding 25: a TRAJECTORY is one datagram; lost on a lossy bus, the tracker drove on along the
// old trajectory while the planner believed the robot braking (into a box placed meanwhile). The
// planner sends its newest trajectory again, the same message, until TRACKER_STATUS names it;
// then no more copies.
TEST_F(PlannerProcess, ATrajectoryTheTrackerDoesNotReportIsSentAgainUntilItDoes) {
  Tracker(tracker_status_t::IDLE);  // a tracker is there, and has not got it
  Send(ReachableGoal(61));
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(61, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  const std::int64_t id = out_.Last(61, planner_status_t::SUCCEEDED)->trajectory_id;
  const auto copies = [&] {
    return std::count_if(out_.trajectories.begin(), out_.trajectories.end(),
                         [&](const poly_trajectory_t& t) { return t.trajectory_id == id; });
  };
  ASSERT_TRUE(SpinWithRobot([&] { return copies() >= 4; }, 2.0)) << copies() << " copies in 2 s";
  const poly_trajectory_t* first = nullptr;
  for (const poly_trajectory_t& t : out_.trajectories) {
    if (t.trajectory_id != id) continue;
    if (first == nullptr) first = &t;
    EXPECT_EQ(t.utime, first->utime) << "the same message";
    EXPECT_EQ(t.start_utime, first->start_utime);
    EXPECT_EQ(t.coeffs, first->coeffs);
  }
  Tracker(tracker_status_t::TRACKING, 61, id);
  SpinWithRobot([] { return false; }, 0.3);
  const auto reported = copies();
  SpinWithRobot([] { return false; }, 0.6);
  EXPECT_EQ(copies(), reported) << "no copies once the tracker reports it";
  const std::string log = ReadText(dir_ + "/planner.txt");
  EXPECT_NE(log.find("not reported by the tracker yet: sent again"), std::string::npos) << log;
}

TEST_F(PlannerProcess, AGoalFloodLeavesTheLoopResponsiveAndTheLastGoalPlanned) {
  const int pid_before = watcher_->last["planner"].pid;
  const int beats_before = watcher_->last["planner"].count;
  const Clock::time_point start = Clock::now();
  for (int k = 0; k < 100; ++k) {  // 100 Hz for 1 s
    Send(ReachableGoal(100 + k));
    SpinWithRobot([] { return false; }, 0.01);
  }
  ASSERT_TRUE(SpinWithRobot([&] { return out_.Last(199, planner_status_t::SUCCEEDED) != nullptr; }, 60.0))
      << ReadText(dir_ + "/planner.txt");
  // Heartbeats kept coming (1 Hz) and the superseded goals were reported cancelled.
  const double elapsed = SecondsSince(start);
  EXPECT_GE(watcher_->last["planner"].count - beats_before, static_cast<int>(elapsed) - 2);
  EXPECT_EQ(watcher_->last["planner"].pid, pid_before);
  int cancelled = 0;
  for (const planner_status_t& s : out_.statuses) cancelled += s.state == planner_status_t::CANCELLED;
  EXPECT_GE(cancelled, 1);
  ASSERT_FALSE(out_.trajectories.empty());
  EXPECT_EQ(out_.trajectories.back().goal_id, 199);
}

// Finding 34: a robot off its trajectory by more than the trajectory's clearance can touch what
// the trajectory passes. A low block (only the base can touch it) 0.1 m beside the route: the
// trajectory clears it, a robot 0.2 m off it on the other side is checked and clears it too, a
// robot 0.2 m off towards it is seen colliding as it drifts, and the planner replans from the
// drifted robot (or stops it) before it gets there.
TEST_F(PlannerProcess, ARobotDriftingTowardsAnObstacleTheTrajectoryClearsIsReplannedOrStopped) {
  // The drift check at its defaults. The played robot keeps its error (it reports no rates and
  // is never tracked), the case of the carried start: a replan starts where it will be then.
  // The tracked start (the default) is ActiveTrajectoryTest.ATrackedStartIsWhereTheTrackerBringsTheRobot.
  std::string yaml = ReadText(dir_ + "/planner.yaml");
  const std::string no_check = ", drift_check_position_m: 100, drift_check_yaw_rad: 100, drift_check_joint_rad: 100";
  const std::size_t at = yaml.find(no_check);
  ASSERT_NE(at, std::string::npos) << yaml;
  yaml.replace(at, no_check.size(), ", drift_start: carried");
  WriteText(dir_ + "/planner.yaml", yaml);
  RestartPlanner();
  Send(ReachableGoal(71));
  ASSERT_TRUE(SpinWithRobot([&] { return !out_.trajectories.empty(); }, 60.0)) << ReadText(dir_ + "/planner.txt");
  std::string error;
  const auto first = msgs::FromMessage(out_.trajectories.back(), &error);
  ASSERT_TRUE(first.has_value()) << error;
  const double duration_s = first->durations_s.sum();
  // The block beside the base at 70 % of the way, 0.1 m from the base's outline.
  const double t_block_s = 0.7 * duration_s;
  const double yaw = first->Evaluate(t_block_s)(1);
  const Eigen::Vector2d n_W(-std::sin(yaw), std::cos(yaw));  // to the left of the route there
  const double radius_m = model_.base_cylinder.radius_m;
  const Eigen::Vector2d p = BaseAt(*first, t_block_s) + (radius_m + kPillarHalf_m + 0.1) * n_W;
  ASSERT_GT(BaseDistanceToPillar(*first, p), radius_m + 0.05) << "the route bends towards the block";
  SendPillars({p}, 2, 0.1);
  // Plays the robot on `first` at the wall clock (its start until then), off it by offset_W.
  const auto follow = [&](const Eigen::Vector2d& offset_W, const auto& pred, double timeout_s) {
    const Clock::time_point begin = Clock::now();
    while (!pred() && SecondsSince(begin) < timeout_s) {
      msgs::RobotStateEstimate robot;
      robot.utime = procs::NowUtime();
      const double t_s = std::clamp(1e-6 * static_cast<double>(robot.utime - first->start_utime), 0.0, duration_s);
      const Eigen::VectorXd value = first->Evaluate(t_s);
      const Eigen::Vector2d p_W = BaseAt(*first, t_s) + offset_W;
      robot.state = start_;
      robot.state.x_m = p_W.x();
      robot.state.y_m = p_W.y();
      robot.state.yaw_rad = value(1);
      robot.state.q_rad = value.tail(7);
      robot.qdot_radps = Eigen::VectorXd::Zero(7);
      const robot_state_t msg = msgs::ToMessage(robot);
      watcher_->lcm().publish(std::string(channels::ROBOT_STATE), &msg);
      const Clock::time_point sent = Clock::now();
      while (SecondsSince(sent) < 0.02) watcher_->lcm().handleTimeout(5);
    }
    return pred();
  };
  const auto said_drifts = [&] {
    for (const planner_status_t& s : out_.statuses) {
      if (s.detail.find("as it drifts") != std::string::npos) return true;
    }
    return false;
  };
  // Away from the block, up to 3 s before the block: checked, clear.
  const double away_s = std::max(0.5, t_block_s - 1e-6 * static_cast<double>(procs::NowUtime() - first->start_utime) - 3.0);
  EXPECT_FALSE(follow(-0.2 * n_W, said_drifts, away_s)) << ReadText(dir_ + "/planner.txt");
  const std::size_t before = out_.trajectories.size();
  // Towards it: a collision as it drifts, then a new trajectory (a replan or a stop).
  ASSERT_TRUE(follow(0.2 * n_W, [&] { return said_drifts() && out_.trajectories.size() > before; }, duration_s))
      << ReadText(dir_ + "/planner.txt");
  const poly_trajectory_t& next = out_.trajectories.back();
  EXPECT_EQ(next.goal_id, 71);
  EXPECT_GT(next.trajectory_id, first->trajectory_id);
  // It starts before the robot would reach the block, where the robot will be then (a replan
  // from the drifted robot, or a stop braking from there rather than from the trajectory).
  const double t_next_s = 1e-6 * static_cast<double>(next.start_utime - first->start_utime);
  EXPECT_LT(t_next_s, t_block_s);
  const auto next_t = msgs::FromMessage(next, &error);
  ASSERT_TRUE(next_t.has_value()) << error;
  EXPECT_LT((next_t->p0_W_m - (BaseAt(*first, t_next_s) + 0.2 * n_W)).norm(), 0.05)
      << "it starts at " << next_t->p0_W_m.transpose() << ", not where the robot is";
  const std::string log = StopPlannerAndReadLog();
  EXPECT_NE(log.find("drift_collision"), std::string::npos) << log;
}

}  // namespace
}  // namespace topay::test
