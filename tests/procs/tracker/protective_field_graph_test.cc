// The protective field through real processes (finding 30), in a private network namespace
// (skipped, with the reason, where none can be made): topay-sim (its plant driven by
// CONTROL_COMMAND, its LiDAR on) and topay-tracker, and no mapper and no planner: nothing that
// maps. The test plays the planner with one straight trajectory (2.5 m in 6 s) and, once the
// robot drives at over 0.6 m/s, makes a box appear on the path 1.6 m ahead. With the field the
// tracker brakes the robot short of it (the collision monitor sees no contact); with the field
// turned off the same run drives into it (the test of the test).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "graph_test_support.h"
#include "tests/common/real_time_skip.h"
#include "tracker_test_trajectory.h"
#include "topay/robot_state_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::test {
namespace {

struct Seen {
  std::optional<robot_state_t> state;
  std::optional<sim_status_t> sim;
  bool held = false;
  void OnState(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { state = *m; }
  void OnSim(const lcm::ReceiveBuffer*, const std::string&, const sim_status_t* m) { sim = *m; }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const tracker_status_t* m) {
    held = held || m->state == tracker_status_t::HELD;
  }
};

struct BoxRun {
  bool ran = false;
  double speed_at_box_mps = 0.0;
  double gap_m = 0.0;  // box face to the base's outline where the robot ended, along the path
  std::int64_t contacts = -1;
  bool held = false;
  std::string tracker_log;
};

BoxRun RunBoxAhead(bool field_on) {
  BoxRun run;
  const std::string dir = TestDir(field_on ? "field_graph_on" : "field_graph_off");
  const std::string config = std::string(TOPAY_SOURCE_DIR) + "/config";
  WriteText(dir + "/room.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
  WriteText(dir + "/sim.yaml",
            "robot:\n  urdf: " + config + "/robot/topay_mm.urdf\n  yaml: " + config + "/robot/topay_mm.yaml\n");
  const std::string tracker_yaml = field_on ? config + "/tracker/tracker.yaml" : dir + "/tracker.yaml";
  WriteText(dir + "/tracker.yaml", "protective_field:\n  enabled: false\n");
  HeartbeatWatcher watcher;
  EXPECT_TRUE(watcher.good());
  Seen seen;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &Seen::OnState, &seen);
  watcher.lcm().subscribe(std::string(channels::SIM_STATUS), &Seen::OnSim, &seen);
  watcher.lcm().subscribe(std::string(channels::TRACKER_STATUS), &Seen::OnStatus, &seen);
  const std::vector<pid_t> pids = {
      Spawn({BinDir() + "/topay-sim", "--config", dir + "/sim.yaml", "--scene", dir + "/room.json", "--name", "sim"},
            dir + "/sim.txt"),
      Spawn({BinDir() + "/topay-tracker", "--config", tracker_yaml, "--name", "tracker"},
            dir + "/tracker.txt")};
  const bool up = watcher.SpinUntil(
      [&] { return watcher.last.contains("sim") && watcher.last.contains("tracker") && seen.state && seen.sim; }, 15.0);
  EXPECT_TRUE(up) << ReadText(dir + "/sim.txt") << ReadText(dir + "/tracker.txt");
  if (up) {
    const robot_state_t start = *seen.state;
    const Eigen::Vector2d p0(start.pose.x_m, start.pose.y_m);
    const Eigen::Vector2d heading(std::cos(start.pose.yaw_rad), std::sin(start.pose.yaw_rad));
    const Eigen::VectorXd q0 = Eigen::Map<const Eigen::VectorXd>(start.joints.position_rad.data(), 7);
    const ArcYawTrajectory trajectory =
        TrackerTestTrajectory(p0, start.pose.yaw_rad, q0, 2.5, 0.0, Eigen::VectorXd::Zero(7), 3.0);
    const poly_trajectory_t msg = TrackerTestMessage(trajectory, p0, start.utime + 300'000, 21);
    watcher.lcm().publish(std::string(channels::TRAJECTORY), &msg);
    const bool fast = watcher.SpinUntil([&] { return std::abs(seen.state->velocity.v_mps) > 0.6; }, 5.0);
    EXPECT_TRUE(fast) << "the robot never drove at 0.6 m/s";
    run.speed_at_box_mps = std::abs(seen.state->velocity.v_mps);
    const Eigen::Vector2d robot(seen.state->pose.x_m, seen.state->pose.y_m);
    const double along_m = (robot - p0).dot(heading) + 1.6;  // the box centre, along the path
    const Eigen::Vector2d p_box = p0 + along_m * heading;
    const double size_m[3] = {0.4, 0.8, 0.5};
    AppearBoxNow(&watcher.lcm(), 2000, p_box.x(), p_box.y(), size_m, "box ahead, no map");
    watcher.Spin(7.0);  // the rest of the trajectory, the stop and the settle
    const double end_along_m = (Eigen::Vector2d(seen.state->pose.x_m, seen.state->pose.y_m) - p0).dot(heading);
    run.gap_m = (along_m - 0.5 * size_m[0]) - (end_along_m + 0.40);
    run.contacts = seen.sim->contact_events;
    run.held = seen.held;
    run.ran = fast;
  }
  StopProcesses(pids);
  run.tracker_log = ReadText(dir + "/tracker.txt");
  std::printf("field %s: box 1.6 m ahead at %.2f m/s; the robot ended %.3f m short of it (negative: into it), %lld "
              "contact events\n",
              field_on ? "on" : "off", run.speed_at_box_mps, run.gap_m, static_cast<long long>(run.contacts));
  return run;
}

class ProtectiveFieldGraph : public ::testing::Test {
 protected:
  void SetUp() override {
    TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD();
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  }
};

TEST_F(ProtectiveFieldGraph, ABoxAppearingOnThePathWithNoMapIsStoppedShortOf) {
  const BoxRun run = RunBoxAhead(true);
  ASSERT_TRUE(run.ran);
  EXPECT_EQ(run.contacts, 0) << run.tracker_log;
  EXPECT_GT(run.gap_m, 0.0) << run.tracker_log;
  EXPECT_TRUE(run.held) << "TRACKER_STATUS never HELD";
  EXPECT_NE(run.tracker_log.find("protective field entered"), std::string::npos) << run.tracker_log;
}

TEST_F(ProtectiveFieldGraph, WithTheFieldOffTheSameBoxIsHit) {
  const BoxRun run = RunBoxAhead(false);
  ASSERT_TRUE(run.ran);
  EXPECT_GT(run.contacts, 0) << "without the field nothing stops the robot before the box";
  EXPECT_EQ(run.tracker_log.find("protective field entered"), std::string::npos);
}

}  // namespace
}  // namespace topay::test
