#include "sim/motors/motor_sim.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "drivers/arm/cia402_state.h"
#include "drivers/base/base_mode.h"

namespace topay::sim::motors {

std::string CheckMotorSimOptions(const MotorSimOptions& o) {
  if (!(o.step_period_s > 0.0) || !std::isfinite(o.step_period_s)) return "step_period_s must be finite and > 0";
  if (std::string bad = CheckWheelControllerOptions(o.base); !bad.empty()) return "base: " + bad;
  if (o.joint_node_ids.empty()) return "drives.node_ids: at least one drive";
  std::set<int> ids = {o.base.node_id};
  for (int id : o.joint_node_ids) {
    DriveNodeOptions drive = o.drive;
    drive.node_id = id;
    if (std::string bad = CheckDriveNodeOptions(drive); !bad.empty()) return "drives: " + bad;
    if (id == 127) return "drives.node_ids: 127 is the host's (the bridge's) node id";
    if (!ids.insert(id).second) {
      return "node id " + std::to_string(id) + " is used twice (the base's and the drives' ids must differ)";
    }
  }
  if (o.base.node_id == 127) return "base.node_id: 127 is the host's (the bridge's) node id";
  if (std::string bad = CheckStalledPlantOptions(o.stalled_plant); !bad.empty()) return "stalled_plant: " + bad;
  if (std::string bad = CheckFaultInjectionOptions(o.faults, static_cast<int>(o.joint_node_ids.size())); !bad.empty()) {
    return "faults: " + bad;
  }
  return "";
}

namespace {
const MotorSimOptions& Checked(const MotorSimOptions& o) {
  if (std::string bad = CheckMotorSimOptions(o); !bad.empty()) throw std::invalid_argument("MotorSimOptions: " + bad);
  return o;
}
}  // namespace

MotorSim::MotorSim(const MotorSimOptions& options, double start_time_s)
    : options_(Checked(options)),
      base_(options.base, start_time_s),
      injector_(options.faults, static_cast<int>(options.joint_node_ids.size())) {
  for (int id : options.joint_node_ids) {
    DriveNodeOptions drive = options.drive;
    drive.node_id = id;
    drives_.push_back(std::make_unique<DriveNode>(drive, start_time_s));
  }
}

void MotorSim::Receive(const can::CanFrame& frame, double time_s) {
  ++counts_.frames_received;
  injector_.PushReceived(frame, time_s);
}

std::string MotorSim::Inject(const FaultEvent& event, double time_s) {
  std::string why = injector_.Inject(event, time_s);
  if (!why.empty()) ++counts_.faults_rejected;
  return why;
}

void MotorSim::ApplyNodeFault(const FaultEvent& fault, double time_s, std::vector<can::CanFrame>* out) {
  if (fault.kind == FaultKind::kBaseFault) {
    base_.RaiseFault(static_cast<base::BaseFault>(fault.code), time_s);
  } else if (fault.kind == FaultKind::kDriveFault) {
    drives_.at(static_cast<std::size_t>(fault.joint - 1))->InjectFault(static_cast<std::uint16_t>(fault.code), time_s, out);
  }
}

void MotorSim::Step(double time_s, const PlantState* plant, std::vector<can::CanFrame>* out) {
  ++counts_.steps;
  const FaultInjector::Actions actions = injector_.Advance(time_s);
  for (const can::CanFrame& frame : actions.error_frames) {
    out->push_back(frame);
    ++counts_.frames_sent;
    ++counts_.error_frames_sent;
  }
  if (plant != nullptr) {
    for (std::size_t k = 0; k < drives_.size(); ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      const double q = i < plant->state.q_rad.size() ? plant->state.q_rad[i] : 0.0;
      const double qd = i < plant->qdot_radps.size() ? plant->qdot_radps[i] : 0.0;
      drives_[k]->SetFeedback({q, qd});
    }
  }
  std::vector<can::CanFrame> node_out;
  for (const FaultEvent& fault : actions.node_faults) ApplyNodeFault(fault, time_s, &node_out);
  for (const can::CanFrame& frame : injector_.TakeReceived(time_s)) {
    bool handled = base_.OnFrame(frame, time_s);
    for (auto& drive : drives_) handled = drive->OnFrame(frame, time_s, &node_out) || handled;
    if (!handled) ++counts_.frames_unhandled;
  }
  std::optional<base::UnicycleVelocity> base_velocity;
  if (plant != nullptr) base_velocity = base::UnicycleVelocity{plant->v_mps, plant->omega_radps};
  base_.Step(time_s, base_velocity, &node_out);
  for (std::size_t k = 0; k < drives_.size(); ++k) {
    drives_[k]->Step(time_s, injector_.HeartbeatSuppressed(static_cast<int>(k + 1), time_s), &node_out);
  }
  for (const can::CanFrame& frame : node_out) injector_.PushSent(frame, time_s);
  for (const can::CanFrame& frame : injector_.TakeSent(time_s)) {
    out->push_back(frame);
    ++counts_.frames_sent;
  }
}

ActuatorCommand MotorSim::command() const {
  ActuatorCommand command;
  command.v_mps = base_.command().v_m_per_s;
  command.omega_radps = base_.command().omega_rad_per_s;
  command.qdot_radps = Eigen::VectorXd::Zero(num_joints());
  for (int k = 0; k < num_joints(); ++k) command.qdot_radps[k] = drives_[static_cast<std::size_t>(k)]->velocity_command_radps();
  command.gripper = 0.0;
  return command;
}

std::string MotorSim::StatusLine() const {
  int enabled = 0, faulted = 0;
  for (const auto& drive : drives_) {
    enabled += drive->state() == cia402::DriveState::kOperationEnabled;
    faulted += drive->state() == cia402::DriveState::kFault || drive->state() == cia402::DriveState::kFaultReactionActive;
  }
  return std::string("base ") + base::ModeName(base_.mode()) + ", drives " + std::to_string(enabled) + "/" +
         std::to_string(num_joints()) + " enabled, " + std::to_string(faulted) + " in fault" +
         (injector_.bus_off() ? ", BUS-OFF (injected)" : "") + ", frames rx " + std::to_string(counts_.frames_received) +
         " tx " + std::to_string(counts_.frames_sent);
}

std::string MotorSim::Report() const {
  const WheelControllerCounts& b = base_.counts();
  std::string text = "motorsim: steps " + std::to_string(counts_.steps) + ", frames received " +
                     std::to_string(counts_.frames_received) + ", sent " + std::to_string(counts_.frames_sent) +
                     " (error frames " + std::to_string(counts_.error_frames_sent) + "), for no node " +
                     std::to_string(counts_.frames_unhandled) + "\n";
  text += "motorsim: base node " + std::to_string(base_.node_id()) + ": mode " + base::ModeName(base_.mode()) +
          ", mode requests " + std::to_string(b.mode_requests) + " (refused " + std::to_string(b.mode_refused) +
          "), commands " + std::to_string(b.commands) + " (ignored " + std::to_string(b.commands_ignored) +
          ", lost by counter " + std::to_string(b.counter_gaps) + "), malformed " + std::to_string(b.malformed) +
          ", command timeouts " + std::to_string(b.timeouts) + ", faults " + std::to_string(b.faults) + "\n";
  for (int k = 1; k <= num_joints(); ++k) {
    const DriveNode& d = drive(k);
    const DriveNodeCounts& c = d.counts();
    text += "motorsim: joint " + std::to_string(k) + " node " + std::to_string(d.node_id()) + ": " +
            std::string(cia402::ToString(d.state())) + ", SYNCs " + std::to_string(c.syncs) + ", RPDOs " +
            std::to_string(c.rpdos) + ", SDO writes " + std::to_string(c.sdo_writes) + " (aborted " +
            std::to_string(c.sdo_aborts) + "), refused controlwords " + std::to_string(c.refused_controlwords) +
            ", malformed " + std::to_string(c.malformed) + ", faults " + std::to_string(c.faults) + " (host heartbeat lost " +
            std::to_string(c.host_heartbeat_lost) + "), EMCY " + std::to_string(c.emcy) + "\n";
  }
  const InjectorCounts& f = injector_.counts();
  const LinkCounts& rx = injector_.rx_counts();
  const LinkCounts& tx = injector_.tx_counts();
  text += "motorsim: faults injected: drive " + std::to_string(f.drive_faults) + ", base " + std::to_string(f.base_faults) +
          ", heartbeat losses " + std::to_string(f.heartbeat_losses) + ", bus-off " + std::to_string(f.bus_offs) +
          ", link changes " + std::to_string(f.link_changes) + ", rejected " + std::to_string(f.rejected) + "\n";
  text += "motorsim: link rx lost " + std::to_string(rx.lost) + " delayed " + std::to_string(rx.delayed) + " silenced " +
          std::to_string(rx.silenced) + "; tx lost " + std::to_string(tx.lost) + " delayed " + std::to_string(tx.delayed) +
          " silenced " + std::to_string(tx.silenced);
  return text;
}

}  // namespace topay::sim::motors
