#include "sim/events/apply_event.h"

namespace topay::sim {

std::string ApplyEvent(const SimEvent& event, SimWorld* world) {
  std::string error;
  const bool ok = event.action == SimEvent::Action::kAppear ? world->Appear(event.box_id, event.box, &error)
                                                            : world->Disappear(event.box_id, &error);
  return ok ? "" : error;
}

}  // namespace topay::sim
