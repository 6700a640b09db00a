// The topay-director process: exit codes (a bad script or scene -> 1, usage -> 2, a clean stop
// on SIGINT -> 0, the last in a private network namespace) and its heartbeat's status line.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include "graph_test_support.h"
#include "procs/runtime/process_loop.h"
#include "tests/procs/tracker/tracker_test_trajectory.h"
#include "topay/mission_status_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_event_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.68:7667?ttl=0";

int ExitStatusOf(const std::vector<std::string>& argv, const std::string& out) {
  const pid_t pid = Spawn(argv, out);
  const int status = WaitFor(pid, 20.0);
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class DirectorProcess : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = TestDir("director");
    WriteText(dir_ + "/room.json", "{\"boxes\": []}\n");
    WriteText(dir_ + "/script.yaml", "events:\n  - type: box_on_route\n    during_step: dropoff\n");
  }
  std::string dir_;
};

TEST_F(DirectorProcess, BadConfigOrSceneExitsOne) {
  WriteText(dir_ + "/bad.yaml", "events:\n  - type: box_on_route\n    during_stp: dropoff\n");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--config", dir_ + "/bad.yaml"},
                         dir_ + "/bad.txt"),
            1);
  EXPECT_NE(ReadText(dir_ + "/bad.txt").find("events[0].during_stp"), std::string::npos) << ReadText(dir_ + "/bad.txt");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/missing.json", "--config",
                          dir_ + "/script.yaml"},
                         dir_ + "/scene.txt"),
            1);
}

TEST_F(DirectorProcess, UsageErrorsExitTwo) {
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--config", dir_ + "/script.yaml"}, dir_ + "/u1.txt"), 2);
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--frobnicate"},
                         dir_ + "/u2.txt"),
            2);
}

TEST_F(DirectorProcess, WaitsForItsStepAndStopsCleanly) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  HeartbeatWatcher watcher(kLcmUrl);
  const pid_t pid = Spawn({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--config",
                           dir_ + "/script.yaml", "--name", "director", "--lcm-url", kLcmUrl},
                          dir_ + "/run.txt");
  EXPECT_TRUE(watcher.SpinUntil(
      [&] { return watcher.last.count("director") && watcher.last["director"].status == "waiting for step dropoff"; },
      10.0))
      << ReadText(dir_ + "/run.txt");
  kill(pid, SIGINT);
  const int status = WaitFor(pid, 10.0);
  ASSERT_TRUE(status >= 0 && WIFEXITED(status)) << ReadText(dir_ + "/run.txt");
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Over LCM: the test plays the mission (step dropoff running), the planner (a straight 8 m
// trajectory) and the robot (driving along it at 0.8 m/s); one SIM_EVENT comes, a box 2-3.6 m
// ahead of the robot on the route, and the heartbeat says so.
TEST_F(DirectorProcess, PutsOneBoxOnTheRouteOverLcm) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  WriteText(dir_ + "/room.json",
            "{\"bounds\": {\"min\": [-10, -10, 0], \"max\": [10, 10, 1.6]},\n"
            " \"boxes\": [{\"center\": [5, 8, 0.5], \"size\": [0.5, 0.5, 1], \"yaw\": 0}]}\n");
  HeartbeatWatcher watcher(kLcmUrl);
  struct Events {
    std::vector<sim_event_t> got;
    void On(const lcm::ReceiveBuffer*, const std::string&, const sim_event_t* m) { got.push_back(*m); }
  } events;
  watcher.lcm().subscribe(std::string(channels::SIM_EVENT), &Events::On, &events);
  const pid_t pid = Spawn({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--config",
                           dir_ + "/script.yaml", "--name", "director", "--lcm-url", kLcmUrl},
                          dir_ + "/run.txt");
  const Eigen::Vector2d p0(-4.0, 0.0);
  const ArcYawTrajectory trajectory =
      TrackerTestTrajectory(p0, 0.0, Eigen::VectorXd::Zero(7), 8.0, 0.0, Eigen::VectorXd::Zero(7), 5.0);
  const std::int64_t t0 = procs::NowUtime();
  const poly_trajectory_t trajectory_msg = TrackerTestMessage(trajectory, p0, t0, 7);
  TrajectorySample sample = trajectory.MakePoint();
  double x_robot_m = p0.x();
  const Clock::time_point start = Clock::now();
  while (events.got.empty() && SecondsSince(start) < 6.0) {
    mission_status_t mission{};
    mission.utime = procs::NowUtime();
    mission.state = mission_status_t::RUNNING;
    mission.step = "goto dropoff";
    watcher.lcm().publish(std::string(channels::MISSION_STATUS), &mission);
    watcher.lcm().publish(std::string(channels::TRAJECTORY), &trajectory_msg);
    trajectory.Evaluate(std::min(1e-6 * static_cast<double>(procs::NowUtime() - t0), trajectory.duration_s()), &sample);
    robot_state_t robot{};
    robot.utime = procs::NowUtime();
    robot.pose.x_m = x_robot_m = p0.x() + sample.s_m;
    robot.velocity.v_mps = 0.8;
    watcher.lcm().publish(std::string(channels::ROBOT_STATE), &robot);
    watcher.Spin(0.1);
  }
  watcher.Spin(1.5);  // a second box would come within this
  StopProcesses({pid});
  ASSERT_EQ(events.got.size(), 1u) << ReadText(dir_ + "/run.txt");
  EXPECT_EQ(events.got[0].action, sim_event_t::APPEAR);
  EXPECT_EQ(events.got[0].box_id, 1000);
  EXPECT_GE(events.got[0].center_m[0] - x_robot_m, 1.5);  // the robot drove on meanwhile
  EXPECT_LE(events.got[0].center_m[0] - x_robot_m, 3.6);
  EXPECT_NE(watcher.last["director"].status.find("box 1000 placed at"), std::string::npos)
      << watcher.last["director"].status;
}

}  // namespace
}  // namespace topay::test
