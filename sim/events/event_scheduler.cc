#include "sim/events/event_scheduler.h"

#include <cmath>
#include <limits>

#include "core/common/random.h"

namespace topay::sim {

EventScheduler::EventScheduler(std::vector<SimEvent> scripted, std::uint64_t seed) {
  Rng rng(seed);
  for (SimEvent& event : scripted) {
    double fire_at_s = std::numeric_limits<double>::quiet_NaN();
    if (event.trigger == SimEvent::Trigger::kAtTime) {
      // One draw per time event, whether it has jitter or not: adding jitter to one event does
      // not shift the others' draws.
      fire_at_s = event.at_s + event.jitter_s * rng.Uniform01();
    }
    fire_times_s_.push_back(fire_at_s);
    pending_.push_back({std::move(event), fire_at_s});
  }
}

void EventScheduler::Add(SimEvent event) {
  const double fire_at_s = event.at_s;
  pending_.push_back({std::move(event), fire_at_s});
}

std::vector<SimEvent> EventScheduler::Poll(double t_s, const Eigen::Vector2d& p_WB_m) {
  std::vector<SimEvent> due;
  std::vector<Pending> keep;
  for (Pending& p : pending_) {
    bool fire = false;
    switch (p.event.trigger) {
      case SimEvent::Trigger::kNow:
        fire = true;
        break;
      case SimEvent::Trigger::kAtTime:
        // A tiny tolerance so that an event at a step's exact time fires at that step.
        fire = t_s >= p.fire_at_s - 1e-9;
        break;
      case SimEvent::Trigger::kNearPoint:
        fire = (p_WB_m - p.event.point_W_m).norm() <= p.event.distance_m;
        break;
    }
    if (fire) {
      due.push_back(std::move(p.event));
    } else {
      keep.push_back(std::move(p));
    }
  }
  pending_ = std::move(keep);
  fired_ += static_cast<std::int64_t>(due.size());
  return due;
}

}  // namespace topay::sim
