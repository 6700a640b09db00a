// topay-estimator's subscriptions (BASE_POSE, BASE_VELOCITY, JOINT_STATE, GRIPPER_STATE) and
// its 100 Hz step, on the shipped options, with the node's own handlers (EstimatorNode) and a
// clock the input advances. Checked: every ROBOT_STATE it would publish is a valid state
// (msgs::FromMessage accepts it: finite pose, velocity and joints, consistent arrays).
// Input: subscriber_fuzz.h, 4 channels.
#include <cstdint>
#include <string>

#include "procs/estimator/estimator_config.h"
#include "procs/estimator/estimator_node.h"
#include "procs/msgs/convert_robot_state.h"
#include "tests/fuzz/subscriber_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const estimator::EstimatorProcessOptions options =
      estimator::LoadEstimatorProcessOptions(ShippedConfig("estimator/estimator.yaml"));
  estimator::EstimatorNode node(options);
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 4);
    if (!op) break;
    if (op->tick) {
      now += op->advance_us;
      if (const robot_state_t* state = node.Step(now)) {
        std::string error;
        FuzzCheck(msgs::FromMessage(*state, &error).has_value(), "the estimator publishes only valid states");
      }
      continue;
    }
    switch (op->channel) {
      case 0:
        if (auto m = DecodeFuzzed<base_pose_t>(op->bytes, op->fix_fingerprint)) node.OnPose(*m, now);
        break;
      case 1:
        if (auto m = DecodeFuzzed<base_velocity_t>(op->bytes, op->fix_fingerprint)) node.OnVelocity(*m, now);
        break;
      case 2:
        if (auto m = DecodeFuzzed<joint_state_t>(op->bytes, op->fix_fingerprint)) node.OnJoints(*m, now);
        break;
      default:
        if (auto m = DecodeFuzzed<joint_state_t>(op->bytes, op->fix_fingerprint)) node.OnGripper(*m, now);
        break;
    }
  }
  node.StatusLine(now);
  node.Report();
  return 0;
}
