// topay-mission in the closed loop: topay-sim (its plant driven by the tracker's commands, with
// command latency and actuator lag), topay-mapper, topay-planner, topay-tracker and topay-mission
// as real processes over real LCM in a private network
// namespace (skipped, with the reason, where none can be made), in a Tables room the planner
// has never seen. A two-goal mission (goto, close the gripper, goto, open it, home) written by the
// test with goals it can prove reachable (tests/procs/planner/unseen_room.h) must end with the
// mission process's exit code 0, MISSION_STATUS SUCCEEDED and no contact in the simulator's
// collision monitor.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <optional>

#include "graph_test_support.h"
#include "tests/common/real_time_skip.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/convert_robot_state.h"
#include "tests/procs/mission/closed_loop_graph.h"
#include "tests/procs/planner/unseen_room.h"
#include "topay/mission_status_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_status_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608";

std::string Bin(const std::string& name) { return BinDir() + "/" + name; }
std::string ConfigFile(const std::string& rel) { return std::string(TOPAY_SOURCE_DIR) + "/config/" + rel; }

struct MissionListener {
  std::vector<mission_status_t> statuses;
  std::optional<robot_state_t> robot;
  std::optional<sim_status_t> sim;
  void OnMission(const lcm::ReceiveBuffer*, const std::string&, const mission_status_t* m) { statuses.push_back(*m); }
  void OnRobot(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { robot = *m; }
  void OnSim(const lcm::ReceiveBuffer*, const std::string&, const sim_status_t* m) { sim = *m; }
};

// A goto step of the mission YAML to the end-effector pose of `state`, with it as the hint.
std::string GotoStep(const Kinematics& kinematics, const WholeBodyState& state, const std::string& name) {
  const Eigen::Isometry3d X_WE = kinematics.EndEffectorPose(state);
  const Eigen::Quaterniond q(X_WE.linear());
  std::string q_rad;
  for (int j = 0; j < state.num_joints(); ++j) q_rad += fmt::format("{}{:.17g}", j ? ", " : "", state.q_rad(j));
  return fmt::format(
      "  - type: goto\n    name: {}\n    position_m: [{:.17g}, {:.17g}, {:.17g}]\n"
      "    quat_wxyz: [{:.17g}, {:.17g}, {:.17g}, {:.17g}]\n"
      "    hint: {{x_m: {:.17g}, y_m: {:.17g}, yaw_rad: {:.17g}, q_rad: [{}]}}\n",
      name, X_WE.translation().x(), X_WE.translation().y(), X_WE.translation().z(), q.w(), q.x(), q.y(), q.z(),
      state.x_m, state.y_m, state.yaw_rad, q_rad);
}

class MissionGraph : public ::testing::Test {
 protected:
  void SetUp() override {
    TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD();
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("graph");
    scene_ = WriteUnseenTablesRoom(dir_ + "/room.json");
    watcher_ = std::make_unique<HeartbeatWatcher>(kLcmUrl);
    lcm::LCM& lcm = watcher_->lcm();
    lcm.subscribe(std::string(channels::MISSION_STATUS), &MissionListener::OnMission, &out_);
    lcm.subscribe(std::string(channels::ROBOT_STATE), &MissionListener::OnRobot, &out_);
    lcm.subscribe(std::string(channels::SIM_STATUS), &MissionListener::OnSim, &out_);
    pids_ = SpawnClosedLoopGraph(dir_, kLcmUrl);
    ASSERT_TRUE(watcher_->SpinUntil([&] { return out_.robot.has_value() && watcher_->last.contains("planner") &&
                                                  watcher_->last.contains("mapper") &&
                                                  watcher_->last.contains("tracker"); }, 15.0))
        << Logs();
    watcher_->Spin(1.0);  // a few scans into the map
  }
  void TearDown() override {
    StopProcesses(pids_);
    if (HasFailure()) std::cout << Logs();
  }
  std::string Logs() const {
    return "--- sim\n" + ReadText(dir_ + "/sim.txt") + "--- tracker\n" + ReadText(dir_ + "/tracker.txt") +
           "--- planner\n" + ReadText(dir_ + "/planner.txt") + "--- mission\n" + ReadText(dir_ + "/mission.txt") +
           "--- mapper\n" + ReadText(dir_ + "/mapper.txt");
  }
  // Handles messages until `pid` exits (its wait status) or timeout_s (-1).
  int SpinUntilExit(pid_t pid, double timeout_s) {
    const Clock::time_point start = Clock::now();
    while (SecondsSince(start) < timeout_s) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        watcher_->Spin(0.3);  // the last statuses
        return status;
      }
      watcher_->Spin(0.05);
    }
    return -1;
  }

  RobotModel model_ = LoadRobotModel(ConfigFile("robot/topay_mm.urdf"), ConfigFile("robot/topay_mm.yaml"));
  Kinematics kinematics_{model_};
  Scene scene_;
  std::string dir_;
  std::vector<pid_t> pids_;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  MissionListener out_;
};

