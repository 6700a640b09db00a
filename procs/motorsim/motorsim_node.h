#pragma once
// topay-motorsim on the bus and LCM (docs/motorsim.md): every step (5 ms) it drains the CAN bus
// into the MotorSim, steps it with the plant's latest state (SIM_PLANT_STATE from topay-sim in
// CAN mode), sends the frames it gives and publishes ACTUATOR_COMMAND (200 Hz); MOTORSIM_FAULT
// injects faults at run time. While SIM_PLANT_STATE is stale (the simulator's process not
// running) the drives answer with the last state carried on their own command (StalledPlant).
// Heartbeat health: WARN without a plant state (none yet or none
// for plant_state_timeout_s), while injected bus-off lasts or after send errors, else OK.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_bus.h"
#include "procs/runtime/process_loop.h"
#include "sim/motors/motor_sim.h"
#include "sim/motors/stalled_plant.h"
#include "topay/motorsim_fault_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::motorsim {

struct MotorSimNodeOptions {
  double step_period_s = 0.005;          ///< the step (200 Hz): bus drained, frames sent, ACTUATOR_COMMAND
  double plant_state_timeout_s = 0.5;    ///< no SIM_PLANT_STATE for this long: health WARN
  double status_period_s = 1.0;          ///< heartbeat status line update, s
  sim::motors::StalledPlantOptions stalled_plant;  ///< a stalled simulator: the state carried on
};

struct MotorSimNodeCounts {
  std::int64_t plant_states = 0;
  std::int64_t bad_plant_states = 0;     ///< decoded but inconsistent (logged)
  std::int64_t faults_requested = 0;     ///< MOTORSIM_FAULT accepted
  std::int64_t faults_rejected = 0;
  std::int64_t actuator_commands = 0;    ///< ACTUATOR_COMMAND published
  std::int64_t send_failures = 0;        ///< bus Send() not ok (bus-off seen, queue full, ...)
  std::int64_t receive_errors = 0;       ///< bus Receive() errors other than a timeout
};

class MotorSimNode {
 public:
  /// Subscribes and adds the step timer to *loop (call before loop->Run()). loop, bus and sim
  /// outlive the node; the sim's start time is the node's time 0.
  MotorSimNode(procs::ProcessLoop* loop, can::CanBus* bus, sim::motors::MotorSim* sim,
               const MotorSimNodeOptions& options);

  const MotorSimNodeCounts& counts() const { return counts_; }
  /// The counts of the node, the sim and the bus, printed on exit.
  std::string FinalReport() const;

 private:
  procs::ProcessLoop::Clock::time_point OnStep();
  void OnPlantState(const robot_state_t& msg);
  void OnFault(const motorsim_fault_t& msg);
  void DrainBus(double now_s);
  void Send(const can::CanFrame& frame);
  void UpdateHealth(double now_s);
  double NowS() const;

  procs::ProcessLoop* loop_;
  can::CanBus* bus_;
  sim::motors::MotorSim* sim_;
  MotorSimNodeOptions options_;
  procs::ProcessLoop::Clock::time_point start_;
  std::int64_t step_ = 0;
  sim::motors::StalledPlant plant_;
  double plant_received_s_ = -1.0;
  double next_status_s_ = 0.0;
  std::string last_send_error_;
  MotorSimNodeCounts counts_;
};

}  // namespace topay::motorsim
