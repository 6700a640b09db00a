#include "procs/motorsim/motorsim_node.h"

#include <spdlog/spdlog.h>

#include <chrono>

#include "procs/motorsim/motorsim_messages.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::motorsim {
namespace {

bool Every(std::int64_t n) { return n <= 10 || n % 1000 == 0; }  // log the first 10, then every 1000th

}  // namespace

MotorSimNode::MotorSimNode(procs::ProcessLoop* loop, can::CanBus* bus, sim::motors::MotorSim* sim,
                           const MotorSimNodeOptions& options)
    : loop_(loop),
      bus_(bus),
      sim_(sim),
      options_(options),
      start_(procs::ProcessLoop::Clock::now()),
      plant_(options.stalled_plant) {
  loop_->Subscribe<robot_state_t>(std::string(channels::SIM_PLANT_STATE),
                                  [this](const robot_state_t& msg) { OnPlantState(msg); });
  loop_->Subscribe<motorsim_fault_t>(std::string(channels::MOTORSIM_FAULT),
                                     [this](const motorsim_fault_t& msg) { OnFault(msg); });
  loop_->AddScheduledTimer([this] { return OnStep(); });
  loop_->SetHealth(heartbeat_t::WARN, "starting: no plant state yet");
}

double MotorSimNode::NowS() const {
  return std::chrono::duration<double>(procs::ProcessLoop::Clock::now() - start_).count();
}

procs::ProcessLoop::Clock::time_point MotorSimNode::OnStep() {
  const double now_s = NowS();
  DrainBus(now_s);
  std::vector<can::CanFrame> out;
  sim_->Step(now_s, plant_.At(now_s, sim_->command()), &out);
  for (const can::CanFrame& frame : out) Send(frame);
  const control_command_t command = ToActuatorMessage(sim_->command(), procs::NowUtime());
  loop_->lcm().publish(std::string(channels::ACTUATOR_COMMAND), &command);
  ++counts_.actuator_commands;
  if (now_s >= next_status_s_) UpdateHealth(now_s);
  // A fixed schedule: step k at start + k * period (a late wake-up does not shift the next ones;
  // after a stall the schedule restarts from now rather than bursting).
  ++step_;
  const auto period = std::chrono::duration<double>(options_.step_period_s);
  auto next = start_ + std::chrono::duration_cast<procs::ProcessLoop::Clock::duration>(period * static_cast<double>(step_));
  const auto now = procs::ProcessLoop::Clock::now();
  if (next < now) {
    step_ = static_cast<std::int64_t>(std::chrono::duration<double>(now - start_).count() / options_.step_period_s) + 1;
    next = start_ + std::chrono::duration_cast<procs::ProcessLoop::Clock::duration>(period * static_cast<double>(step_));
  }
  return next;
}

void MotorSimNode::DrainBus(double now_s) {
  can::ReceivedCanFrame received;
  while (true) {
    const can::CanResult result = bus_->Receive(0.0, &received);
    if (result.code == can::CanResult::Code::kTimeout) return;
    if (!result.ok()) {
      if (Every(++counts_.receive_errors)) spdlog::warn("CAN receive: {}", result.message);
      return;
    }
    sim_->Receive(received.frame, now_s);
  }
}

void MotorSimNode::Send(const can::CanFrame& frame) {
  const can::CanResult result = bus_->Send(frame);
  if (result.ok()) return;
  last_send_error_ = result.message;
  if (Every(++counts_.send_failures)) spdlog::warn("CAN send of {} failed: {}", can::ToString(frame), result.message);
}

void MotorSimNode::OnPlantState(const robot_state_t& msg) {
  std::string error;
  std::optional<sim::PlantState> state = PlantStateFromMessage(msg, sim_->num_joints(), &error);
  if (!state) {
    if (Every(++counts_.bad_plant_states)) spdlog::warn("ignored SIM_PLANT_STATE: {}", error);
    return;
  }
  plant_received_s_ = NowS();
  plant_.OnPlantState(*state, plant_received_s_);
  ++counts_.plant_states;
}

void MotorSimNode::OnFault(const motorsim_fault_t& msg) {
  std::string error;
  const std::optional<sim::motors::FaultEvent> event = FaultEventFromMessage(msg, &error);
  if (event) error = sim_->Inject(*event, NowS());
  if (!error.empty()) {
    ++counts_.faults_rejected;
    spdlog::warn("rejected MOTORSIM_FAULT: {}", error);
    return;
  }
  ++counts_.faults_requested;
  spdlog::info("MOTORSIM_FAULT: {} (joint {}, duration {} s, value {}, code {})",
               sim::motors::FaultKindName(event->kind), msg.joint, msg.duration_s, msg.value, msg.code);
}

void MotorSimNode::UpdateHealth(double now_s) {
  next_status_s_ = now_s + options_.status_period_s;
  const bool plant_fresh = plant_received_s_ >= 0.0 && now_s - plant_received_s_ <= options_.plant_state_timeout_s;
  const bool degraded = !plant_fresh || sim_->faults().bus_off() || counts_.send_failures > 0;
  std::string status = sim_->StatusLine();
  if (!plant_fresh) status += ", NO PLANT STATE";
  if (plant_fresh && plant_.stale()) status += ", the simulator stalled: state carried on the command";
  if (counts_.send_failures > 0) status += ", send failures " + std::to_string(counts_.send_failures);
  loop_->SetHealth(degraded ? heartbeat_t::WARN : heartbeat_t::OK, status);
}

std::string MotorSimNode::FinalReport() const {
  const can::CanBusStatus& bus = bus_->status();
  const sim::motors::StalledPlantCounts& stalled = plant_.counts();
  return sim_->Report() + "\n" +
         fmt::format("motorsim: simulator stalls {} (longest {:.3f} s): the state carried on the command {:.3f} s, held "
                     "{:.3f} s\n",
                     stalled.stalls, stalled.longest_stall_s, stalled.carried_s, stalled.held_s) +
         fmt::format("motorsim: plant states {} (bad {}), MOTORSIM_FAULT {} (rejected {}), ACTUATOR_COMMAND {}, "
                     "send failures {}{}, receive errors {}\n"
                     "motorsim: bus {}: state {}, sent {}, received {}, error frames {}, malformed {}, lost {}",
                     counts_.plant_states, counts_.bad_plant_states, counts_.faults_requested, counts_.faults_rejected,
                     counts_.actuator_commands, counts_.send_failures,
                     last_send_error_.empty() ? "" : " (last: " + last_send_error_ + ")", counts_.receive_errors,
                     bus_->url(), can::ToString(bus.state), bus.frames_sent, bus.frames_received, bus.error_frames,
                     bus.malformed, bus.lost_frames);
}

}  // namespace topay::motorsim
