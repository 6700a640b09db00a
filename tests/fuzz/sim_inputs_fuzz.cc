// topay-sim's subscriptions (CONTROL_COMMAND, ACTUATOR_COMMAND, GRIPPER_COMMAND, TRAJECTORY,
// SIM_EVENT) with the calls its node makes (SimNode::On*): commands converted
// (ToActuatorCommand) and kept on their stamps' time (CommandTimeline, any stamp) into the
// plant (sim::Plant::Command at the step they are due, CommandGripper), trajectories into
// the follow mode's follower (TrajectoryFollower::Accept, StateAt), events read
// (FromEventMessage); the plant stepped at its rate on ticks. Shipped options and robot.
// Checked: the plant's true state stays finite whatever it was commanded, and so does the
// follower's state; refusals say why. A sixth channel is topay-kinematic-sim's CONTROL_COMMAND
// (KinematicModel::Apply), whose state must stay finite too.
// Input: subscriber_fuzz.h, 6 channels; at most 2 s of plant steps per tick, 20 s in all.
#include <algorithm>
#include <cstdint>
#include <string>

#include "procs/kinematic_sim/kinematic_model.h"
#include "procs/sim/command_timeline.h"
#include "procs/sim/sim_messages.h"
#include "procs/sim/sim_options.h"
#include "procs/sim/trajectory_follower.h"
#include "sim/plant/plant.h"
#include "tests/fuzz/subscriber_fuzz.h"
#include "topay/gripper_command_t.hpp"
#include "topay/sim_event_t.hpp"

namespace {

using namespace topay;

void CheckPlantState(const sim::PlantState& s) {
  FuzzCheck(std::isfinite(s.state.x_m) && std::isfinite(s.state.y_m) && std::isfinite(s.state.yaw_rad),
            "plant pose finite");
  FuzzCheck(s.state.q_rad.allFinite() && s.qdot_radps.allFinite(), "plant joints finite");
  FuzzCheck(std::isfinite(s.v_mps) && std::isfinite(s.omega_radps) && std::isfinite(s.gripper), "plant rates finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  static const simproc::SimOptions options = simproc::LoadSimOptions(ShippedConfig("sim/sim.yaml"));
  const RobotModel& model = ShippedRobotModel();
  sim::Plant plant(model, options.plant, options.seed);
  simproc::TrajectoryFollower follower(model.num_joints(), options.follower);
  kinsim::KinematicModel kinematic(kinsim::KinematicModelOptions{});
  double gripper_target = 0.0;
  simproc::CommandTimeline timeline;
  std::vector<sim::ActuatorCommand> due;
  FuzzReader in(data, size);
  std::int64_t now = kFuzzT0Utime;
  double stepped_s = 0.0;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 6);
    if (!op) break;
    if (op->tick) {
      const double advance_s = std::min(2.0, 1e-6 * static_cast<double>(op->advance_us));
      if ((stepped_s += advance_s) > 20.0) break;
      now += static_cast<std::int64_t>(advance_s * 1e6);
      const std::int64_t stepped_from = now - static_cast<std::int64_t>(advance_s * 1e6);
      for (double t = 0; t < advance_s; t += plant.step_s()) {
        timeline.TakeDue(stepped_from + static_cast<std::int64_t>((t + plant.step_s()) * 1e6), &due);
        for (const sim::ActuatorCommand& command : due) plant.Command(command);
        plant.Step();
      }
      FuzzCheck(timeline.pending() <= simproc::CommandTimelineOptions{}.max_pending, "the timeline stays bounded");
      CheckPlantState(plant.state());
      CheckPlantState(follower.StateAt(now, plant.state()));
      continue;
    }
    switch (op->channel) {
      case 0:
      case 1:  // CONTROL_COMMAND, ACTUATOR_COMMAND (one plant takes both here; the node sets the
               // CAN mode's gripper target when the command is due, here when it is kept)
        if (auto m = DecodeFuzzed<control_command_t>(op->bytes, op->fix_fingerprint)) {
          sim::ActuatorCommand command = simproc::ToActuatorCommand(*m);
          if (op->channel == 1) command.gripper = gripper_target;
          const std::string why = timeline.Push(m->utime, command, now, now);
          FuzzCheck(why.empty() || why.find("before the newest") != std::string::npos, "a dropped command says why");
        }
        break;
      case 2:
        if (auto m = DecodeFuzzed<gripper_command_t>(op->bytes, op->fix_fingerprint)) {
          if (plant.CommandGripper(m->position).empty()) gripper_target = m->position;
        }
        break;
      case 3:
        if (auto m = DecodeFuzzed<poly_trajectory_t>(op->bytes, op->fix_fingerprint)) {
          follower.Accept(*m, now, plant.state());
        }
        break;
      case 5:
        if (auto m = DecodeFuzzed<control_command_t>(op->bytes, op->fix_fingerprint)) {
          if (kinematic.Apply(*m)) {
            const WholeBodyState& s = kinematic.state().state;
            FuzzCheck(std::isfinite(s.x_m) && std::isfinite(s.y_m) && std::isfinite(s.yaw_rad) && s.q_rad.allFinite(),
                      "the kinematic model stays finite");
          }
        }
        break;
      default:
        if (auto m = DecodeFuzzed<sim_event_t>(op->bytes, op->fix_fingerprint)) {
          std::string error;
          if (!simproc::FromEventMessage(*m, &error)) FuzzCheck(!error.empty(), "a refused event says why");
        }
        break;
    }
  }
  return 0;
}
