#include "core/control/warm_start_shift.h"

#include <algorithm>
#include <cmath>

namespace topay {

void ShiftInputSequence(const InputSequence& previous, double shift_steps,
                        InputSequence* shifted) {
  const int N = previous.steps();
  for (int k = 0; k < N; ++k) {
    const double tau = k + shift_steps;
    const int i = std::min(static_cast<int>(std::floor(tau)), N - 1);
    const int next = std::min(i + 1, N - 1);
    const double f = i == N - 1 ? 0.0 : tau - i;  // past the end: hold the last step
    shifted->u_base.col(k) = (1.0 - f) * previous.u_base.col(i) + f * previous.u_base.col(next);
    shifted->qd_radps.col(k) =
        (1.0 - f) * previous.qd_radps.col(i) + f * previous.qd_radps.col(next);
  }
}

}  // namespace topay
