// The closed loop through CAN, as on the robot, with real processes over real LCM and the
// user-space UDP CAN bus in a private network namespace (skipped, with the reason, where none
// can be made): topay-tracker -> CONTROL_COMMAND -> topay-canbridge -> CAN -> topay-motorsim ->
// ACTUATOR_COMMAND -> topay-sim's plant (CAN mode), and back: wheel speeds and drive feedback
// over CAN -> the bridge's BASE_VELOCITY and JOINT_STATE -> topay-estimator (with the sim's
// BASE_POSE) -> ROBOT_STATE -> the tracker. The test plays the planner (one short whole-body
// trajectory), the operator (a fault reset) and the fault injector (MOTORSIM_FAULT):
//   1. the trajectory is followed: the plant's TRUE final state (SIM_PLANT_STATE) is within a few
//      cm / hundredths of a radian of its end, the estimate within a cm of the truth, no contact;
//   2. with 10 % of the frames to the drives lost, a second trajectory is still completed;
//   3. a drive fault stops the robot (DRIVE_STATUS FAULT naming the drive), a FAULT_RESET on
//      DRIVE_COMMAND brings it back to RUNNING;
//   4. the command stream stops (the tracker is frozen with SIGSTOP): the bridge stops the robot
//      (STOPPED, stale command) and recovers by itself once commands (zero) come again; the
//      time from the last command to the stop frames on the bus is printed (from can.log).
// The 100 ms stop deadlines are asserted on the bridge's simulated clock (canbridge_node_test);
// this test checks the reactions through the real processes.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <optional>
#include <memory>

#include "tests/common/real_time_skip.h"
#include "core/common/angles.h"
#include "drivers/can/candump_log.h"
#include "procs/runtime/process_loop.h"
#include "tests/procs/graph_test_support.h"
#include "tests/procs/tracker/tracker_test_trajectory.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kCanUrl = "udp://239.255.1.1:9000";

