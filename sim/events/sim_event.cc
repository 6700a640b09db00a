#include "sim/events/sim_event.h"

#include <cstdio>

namespace topay::sim {

std::string Describe(const SimEvent& event) {
  std::string text = (event.action == SimEvent::Action::kAppear ? "appear box " : "disappear box ") +
                     std::to_string(event.box_id);
  char buffer[128];
  switch (event.trigger) {
    case SimEvent::Trigger::kNow:
      text += " now";
      break;
    case SimEvent::Trigger::kAtTime:
      std::snprintf(buffer, sizeof buffer, " at t=%.3f s", event.at_s);
      text += buffer;
      if (event.jitter_s > 0.0) {
        std::snprintf(buffer, sizeof buffer, " (+U[0, %.3f) s)", event.jitter_s);
        text += buffer;
      }
      break;
    case SimEvent::Trigger::kNearPoint:
      std::snprintf(buffer, sizeof buffer, " when the base is within %.2f m of (%.2f, %.2f)", event.distance_m,
                    event.point_W_m.x(), event.point_W_m.y());
      text += buffer;
      break;
  }
  return event.name.empty() ? text : event.name + ": " + text;
}

}  // namespace topay::sim
