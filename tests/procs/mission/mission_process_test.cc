// The topay-mission process on its own (the test plays the robot and the planner over real LCM
// in a private network namespace, skipped with the reason where none can be made): its exit
// codes (0 success, 1 a bad mission file, 2 usage, 3 a failed mission, 4 SIGINT) and the
// MISSION_STATUS that goes with them.

#include <gtest/gtest.h>

#include <optional>

#include "graph_test_support.h"
#include "core/io/robot_loader.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/runtime/process_loop.h"
#include "tests/common/arm_state.h"
#include "topay/goal_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

struct Bus {
  std::vector<goal_t> goals;
  std::vector<mission_status_t> statuses;
  void OnGoal(const lcm::ReceiveBuffer*, const std::string&, const goal_t* m) { goals.push_back(*m); }
  void OnMission(const lcm::ReceiveBuffer*, const std::string&, const mission_status_t* m) { statuses.push_back(*m); }
};

class MissionProcess : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("run");
    watcher_ = std::make_unique<HeartbeatWatcher>(kLcmUrl);
    watcher_->lcm().subscribe(std::string(channels::GOAL), &Bus::OnGoal, &bus_);
    watcher_->lcm().subscribe(std::string(channels::MISSION_STATUS), &Bus::OnMission, &bus_);
  }
  pid_t Start(const std::string& mission_yaml, const std::string& options_yaml = "") {
    WriteText(dir_ + "/mission.yaml", mission_yaml);
    WriteText(dir_ + "/options.yaml", options_yaml.empty() ? "{}\n" : options_yaml);
    return Spawn({BinDir() + "/topay-mission", "--mission", dir_ + "/mission.yaml", "--config",
                  dir_ + "/options.yaml", "--lcm-url", kLcmUrl},
                 dir_ + "/out.txt");
  }
  // Plays robot and planner every 0.1 s (the planner IDLE, or FAILED for every goal if
  // `fail_goals`) until `pid` exits or timeout_s; returns its wait status (-1: timeout).
  int Play(pid_t pid, double timeout_s, bool fail_goals, double sigint_after_s = -1.0) {
    msgs::RobotStateEstimate robot;
    robot.state = BentArmState(0, 0, 0);
    robot.qdot_radps = Eigen::VectorXd::Zero(7);
    const Clock::time_point start = Clock::now();
    bool signalled = false;
    while (SecondsSince(start) < timeout_s) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        watcher_->Spin(0.2);
        return status;
      }
      robot.utime = procs::NowUtime();
      const robot_state_t state = msgs::ToMessage(robot);
      watcher_->lcm().publish(std::string(channels::ROBOT_STATE), &state);
      planner_status_t planner{};
      planner.utime = procs::NowUtime();
      planner.state = planner_status_t::IDLE;
      if (fail_goals && !bus_.goals.empty()) {
        planner.state = planner_status_t::FAILED;
        planner.goal_id = bus_.goals.back().goal_id;
        planner.failure_reason = "no route (test)";
      }
      watcher_->lcm().publish(std::string(channels::PLANNER_STATUS), &planner);
      if (sigint_after_s >= 0.0 && !signalled && SecondsSince(start) > sigint_after_s) {
        kill(pid, SIGINT);
        signalled = true;
      }
      watcher_->Spin(0.1);
    }
    kill(pid, SIGKILL);
    WaitFor(pid, 3.0);
    return -1;
  }
  std::string Output() const { return ReadText(dir_ + "/out.txt"); }

  std::string dir_;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  Bus bus_;
};

TEST_F(MissionProcess, UsageAndFileErrorsHaveTheirExitCodes) {
  const pid_t usage = Spawn({BinDir() + "/topay-mission", "--lcm-url", kLcmUrl}, dir_ + "/usage.txt");
  const int usage_status = WaitFor(usage, 10.0);
  ASSERT_TRUE(WIFEXITED(usage_status));
  EXPECT_EQ(WEXITSTATUS(usage_status), 2) << ReadText(dir_ + "/usage.txt");

  const int status = WaitFor(Start("name: m\nsteps:\n  - {type: wait, duration_s: 1}\n  - {type: jump}\n"), 10.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(Output().find("mission.yaml: steps[1].type: unknown step type 'jump'"), std::string::npos) << Output();
}

TEST_F(MissionProcess, AShortMissionSucceedsWithExitCodeZero) {
  const int status = Play(Start("name: short\nsteps:\n  - {type: wait, duration_s: 0.5}\n"
                                "  - {type: gripper, action: close, settle_s: 0.2}\n"),
                          15.0, false);
  ASSERT_NE(status, -1) << Output();
  ASSERT_TRUE(WIFEXITED(status)) << Output();
  EXPECT_EQ(WEXITSTATUS(status), 0) << Output();
  ASSERT_FALSE(bus_.statuses.empty());
  EXPECT_EQ(bus_.statuses.back().state, mission_status_t::SUCCEEDED);
  EXPECT_EQ(bus_.statuses.back().mission, "short");
  EXPECT_NE(Output().find("mission 'short' SUCCEEDED"), std::string::npos) << Output();
}

TEST_F(MissionProcess, PlansThatKeepFailingFailTheMissionWithExitCodeThree) {
  const int status = Play(Start("name: unreachable\nsteps:\n  - {type: goto, position_m: [50, 0, 0.5], rpy_rad: [0, 0, 0]}\n",
                                "max_attempts: 2\nretry_delay_s: 0.1\n"),
                          20.0, true);
  ASSERT_NE(status, -1) << Output();
  ASSERT_TRUE(WIFEXITED(status)) << Output();
  EXPECT_EQ(WEXITSTATUS(status), 3) << Output();
  ASSERT_EQ(bus_.goals.size(), 2u) << "one retry with a new goal id";
  EXPECT_NE(bus_.goals[0].goal_id, bus_.goals[1].goal_id);
  ASSERT_FALSE(bus_.statuses.empty());
  EXPECT_EQ(bus_.statuses.back().state, mission_status_t::FAILED);
  EXPECT_NE(bus_.statuses.back().detail.find("no route (test)"), std::string::npos) << bus_.statuses.back().detail;
}

TEST_F(MissionProcess, SigintAbortsWithExitCodeFour) {
  const int status = Play(Start("name: long\nsteps:\n  - {type: wait, duration_s: 60}\n"), 15.0, false, 1.5);
  ASSERT_NE(status, -1) << Output();
  ASSERT_TRUE(WIFEXITED(status)) << Output();
  EXPECT_EQ(WEXITSTATUS(status), 4) << Output();
  ASSERT_FALSE(bus_.statuses.empty());
  EXPECT_EQ(bus_.statuses.back().state, mission_status_t::ABORTED);
  EXPECT_NE(Output().find("ABORTED"), std::string::npos) << Output();
}

}  // namespace
}  // namespace topay::test
