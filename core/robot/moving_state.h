#pragma once

#include "core/robot/whole_body_rates.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// A whole-body state and its rates: where a trajectory that joins a motion under way must
/// start (positions x, y, yaw, q and v, omega, a, beta, qd, qdd). Default rates: at rest.
struct MovingState {
  WholeBodyState state;
  WholeBodyRates rates;
};

}  // namespace topay
