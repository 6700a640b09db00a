// topay-mission's subscriptions (ROBOT_STATE, PLANNER_STATUS, TRACKER_STATUS) and its 20 Hz
// tick, running the shipped pick-and-place mission with the shipped options (MissionNode's own
// handlers, a clock the input advances). Checked: every GOAL it sends is one the planner can
// read (msgs::FromMessage accepts it), every gripper command is finite.
// Input: subscriber_fuzz.h, 3 channels.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/robot/kinematics.h"
#include "procs/mission/mission_node.h"
#include "procs/mission/mission_options.h"
#include "procs/mission/mission_spec.h"
#include "procs/msgs/convert_goal.h"
#include "tests/fuzz/subscriber_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const Kinematics kinematics(ShippedRobotModel());
  static const mission::Mission shipped_mission = mission::LoadMission(ShippedConfig("missions/pick_and_place.yaml"));
  static const mission::MissionOptions options = mission::LoadMissionOptions(ShippedConfig("mission/mission.yaml"));
  mission::MissionOutputs outputs;
  outputs.goal = [](const goal_t& goal) {
    std::string error;
    FuzzCheck(msgs::FromMessage(goal, &error).has_value(), "the mission sends only readable goals");
  };
  outputs.gripper = [](const gripper_command_t& cmd) { FuzzCheck(std::isfinite(cmd.position), "gripper finite"); };
  mission::MissionNode node(shipped_mission, kinematics, options, outputs, 100);
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 3);
    if (!op) break;
    if (op->tick) {
      now += op->advance_us;
      node.Tick(now);
      continue;
    }
    switch (op->channel) {
      case 0:
        if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) node.OnRobotState(*m, now);
        break;
      case 1:
        if (auto m = DecodeFuzzed<planner_status_t>(op->bytes, op->fix_fingerprint)) node.OnPlannerStatus(*m, now);
        break;
      default:
        if (auto m = DecodeFuzzed<tracker_status_t>(op->bytes, op->fix_fingerprint)) node.OnTrackerStatus(*m, now);
        break;
    }
  }
  node.Abort("end of input", now);
  node.StatusLine();
  node.Summary();
  return 0;
}
