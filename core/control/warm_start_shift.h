#pragma once

#include "core/control/control_command.h"

namespace topay {

/// The warm start of the next solve: the previous solution shifted by `shift_steps` steps
/// (control_period / step, usually 0.5), linearly interpolated between its steps, the last
/// step held past the end:
///   shifted_k = (1 - f) previous_i + f previous_min(i + 1, N - 1),  i + f = k + shift_steps.
/// Both sequences sized alike; allocation-free. shift_steps >= 0.
void ShiftInputSequence(const InputSequence& previous, double shift_steps, InputSequence* shifted);

}  // namespace topay
