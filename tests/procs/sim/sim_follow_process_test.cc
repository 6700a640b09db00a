// topay-sim --follow as a real process over real LCM in a private network namespace (skipped,
// with the reason, where none can be made): a trajectory published on TRAJECTORY from the
// robot's current state is followed exactly (every ROBOT_STATE equals the trajectory at its
// utime, velocities included), the robot holds before its start and at its end; a corrupted
// trajectory and a far one are rejected and logged, CONTROL_COMMAND is ignored and counted.

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/angles.h"
#include "follow_test_trajectory.h"
#include "graph_test_support.h"
#include "topay/control_command_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

struct States {
  std::vector<robot_state_t> list;
  void On(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { list.push_back(*m); }
};

Eigen::VectorXd Joints(const robot_state_t& s) {
  return Eigen::Map<const Eigen::VectorXd>(s.joints.position_rad.data(), s.joints.num_joints);
}
Eigen::VectorXd JointRates(const robot_state_t& s) {
  return Eigen::Map<const Eigen::VectorXd>(s.joints.velocity_radps.data(), s.joints.num_joints);
}

// Expects `s` equal to `point` (pose, joints) and, if `moving`, to its velocities, else at rest.
void ExpectStateIs(const robot_state_t& s, const TrajectorySample& point, bool moving) {
  SCOPED_TRACE(s.utime);
  EXPECT_NEAR(s.pose.x_m, point.state.x_m, 1e-9);
  EXPECT_NEAR(s.pose.y_m, point.state.y_m, 1e-9);
  EXPECT_NEAR(WrapAngle(s.pose.yaw_rad - point.state.yaw_rad), 0.0, 1e-9);
  EXPECT_LE((Joints(s) - point.state.q_rad).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(s.velocity.v_mps, moving ? point.v_mps : 0.0, 1e-9);
  EXPECT_NEAR(s.velocity.omega_radps, moving ? point.omega_radps : 0.0, 1e-9);
  EXPECT_LE((JointRates(s) - (moving ? point.qd_radps : Eigen::VectorXd::Zero(7))).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(SimFollowProcess, FollowsATrajectoryExactlyAndRejectsBadOnes) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("sim_follow");
  WriteText(dir + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
  const pid_t pid = Spawn({BinDir() + "/topay-sim", "--config", std::string(TOPAY_SOURCE_DIR) + "/config/sim/sim.yaml",
                           "--scene", dir + "/empty.json", "--name", "sim-follow", "--follow"},
                          dir + "/out.txt");
  HeartbeatWatcher watcher;
  States states;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &States::On, &states);
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last.contains("sim-follow") && states.list.size() > 10; }, 10.0))
      << ReadText(dir + "/out.txt");

  // The planner's part: a trajectory from the state just received, starting 0.3 s later in the
  // ROBOT_STATE utime base.
  const robot_state_t now = states.list.back();
  const Eigen::Vector2d p0(now.pose.x_m, now.pose.y_m);
  const ArcYawTrajectory trajectory = FollowTestTrajectory(p0, now.pose.yaw_rad, Joints(now));
  const std::int64_t start_utime = now.utime + 300'000;
  const std::int64_t end_utime = start_utime + std::llround(trajectory.duration_s() * 1e6);
  poly_trajectory_t corrupted = FollowTestMessage(trajectory, p0, start_utime, 7);
  corrupted.coeffs[(0 * 9 + 4) * 6 + 5] += 0.1;  // piece 0, joint 3, t^5
  const poly_trajectory_t far = FollowTestMessage(trajectory, p0 + Eigen::Vector2d(1.0, 0.0), start_utime, 8);
  const poly_trajectory_t good = FollowTestMessage(trajectory, p0, start_utime, 9);
  for (const poly_trajectory_t& msg : {corrupted, far, good}) watcher.lcm().publish(std::string(channels::TRAJECTORY), &msg);
  control_command_t reverse{};
  reverse.v_mps = -0.5;
  reverse.num_joints = 7;
  reverse.qdot_radps.assign(7, 0.0);
  states.list.clear();
  const Clock::time_point publishing = Clock::now();
  while (SecondsSince(publishing) < 3.0) {  // past the end (2.3 s)
    watcher.lcm().publish(std::string(channels::CONTROL_COMMAND), &reverse);
    watcher.Spin(0.02);
  }

  TrajectorySample point = trajectory.MakePoint();
  trajectory.Evaluate(0.0, &point);
  int before = 0, during = 0, after = 0;
  for (const robot_state_t& s : states.list) {
    if (s.utime < start_utime) {
      ++before;
      ExpectStateIs(s, point, false);  // held where it was
    } else if (s.utime < end_utime) {
      ++during;
      TrajectorySample at = trajectory.MakePoint();
      trajectory.Evaluate(static_cast<double>(s.utime - start_utime) * 1e-6, &at);
      ExpectStateIs(s, at, true);
    } else {
      ++after;
      TrajectorySample end = trajectory.MakePoint();
      trajectory.Evaluate(trajectory.duration_s(), &end);
      ExpectStateIs(s, end, false);
    }
  }
  EXPECT_GT(before, 10);
  EXPECT_GT(during, 150);  // 100 Hz over 2 s (a few may be lost)
  EXPECT_GT(after, 20);
  ASSERT_FALSE(states.list.empty());
  EXPECT_GT(std::hypot(states.list.back().pose.x_m - p0.x(), states.list.back().pose.y_m - p0.y()), 0.9);

  kill(pid, SIGTERM);
  const int status = WaitFor(pid, 5.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const std::string out = ReadText(dir + "/out.txt");
  EXPECT_NE(out.find("rejected TRAJECTORY 7 (#1): trajectory 7 (goal 1): not a MINCO s = 3 trajectory"), std::string::npos)
      << out;
  EXPECT_NE(out.find("rejected TRAJECTORY 8 (#2): starts 1 m from the robot"), std::string::npos) << out;
  EXPECT_NE(out.find("TRAJECTORY 9 (goal 1) accepted"), std::string::npos) << out;
  EXPECT_NE(out.find("follow: trajectories 1 accepted / 2 rejected / 1 started (following 9)"), std::string::npos)
      << out;
  EXPECT_NE(out.find("commands ignored"), std::string::npos) << out;
  EXPECT_NE(out.find("final: contacts 0 events"), std::string::npos) << out;
}

}  // namespace
}  // namespace topay::test
