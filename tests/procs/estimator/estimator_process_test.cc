// The topay-estimator process: exit codes (a misspelt key -> 1 naming it, usage -> 2), and the
// real binary in a private network namespace (skipped, with the reason, where none can be
// made) fed by the test's publishers: BASE_VELOCITY at 200 Hz, JOINT_STATE at 100 Hz, BASE_POSE
// at 20 Hz, GRIPPER_STATE at 50 Hz, of a base driving an arc. ROBOT_STATE arrives every 10 ms
// (median interval of its stamps), on the true pose within a few cm, with the latest velocity,
// joints and gripper; when the odometry stops, ROBOT_STATE stops and the heartbeat says why;
// SIGTERM ends it with exit code 0 and its report.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/estimation/se2_motion.h"
#include "estimator_test_messages.h"
#include "graph_test_support.h"
#include "procs/runtime/process_loop.h"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.68:7667?ttl=0";

int ExitStatusOf(const std::vector<std::string>& argv, const std::string& out) {
  const pid_t pid = Spawn(argv, out);
  const int status = WaitFor(pid, 20.0);
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(EstimatorProcess, ConfigAndUsageErrorsExitWithTheirCodes) {
  const std::string dir = TestDir("estimator_errors");
  WriteText(dir + "/typo.yaml", "filter:\n  gate_chi: 9\n");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-estimator", "--config", dir + "/typo.yaml", "--lcm-url", "memq://"},
                         dir + "/typo.txt"),
            1);
  EXPECT_NE(ReadText(dir + "/typo.txt").find("filter.gate_chi"), std::string::npos) << ReadText(dir + "/typo.txt");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-estimator", "--frobnicate"}, dir + "/usage.txt"), 2);
}

