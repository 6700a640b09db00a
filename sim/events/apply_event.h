#pragma once
// Applies a fired event to the world.

#include <string>

#include "sim/events/sim_event.h"
#include "sim/world/sim_world.h"

namespace topay::sim {

/// Makes the event's box appear or disappear in *world. Returns "" on success, else why not
/// (an unknown id, a new id without geometry, an invalid box): the world is unchanged.
std::string ApplyEvent(const SimEvent& event, SimWorld* world);

}  // namespace topay::sim
