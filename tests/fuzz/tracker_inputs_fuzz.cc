// topay-tracker's subscriptions (TRAJECTORY, ROBOT_STATE, GRIPPER_COMMAND, DRIVE_STATUS,
// HEARTBEAT, POINT_CLOUD for the protective field) and its 50 Hz NMPC step, on the shipped
// options and robot (the field on), with the node's own handlers (TrackerNode) and a clock the
// input advances. Checked on every CONTROL_COMMAND it would send: finite, and within
// the robot's velocity limits (|v| <= v_max, |omega| <= omega_max, |qdot_i| <= qd_max_i).
// Input: subscriber_fuzz.h, 6 channels; at most 64 steps per input (each may solve).
#include <cmath>
#include <cstdint>

#include "core/control/tracker_limits.h"
#include "procs/tracker/tracker_node.h"
#include "procs/tracker/tracker_options.h"
#include "tests/fuzz/subscriber_fuzz.h"

namespace {

void CheckCommand(const topay::control_command_t& cmd, const topay::TrackerLimits& limits) {
  constexpr double kSlack = 1e-9;
  FuzzCheck(std::isfinite(cmd.v_mps) && std::isfinite(cmd.omega_radps), "base command finite");
  FuzzCheck(std::abs(cmd.v_mps) <= limits.base.v_max_mps * (1 + kSlack), "|v| within v_max");
  FuzzCheck(std::abs(cmd.omega_radps) <= limits.base.omega_max_radps * (1 + kSlack), "|omega| within omega_max");
  FuzzCheck(cmd.num_joints == static_cast<int>(cmd.qdot_radps.size()), "joint count matches");
  for (int j = 0; j < cmd.num_joints && j < limits.num_joints(); ++j) {
    const double qdot = cmd.qdot_radps[static_cast<std::size_t>(j)];
    FuzzCheck(std::isfinite(qdot) && std::abs(qdot) <= limits.qd_max_radps[j] * (1 + kSlack), "|qdot| within limit");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const tracker::TrackerOptions options = tracker::LoadTrackerOptions(ShippedConfig("tracker/tracker.yaml"));
  static const TrackerLimits limits = MakeTrackerLimits(ShippedRobotModel());
  tracker::TrackerNode node(options, ShippedRobotModel());
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  int steps = 0;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 6);
    if (!op) break;
    if (op->tick) {
      if (++steps > 64) break;
      now += op->advance_us;
      CheckCommand(node.Step(now).command, limits);
      continue;
    }
    switch (op->channel) {
      case 0:
        if (auto m = DecodeFuzzed<poly_trajectory_t>(op->bytes, op->fix_fingerprint)) node.OnTrajectory(*m, now);
        break;
      case 1:
        if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) node.OnRobotState(*m);
        break;
      case 2:
        if (auto m = DecodeFuzzed<gripper_command_t>(op->bytes, op->fix_fingerprint)) node.OnGripper(*m);
        break;
      case 3:
        if (auto m = DecodeFuzzed<drive_status_t>(op->bytes, op->fix_fingerprint)) node.OnDriveStatus(*m);
        break;
      case 4:
        if (auto m = DecodeFuzzed<heartbeat_t>(op->bytes, op->fix_fingerprint)) node.OnHeartbeat(*m, now);
        break;
      default:
        if (auto m = DecodeFuzzed<point_cloud_t>(op->bytes, op->fix_fingerprint)) node.OnPointCloud(*m);
        break;
    }
  }
  node.StatusLine();
  node.Report();
  return 0;
}