struct Received {
  std::vector<robot_state_t> states;
  void On(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { states.push_back(*m); }
};

constexpr double kV = 0.4, kOmega = 0.3;

// Publishes the inputs of a base driving an arc for `seconds` (odometry only if `odometry`),
// handling what arrives in between. *X_WB is the true pose at *utime (the last tick).
void Drive(HeartbeatWatcher* w, double seconds, bool odometry, Eigen::Vector3d* X_WB, std::int64_t* utime) {
  constexpr double kTickS = 0.005;
  const Clock::time_point start = Clock::now();
  std::int64_t last_utime = procs::NowUtime();
  for (int tick = 0; SecondsSince(start) < seconds; ++tick) {
    const std::int64_t now = procs::NowUtime();
    *X_WB = MoveAlongArc(*X_WB, {kV, kOmega, static_cast<double>(now - last_utime) * 1e-6});
    last_utime = *utime = now;
    if (odometry) {
      const base_velocity_t v = VelocityMessage(now, kV, kOmega);
      w->lcm().publish(std::string(channels::BASE_VELOCITY), &v);
    }
    if (tick % 2 == 0) {
      const joint_state_t q = JointMessage(now, 0.25);
      w->lcm().publish(std::string(channels::JOINT_STATE), &q);
    }
    if (tick % 4 == 0) {
      const joint_state_t g = GripperMessage(now, 0.4);
      w->lcm().publish("GRIPPER_STATE", &g);
    }
    if (tick % 10 == 0) {
      const base_pose_t p = PoseMessage(now, X_WB->x(), X_WB->y(), X_WB->z());
      w->lcm().publish(std::string(channels::BASE_POSE), &p);
    }
    const Clock::time_point next = start + std::chrono::microseconds(static_cast<int>((tick + 1) * kTickS * 1e6));
    while (Clock::now() < next) w->lcm().handleTimeout(1);
  }
}

TEST(EstimatorProcess, PublishesRobotStateFromItsInputsAndStopsWhenStale) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("estimator_process");
  const std::string config = std::string(TOPAY_SOURCE_DIR) + "/config/estimator/estimator.yaml";
  const pid_t pid = Spawn({BinDir() + "/topay-estimator", "--config", config, "--name", "estimator", "--lcm-url",
                           kLcmUrl},
                          dir + "/estimator.txt");
  HeartbeatWatcher watcher(kLcmUrl);
  ASSERT_TRUE(watcher.good());
  Received rx;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &Received::On, &rx);
  // The first heartbeat says "starting"; the next ones why nothing is published.
  ASSERT_TRUE(watcher.SpinUntil(
      [&] {
        return watcher.last.contains("estimator") &&
               watcher.last["estimator"].status.find("held (no pose yet)") != std::string::npos;
      },
      15.0))
      << ReadText(dir + "/estimator.txt");
  EXPECT_EQ(rx.states.size(), 0u);  // nothing without inputs

  Eigen::Vector3d X_WB(1.0, -2.0, 0.5);
  std::int64_t truth_utime = 0;
  Drive(&watcher, 3.0, true, &X_WB, &truth_utime);
  const std::int64_t end_utime = procs::NowUtime();
  ASSERT_GT(rx.states.size(), 50u) << ReadText(dir + "/estimator.txt");
  std::vector<std::int64_t> intervals;
  for (std::size_t k = 1; k < rx.states.size(); ++k) intervals.push_back(rx.states[k].utime - rx.states[k - 1].utime);
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  const std::int64_t median_us = intervals[intervals.size() / 2];
  const robot_state_t& last = rx.states.back();
  // The truth at the state's time (the exact arc run back or on from the last tick).
  const Eigen::Vector3d truth =
      MoveAlongArc(X_WB, {kV, kOmega, static_cast<double>(last.utime - truth_utime) * 1e-6});
  std::printf("%zu ROBOT_STATE in ~3 s, median interval %.2f ms; last: (%.4f, %.4f, %.4f), truth (%.4f, %.4f, %.4f)\n",
              rx.states.size(), median_us * 1e-3, last.pose.x_m, last.pose.y_m, last.pose.yaw_rad, truth.x(),
              truth.y(), truth.z());
  EXPECT_GE(median_us, 8'000);  // the 100 Hz timer
  EXPECT_LE(median_us, 12'000);
  // Content: on the arc, and recent.
  EXPECT_LT(std::hypot(last.pose.x_m - truth.x(), last.pose.y_m - truth.y()), 0.03);
  EXPECT_LT(std::abs(std::remainder(last.pose.yaw_rad - truth.z(), 2 * M_PI)), 0.03);
  EXPECT_LE(end_utime - last.utime, 100'000);
  EXPECT_EQ(last.pose.utime, last.utime);
  EXPECT_DOUBLE_EQ(last.velocity.v_mps, 0.4);
  EXPECT_DOUBLE_EQ(last.velocity.omega_radps, 0.3);
  ASSERT_EQ(last.joints.num_joints, 7);
  EXPECT_DOUBLE_EQ(last.joints.position_rad[0], 0.25);
  EXPECT_DOUBLE_EQ(last.joints.position_rad[6], 0.25 + 0.6);
  EXPECT_DOUBLE_EQ(last.gripper, 0.4);

  // The odometry stops (pose, joints and gripper go on): within the timeout (0.1 s) and a cycle
  // ROBOT_STATE stops, and stays stopped.
  Drive(&watcher, 0.4, false, &X_WB, &truth_utime);
  const std::size_t after_stop = rx.states.size();
  Drive(&watcher, 1.2, false, &X_WB, &truth_utime);  // includes a heartbeat
  EXPECT_EQ(rx.states.size(), after_stop);
  EXPECT_NE(watcher.last["estimator"].status.find("held (odometry stale)"), std::string::npos)
      << watcher.last["estimator"].status;

  kill(pid, SIGTERM);
  const int status = WaitFor(pid, 5.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  const std::string out = ReadText(dir + "/estimator.txt");
  EXPECT_NE(out.find("ROBOT_STATE published"), std::string::npos) << out;
  EXPECT_NE(out.find("odometry stale"), std::string::npos) << out;
  std::printf("%s", out.c_str());
}

}  // namespace
}  // namespace topay::test
