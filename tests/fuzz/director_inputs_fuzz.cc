// topay-director's subscriptions (MISSION_STATUS, TRAJECTORY, ROBOT_STATE) and its tick, with
// the shipped pick-and-place script in a small room (DirectorNode's own handlers, a clock the
// input advances). Checked: every SIM_EVENT it publishes places a box of finite, positive size
// at a finite pose.
// Input: subscriber_fuzz.h, 3 channels.
#include <cmath>
#include <cstdint>

#include "core/robot/kinematics.h"
#include "procs/director/director_node.h"
#include "procs/director/director_options.h"
#include "tests/fuzz/subscriber_fuzz.h"

namespace {

topay::Scene SmallRoom() {
  topay::Scene room;
  room.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6));
  topay::OrientedBox far;
  far.center_W_m = Eigen::Vector3d(5, 8, 0.5);
  far.size_m = Eigen::Vector3d(0.5, 0.5, 1);
  room.boxes.push_back(far);
  return room;
}

void CheckEvent(const topay::sim_event_t& event) {
  if (!event.has_box) return;
  for (double v : event.center_m) FuzzCheck(std::isfinite(v), "event box centre finite");
  FuzzCheck(std::isfinite(event.yaw_rad), "event box yaw finite");
  for (double s : event.size_m) FuzzCheck(std::isfinite(s) && s > 0, "event box size finite and positive");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const Kinematics kinematics(ShippedRobotModel());
  static const director::DirectorOptions options =
      director::LoadDirectorOptions(ShippedConfig("director/pick_place.yaml"));
  director::DirectorOutputs outputs;
  outputs.event = CheckEvent;
  director::DirectorNode node(options, SmallRoom(), kinematics, outputs);
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 3);
    if (!op) break;
    if (op->tick) {
      now += op->advance_us;
      node.Tick(now);
      node.WaitForPlacement();  // deterministic: an attempt's result is taken by the next tick
      continue;
    }
    switch (op->channel) {
      case 0:
        if (auto m = DecodeFuzzed<mission_status_t>(op->bytes, op->fix_fingerprint)) node.OnMissionStatus(*m);
        break;
      case 1:
        if (auto m = DecodeFuzzed<poly_trajectory_t>(op->bytes, op->fix_fingerprint)) node.OnTrajectory(*m);
        break;
      default:
        if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) node.OnRobotState(*m);
        break;
    }
  }
  return 0;
}
