// topay-motorsim's subscriptions (SIM_PLANT_STATE, MOTORSIM_FAULT) with the calls its node makes
// (MotorSimNode::On*): the plant state read (PlantStateFromMessage) and used by the devices'
// next steps (carried on their command while stale: StalledPlant), faults read (FaultEventFromMessage) and injected (MotorSim::Inject); the devices
// stepped every 5 ms on ticks, as the node does. Shipped options. Checked: refusals say why; every frame
// the devices send is a valid CAN frame; the actuator command to the plant is finite.
// Input: subscriber_fuzz.h, 2 channels; at most 2 s of steps per tick, 20 s in all.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "procs/motorsim/motorsim_messages.h"
#include "sim/motors/motor_sim.h"
#include "sim/motors/motorsim_options.h"
#include "sim/motors/stalled_plant.h"
#include "tests/fuzz/subscriber_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const sim::motors::MotorSimOptions options =
      sim::motors::LoadMotorSimOptions(ShippedConfig("sim/motorsim.yaml"));
  double now_s = 0.0;
  sim::motors::MotorSim motors(options, now_s);
  sim::motors::StalledPlant plant(options.stalled_plant);
  std::vector<can::CanFrame> out;
  FuzzReader in(data, size);
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 2);
    if (!op) break;
    std::string error;
    if (op->tick) {
      const double advance_s = std::min(2.0, 1e-6 * static_cast<double>(op->advance_us));
      if (now_s + advance_s > 20.0) break;
      for (const double end = now_s + advance_s; now_s < end;) {
        now_s += 5e-3;
        out.clear();
        motors.Step(now_s, plant.At(now_s, motors.command()), &out);
        for (const can::CanFrame& frame : out) FuzzCheck(can::CheckCanFrame(frame).empty(), "devices send valid frames");
      }
      const sim::ActuatorCommand command = motors.command();
      FuzzCheck(std::isfinite(command.v_mps) && std::isfinite(command.omega_radps) && command.qdot_radps.allFinite(),
                "the plant is commanded finite rates");
      continue;
    }
    if (op->channel == 0) {
      if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) {
        auto state = motorsim::PlantStateFromMessage(*m, motors.num_joints(), &error);
        if (state) plant.OnPlantState(*state, now_s);
        else FuzzCheck(!error.empty(), "a refused plant state says why");
      }
    } else if (auto m = DecodeFuzzed<motorsim_fault_t>(op->bytes, op->fix_fingerprint)) {
      const auto event = motorsim::FaultEventFromMessage(*m, &error);
      if (event) motors.Inject(*event, now_s);
      else FuzzCheck(!error.empty(), "a refused fault says why");
    }
  }
  return 0;
}
