#include "core/control/latency_prediction.h"

#include <algorithm>
#include <stdexcept>

#include "core/robot/unicycle_motion.h"

namespace topay {

CommandHistory::CommandHistory(int capacity, int num_joints)
    : times_(std::max(capacity, 1), 0.0),
      commands_(std::max(capacity, 1), ControlCommand::Zero(num_joints)) {}

void CommandHistory::Push(double t_s, const ControlCommand& command) {
  if (size_ > 0 && t_s < time_s(size_ - 1)) Clear();
  const int capacity = static_cast<int>(times_.size());
  if (size_ == capacity) {  // drop the oldest
    head_ = (head_ + 1) % capacity;
    --size_;
  }
  const int slot = Slot(size_);
  times_[slot] = t_s;
  commands_[slot].v_mps = command.v_mps;
  commands_[slot].omega_radps = command.omega_radps;
  commands_[slot].qd_radps = command.qd_radps;
  ++size_;
}

void PredictState(const CommandHistory& history, double latency_s, double t_from_s,
                  double t_to_s, WholeBodyState* state) {
  double t_s = t_from_s;
  // The command acting at t_s: the last one with send time + latency <= t_s (-1: none).
  int active = -1;
  while (active + 1 < history.size() && history.time_s(active + 1) + latency_s <= t_s) ++active;
  while (t_s < t_to_s) {
    const double next_change_s =
        active + 1 < history.size() ? history.time_s(active + 1) + latency_s : t_to_s;
    const double until_s = std::min(next_change_s, t_to_s);
    const double dt_s = until_s - t_s;
    if (active >= 0 && dt_s > 0.0) {
      const ControlCommand& command = history.command(active);
      AdvanceUnicycle(command.v_mps, command.omega_radps, dt_s, state);  // exact arc
      state->q_rad += dt_s * command.qd_radps;                          // q += qd dt
    }
    t_s = until_s;
    ++active;
  }
}

}  // namespace topay
