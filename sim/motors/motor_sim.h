#pragma once
// The motor-controller simulator (docs/motorsim.md): the base's wheel controller and the arm's
// CiA 402 drives on one CAN bus, between the bus and the plant. At each step (5 ms in
// topay-motorsim) it takes the frames received since the last step and the plant's latest
// state, and gives the frames to send and the actuator command for the plant (base v, omega
// from the wheel controller, joint rates from the drives). Fault injection (fault_injection.h)
// sits between the nodes and the bus. Pure and deterministic: times are passed in.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "drivers/can/can_frame.h"
#include "sim/motors/drive_node.h"
#include "sim/motors/fault_injection.h"
#include "sim/motors/stalled_plant.h"
#include "sim/motors/wheel_controller_node.h"
#include "sim/plant/actuator_command.h"
#include "sim/plant/plant_state.h"

namespace topay::sim::motors {

struct MotorSimOptions {
  double step_period_s = 0.005;      ///< topay-motorsim's step (200 Hz), s
  WheelControllerOptions base;       ///< the wheel controller (node 16)
  std::vector<int> joint_node_ids = {1, 2, 3, 4, 5, 6, 7};  ///< joint k's drive: node joint_node_ids[k-1]
  DriveNodeOptions drive;            ///< every drive's options (node_id set per joint)
  FaultInjectionOptions faults;      ///< none by default
  StalledPlantOptions stalled_plant; ///< topay-motorsim: the plant's state while the simulator stalls
};

/// Empty when the options are valid (every part's own checks, distinct node ids, none of them
/// 127: the host's), else what is wrong.
std::string CheckMotorSimOptions(const MotorSimOptions& options);

struct MotorSimCounts {
  std::int64_t steps = 0;
  std::int64_t frames_received = 0;  ///< handed to Receive
  std::int64_t frames_sent = 0;      ///< returned by Step (error frames included)
  std::int64_t frames_unhandled = 0; ///< delivered to the nodes, for none of them
  std::int64_t error_frames_sent = 0;
  std::int64_t faults_rejected = 0;  ///< run-time faults refused
};

class MotorSim {
 public:
  /// `options` must pass CheckMotorSimOptions (else std::invalid_argument).
  MotorSim(const MotorSimOptions& options, double start_time_s);

  /// A frame received from the bus at time_s (it reaches the nodes at the next Step, through the
  /// injected loss and delay).
  void Receive(const can::CanFrame& frame, double time_s);
  /// A run-time fault now (MOTORSIM_FAULT); "" or why it was refused.
  std::string Inject(const FaultEvent& event, double time_s);

  /// One step at time_s with the plant's latest state (null: none yet: no feedback frames);
  /// appends the frames to send now to *out.
  void Step(double time_s, const PlantState* plant, std::vector<can::CanFrame>* out);

  /// The plant's command now: base v, omega, joint rates; gripper 0 (not on this bus).
  ActuatorCommand command() const;

  int num_joints() const { return static_cast<int>(drives_.size()); }
  const WheelControllerNode& base() const { return base_; }
  const DriveNode& drive(int joint) const { return *drives_.at(static_cast<std::size_t>(joint - 1)); }
  const FaultInjector& faults() const { return injector_; }
  const MotorSimCounts& counts() const { return counts_; }
  /// Counts of every part, one line each (the process's final report).
  std::string Report() const;
  /// One line: base mode, drive states, bus (the heartbeat's status).
  std::string StatusLine() const;

 private:
  void ApplyNodeFault(const FaultEvent& fault, double time_s, std::vector<can::CanFrame>* out);

  MotorSimOptions options_;
  WheelControllerNode base_;
  std::vector<std::unique_ptr<DriveNode>> drives_;
  FaultInjector injector_;
  MotorSimCounts counts_;
};

}  // namespace topay::sim::motors
