#pragma once

#include <vector>

#include "core/control/control_command.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The commands sent lately with their send times, oldest first, in a fixed ring (no
/// allocation after construction; the oldest is dropped when full).
class CommandHistory {
 public:
  CommandHistory(int capacity, int num_joints);

  /// Appends a command sent at t_s (times must not decrease; an earlier time clears first).
  void Push(double t_s, const ControlCommand& command);
  void Clear() { size_ = 0; }

  int size() const { return size_; }
  /// i = 0 is the oldest.
  double time_s(int i) const { return times_[Slot(i)]; }
  const ControlCommand& command(int i) const { return commands_[Slot(i)]; }

 private:
  int Slot(int i) const { return (head_ + i) % static_cast<int>(times_.size()); }

  std::vector<double> times_;
  std::vector<ControlCommand> commands_;
  int head_ = 0;
  int size_ = 0;
};

/// Latency compensation: predicts *state, measured at t_from_s, forward to t_to_s with the
/// commands already sent. A command sent at s acts on the robot from s + latency_s until the
/// next one acts (before the oldest known command acts: at rest). The base moves as a
/// unicycle (AdvanceUnicycle, exact arcs), the joints as integrators (q += qd dt).
/// Nothing happens for t_to_s <= t_from_s. Allocation-free.
void PredictState(const CommandHistory& history, double latency_s, double t_from_s,
                  double t_to_s, WholeBodyState* state);

}  // namespace topay
