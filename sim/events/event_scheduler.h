#pragma once
// Decides when world events fire: time triggers at the first plant step at or after their time
// (plus the seeded jitter, drawn once per event in script order when the scheduler is built),
// proximity triggers at the first step the base origin is within the distance of the point,
// run-time events (SIM_EVENT) at the next step for kNow. Every event fires once. Deterministic:
// the same script, seed and base path give the same firing steps.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/events/sim_event.h"

namespace topay::sim {

class EventScheduler {
 public:
  /// `seed` draws the jitter of kAtTime events (in order).
  EventScheduler(std::vector<SimEvent> scripted, std::uint64_t seed);

  /// A run-time event: kNow fires at the next Poll, kAtTime at its time (at once if past; no
  /// jitter), kNearPoint like a scripted one.
  void Add(SimEvent event);

  /// The events due at sim time t_s with the base origin at p_WB_m (x, y), in the order they
  /// were scripted or added; each is returned once and then dropped.
  std::vector<SimEvent> Poll(double t_s, const Eigen::Vector2d& p_WB_m);

  int pending() const { return static_cast<int>(pending_.size()); }
  std::int64_t fired() const { return fired_; }
  /// The time each scripted kAtTime event fires at (at_s + jitter), for logs and tests; in
  /// script order, NaN for other triggers.
  const std::vector<double>& scripted_fire_times_s() const { return fire_times_s_; }

 private:
  struct Pending {
    SimEvent event;
    double fire_at_s;  // kAtTime (jitter included); unused otherwise
  };
  std::vector<Pending> pending_;
  std::vector<double> fire_times_s_;
  std::int64_t fired_ = 0;
};

}  // namespace topay::sim