struct Received {
  std::vector<robot_state_t> estimates;  // ROBOT_STATE (topay-estimator)
  std::vector<robot_state_t> truths;     // SIM_PLANT_STATE (the plant)
  std::vector<tracker_status_t> statuses;
  std::vector<sim_status_t> sims;
  std::vector<drive_status_t> drives;
  void OnEstimate(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { estimates.push_back(*m); }
  void OnTruth(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { truths.push_back(*m); }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const tracker_status_t* m) { statuses.push_back(*m); }
  void OnSim(const lcm::ReceiveBuffer*, const std::string&, const sim_status_t* m) { sims.push_back(*m); }
  void OnDrive(const lcm::ReceiveBuffer*, const std::string&, const drive_status_t* m) { drives.push_back(*m); }
};

Eigen::VectorXd Joints(const robot_state_t& s) {
  return Eigen::Map<const Eigen::VectorXd>(s.joints.position_rad.data(), s.joints.num_joints);
}

// The graph of the test: its processes and what they published.
class CanLoopGraph : public ::testing::Test {
 protected:
  void StartGraph() {
    dir_ = TestDir("can_loop");
    WriteText(dir_ + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
    const std::string config = std::string(TOPAY_SOURCE_DIR) + "/config";
    // The shipped plant and robot; no LiDAR (nothing to see; it would take a core from the loop).
    WriteText(dir_ + "/sim.yaml", "robot:\n  urdf: " + config + "/robot/topay_mm.urdf\n  yaml: " + config +
                                      "/robot/topay_mm.yaml\nlidar:\n  enabled: false\n");
    pids_.push_back(Spawn({BinDir() + "/topay-sim", "--config", dir_ + "/sim.yaml", "--scene", dir_ + "/empty.json",
                           "--plant-input", "actuators", "--name", "sim"},
                          dir_ + "/sim.txt"));
    pids_.push_back(Spawn({BinDir() + "/topay-motorsim", "--config", config + "/sim/motorsim.yaml", "--can", kCanUrl,
                           "--name", "motorsim"},
                          dir_ + "/motorsim.txt"));
    pids_.push_back(Spawn({BinDir() + "/topay-canbridge", "--config", config + "/canbridge/canbridge.yaml", "--can",
                           kCanUrl, "--record", dir_ + "/can.log", "--name", "canbridge"},
                          dir_ + "/canbridge.txt"));
    pids_.push_back(Spawn({BinDir() + "/topay-estimator", "--config", config + "/estimator/estimator.yaml", "--name",
                           "estimator"},
                          dir_ + "/estimator.txt"));
    tracker_ = Spawn({BinDir() + "/topay-tracker", "--config", config + "/tracker/tracker.yaml", "--name", "tracker"},
                     dir_ + "/tracker.txt");
    pids_.push_back(tracker_);
    watcher_ = std::make_unique<HeartbeatWatcher>();
    lcm::LCM& lcm = watcher_->lcm();
    lcm.subscribe(std::string(channels::ROBOT_STATE), &Received::OnEstimate, &rx_);
    lcm.subscribe(std::string(channels::SIM_PLANT_STATE), &Received::OnTruth, &rx_);
    lcm.subscribe(std::string(channels::TRACKER_STATUS), &Received::OnStatus, &rx_);
    lcm.subscribe(std::string(channels::SIM_STATUS), &Received::OnSim, &rx_);
    lcm.subscribe(std::string(channels::DRIVE_STATUS), &Received::OnDrive, &rx_);
    lcm.subscribe(std::string(channels::CONTROL_COMMAND), &CanLoopGraph::OnCommand, this);
  }

  std::string Logs() const {
    std::string out;
    for (const char* name : {"sim", "motorsim", "canbridge", "estimator", "tracker"}) {
      out += std::string("---- ") + name + "\n" + ReadText(dir_ + "/" + name + ".txt");
    }
    return out;
  }

  bool BridgeIs(std::int8_t state) const { return !rx_.drives.empty() && rx_.drives.back().state == state; }

  // Publishes a trajectory from the latest estimate (joints + `joint_change`), 0.3 s ahead, and
  // spins past its end; the trajectory.
  ArcYawTrajectory FollowTrajectory(std::int64_t id, double arc_m, double turn_rad, const Eigen::VectorXd& joint_change) {
    const robot_state_t now = rx_.estimates.back();
    const Eigen::Vector2d p0(now.pose.x_m, now.pose.y_m);
    ArcYawTrajectory trajectory = TrackerTestTrajectory(p0, now.pose.yaw_rad, Joints(now), arc_m, turn_rad, joint_change);
    const poly_trajectory_t msg = TrackerTestMessage(trajectory, p0, now.utime + 300'000, id);
    watcher_->lcm().publish(std::string(channels::TRAJECTORY), &msg);
    rx_.statuses.clear();
    watcher_->Spin(trajectory.duration_s() + 0.3 + 1.5);
    return trajectory;
  }

  // The plant's true final state against the trajectory's end, and the estimate against the truth.
  void ExpectAtTheEnd(const ArcYawTrajectory& trajectory, std::int64_t id, const char* what) {
    TrajectorySample end = trajectory.MakePoint();
    trajectory.Evaluate(trajectory.duration_s(), &end);
    ASSERT_FALSE(rx_.truths.empty() || rx_.estimates.empty()) << what;
    const robot_state_t& truth = rx_.truths.back();
    const robot_state_t& estimate = rx_.estimates.back();
    const double position_error = std::hypot(truth.pose.x_m - end.state.x_m, truth.pose.y_m - end.state.y_m);
    const double yaw_error = std::abs(WrapAngle(truth.pose.yaw_rad - end.state.yaw_rad));
    const double joint_error = (Joints(truth) - end.state.q_rad).cwiseAbs().maxCoeff();
    const double estimate_error = std::hypot(estimate.pose.x_m - truth.pose.x_m, estimate.pose.y_m - truth.pose.y_m);
    std::printf("%s: true final error %.4f m, %.4f rad yaw, %.4f rad joints; estimate - truth %.4f m\n", what,
                position_error, yaw_error, joint_error, estimate_error);
    EXPECT_LT(position_error, 0.03) << what;
    EXPECT_LT(yaw_error, 0.03) << what;
    EXPECT_LT(joint_error, 0.02) << what;
    EXPECT_LT(estimate_error, 0.01) << what;  // the robot is at rest: the estimate is the pose
    ASSERT_FALSE(rx_.statuses.empty()) << what;
    EXPECT_EQ(rx_.statuses.back().state, tracker_status_t::FINISHED) << what;
    EXPECT_EQ(rx_.statuses.back().trajectory_id, id) << what;
  }

  void OnCommand(const lcm::ReceiveBuffer*, const std::string&, const control_command_t*) {
    command_utimes_.push_back(procs::NowUtime());
  }

  std::int64_t LastCommandBefore(std::int64_t utime) const {
    std::int64_t last = 0;
    for (std::int64_t u : command_utimes_) last = u <= utime ? std::max(last, u) : last;
    return last;
  }

  // Seconds from `utime` (us since the epoch) to the first RPDO1 of a drive (0x201-0x207) whose
  // controlword is 0x0002 or 0x0000 in the candump log, or nullopt.
  static std::optional<double> FirstStopFrameAfter(const std::string& log, std::int64_t utime) {
    std::ifstream in(log);
    std::vector<can::CandumpRecord> records;
    std::string error;
    if (!can::ReadCandumpLog(in, &records, &error)) return std::nullopt;
    for (const can::CandumpRecord& r : records) {
      if (r.timestamp_us <= utime || r.frame.extended || r.frame.id < 0x201 || r.frame.id > 0x207) continue;
      const int controlword = r.frame.data[0] | (r.frame.data[1] << 8);
      if (controlword == 0x0002 || controlword == 0x0000) return 1e-6 * static_cast<double>(r.timestamp_us - utime);
    }
    return std::nullopt;
  }

  void InjectFault(std::int8_t kind, int joint, double value) {
    motorsim_fault_t fault{};
    fault.kind = kind;
    fault.joint = joint;
    fault.value = value;
    watcher_->lcm().publish(std::string(channels::MOTORSIM_FAULT), &fault);
  }

  // Stops every process (SIGTERM) and expects a clean exit of each.
  void StopGraph() {
    if (tracker_ > 0) kill(tracker_, SIGCONT);
    for (pid_t pid : pids_) kill(pid, SIGTERM);
    for (pid_t pid : pids_) {
      const int status = WaitFor(pid, 5.0);
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "pid " << pid << "\n" << Logs();
    }
    pids_.clear();
  }

  void TearDown() override { StopGraph(); }

  std::string dir_;
  std::vector<pid_t> pids_;
  pid_t tracker_ = -1;
  std::unique_ptr<HeartbeatWatcher> watcher_;  // made after the test entered its namespace
  Received rx_;
  std::vector<std::int64_t> command_utimes_;  // receipt times of CONTROL_COMMAND, us
};

TEST_F(CanLoopGraph, TheTrackerDrivesThePlantThroughCanFaultsStopItAndItRecovers) {
  TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD();
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  StartGraph();
  ASSERT_TRUE(watcher_->good());
  ASSERT_TRUE(watcher_->SpinUntil(
      [&] {
        return BridgeIs(drive_status_t::RUNNING) && rx_.estimates.size() > 10 && !rx_.statuses.empty() &&
               !rx_.truths.empty();
      },
      20.0))
      << Logs();

  // 1. A trajectory through CAN.
  Eigen::VectorXd change = Eigen::VectorXd::Constant(7, 0.3);
  change[0] = 0.15;
  const ArcYawTrajectory first = FollowTrajectory(11, 1.0, 0.5, change);
  ExpectAtTheEnd(first, 11, "through CAN");
  const drive_status_t running = rx_.drives.back();
  EXPECT_EQ(running.state, drive_status_t::RUNNING) << running.stop_reason;
  EXPECT_GT(running.bus_load_percent, 10.0);  // base + 7 drives at 200 Hz
  EXPECT_LT(running.bus_load_percent, 50.0);
  std::printf("bus load %.1f %%, command -> frame p99 %.3f ms, cycle jitter p99 %.3f ms\n", running.bus_load_percent,
              running.command_latency_p99_ms, running.cycle_jitter_p99_ms);

  // 2. 10 % of the frames to the nodes lost: the motion is still completed.
  InjectFault(motorsim_fault_t::RX_LOSS, 0, 10.0);
  const ArcYawTrajectory second = FollowTrajectory(12, 0.5, -0.3, -0.5 * change);
  ExpectAtTheEnd(second, 12, "10 % frame loss");
  InjectFault(motorsim_fault_t::CLEAR, 0, 0.0);

  // 3. A drive fault: FAULT naming the drive, then an operator's reset.
  InjectFault(motorsim_fault_t::DRIVE_FAULT, 3, 0.0);
  ASSERT_TRUE(watcher_->SpinUntil([&] { return BridgeIs(drive_status_t::FAULT); }, 2.0)) << Logs();
  EXPECT_NE(rx_.drives.back().stop_reason.find("joint3"), std::string::npos) << rx_.drives.back().stop_reason;
  drive_command_t reset{};
  reset.command = drive_command_t::FAULT_RESET;
  reset.source = "can_loop_graph_test";
  watcher_->lcm().publish(std::string(channels::DRIVE_COMMAND), &reset);
  ASSERT_TRUE(watcher_->SpinUntil([&] { return BridgeIs(drive_status_t::RUNNING); }, 5.0)) << Logs();

  // 4. The command stream stops: STOPPED (stale command), then RUNNING again by itself.
  const std::int64_t freeze_utime = procs::NowUtime();
  kill(tracker_, SIGSTOP);
  ASSERT_TRUE(watcher_->SpinUntil([&] { return BridgeIs(drive_status_t::STOPPED); }, 2.0)) << Logs();
  EXPECT_NE(rx_.drives.back().stop_reason.find("stale"), std::string::npos) << rx_.drives.back().stop_reason;
  kill(tracker_, SIGCONT);
  ASSERT_TRUE(watcher_->SpinUntil([&] { return BridgeIs(drive_status_t::RUNNING); }, 5.0)) << Logs();

  ASSERT_FALSE(rx_.sims.empty());
  EXPECT_EQ(rx_.sims.back().contact_events, 0);

  // The stale-command stop in the real processes: from the last CONTROL_COMMAND this test saw
  // before the freeze to the bridge's first stop controlword (quick stop 0x0002 or disable
  // voltage 0x0000 in a drive's RPDO1) in its recorded candump log. A figure (the 100 ms
  // deadline is asserted on the bridge's simulated clock, canbridge_node_test); here it must
  // only be prompt.
  const std::int64_t last_command_utime = LastCommandBefore(freeze_utime);
  ASSERT_GT(last_command_utime, 0) << "no CONTROL_COMMAND seen before the freeze";
  StopGraph();
  const std::optional<double> stop_s = FirstStopFrameAfter(dir_ + "/can.log", last_command_utime);
  ASSERT_TRUE(stop_s.has_value()) << "no stop controlword in can.log after the last command";
  std::printf("command stream lost: stop frames %.1f ms after the last CONTROL_COMMAND\n", *stop_s * 1e3);
  EXPECT_GT(*stop_s, 0.05);  // not before the timeout (0.1 s, one 5 ms cycle early)
  EXPECT_LT(*stop_s, 0.2);
}

}  // namespace
}  // namespace topay::test