TEST_F(MissionGraph, ATwoGoalMissionAndHomeSucceedWithoutTouchingAnything) {
  std::string error;
  const WholeBodyState start = msgs::FromMessage(*out_.robot, &error)->state;
  Rng rng(19);
  const std::optional<WholeBodyState> first = ReachableGoal(scene_, kinematics_, Eigen::Vector2d::Zero(), 3.0, 4.5, &rng);
  ASSERT_TRUE(first.has_value()) << "no first goal";
  const std::optional<WholeBodyState> second =
      ReachableGoal(scene_, kinematics_, Eigen::Vector2d(first->x_m, first->y_m), 3.0, 4.5, &rng);
  ASSERT_TRUE(second.has_value()) << "no second goal";
  WriteText(dir_ + "/mission.yaml", "name: two_goals\nsteps:\n" + GotoStep(kinematics_, *first, "pickup") +
                                        "  - {type: gripper, action: close, settle_s: 0.3}\n" +
                                        GotoStep(kinematics_, *second, "dropoff") +
                                        "  - {type: gripper, action: open, settle_s: 0.3}\n"
                                        "  - {type: home}\n");
  WriteText(dir_ + "/mission_options.yaml", "step_timeout_s: 90\nmax_attempts: 3\n");
  const pid_t mission = Spawn({Bin("topay-mission"), "--config", dir_ + "/mission_options.yaml", "--mission",
                               dir_ + "/mission.yaml", "--name", "mission", "--lcm-url", kLcmUrl},
                              dir_ + "/mission.txt");
  const int status = SpinUntilExit(mission, 220.0);
  if (status == -1) kill(mission, SIGINT), WaitFor(mission, 5.0);
  std::cout << ReadText(dir_ + "/mission.txt");
  // On failure TearDown prints every process's log once; the sim's (its contacts) comes first.
  ASSERT_NE(status, -1) << "the mission did not end in 220 s";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  ASSERT_FALSE(out_.statuses.empty());
  const mission_status_t& last = out_.statuses.back();
  EXPECT_EQ(last.state, mission_status_t::SUCCEEDED) << last.detail;
  EXPECT_EQ(last.num_steps, 5);
  EXPECT_EQ(last.step_index, 4);
  bool saw_running = false;
  for (const mission_status_t& s : out_.statuses) saw_running = saw_running || s.state == mission_status_t::RUNNING;
  EXPECT_TRUE(saw_running);
  // Home: the end effector back where it was at the start.
  const WholeBodyState end = msgs::FromMessage(*out_.robot, &error)->state;
  EXPECT_LT((kinematics_.EndEffectorPose(end).translation() - kinematics_.EndEffectorPose(start).translation()).norm(),
            0.03);
  ASSERT_TRUE(out_.sim.has_value());
  EXPECT_EQ(out_.sim->contact_events, 0);
}

}  // namespace
}  // namespace topay::test
