#pragma once
// The planner's newest TRAJECTORY until the tracker confirms it (docs/planner.md, fault campaign
// finding 25). A TRAJECTORY is one UDP message: lost on a lossy bus (10 % of datagrams dropped
// for 10 s), the planner believed the robot braking on its stop for a stale map while the
// tracker drove on along the old trajectory into a box placed ahead meanwhile. So the newest
// trajectory is sent again, the same message, every resend_period_s until TRACKER_STATUS names
// it or a newer one (the tracker ignores an id not newer than its own, so copies are harmless),
// the tracker is HELD (it dropped every trajectory), or give_up_s after its start. Only once a
// TRACKER_STATUS has been heard: a graph without the tracker (the simulator following
// TRAJECTORY itself) gets each trajectory once.

#include <cstdint>
#include <optional>

#include "topay/poly_trajectory_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::planner {

struct TrajectoryDeliveryOptions {
  /// A trajectory the tracker does not report is sent again after this long (s). 0: never
  /// again. >= 0.
  double resend_period_s = 0.1;
  /// ... until this long (s) after its start (a tracker that never takes it: a pending one is
  /// reported only from its start on). > 0.
  double give_up_s = 2.0;
};

struct TrajectoryDeliveryCounts {
  std::int64_t resent = 0;     ///< copies sent again
  std::int64_t confirmed = 0;  ///< trajectories the tracker reported
  std::int64_t given_up = 0;   ///< never reported within give_up_s of their start
};

class TrajectoryDelivery {
 public:
  explicit TrajectoryDelivery(const TrajectoryDeliveryOptions& options) : options_(options) {}

  /// The newest trajectory went out at now_utime (it replaces any earlier one).
  void Sent(const poly_trajectory_t& msg, std::int64_t now_utime);
  /// TRACKER_STATUS: trajectory_id at or past the one sent confirms it; HELD drops it.
  void OnTrackerStatus(const tracker_status_t& status);
  /// The copy to send at now_utime (null: none due); counts it as sent.
  const poly_trajectory_t* Due(std::int64_t now_utime);
  /// Nothing to deliver any more (the planner forgot its trajectories).
  void Forget() { pending_.reset(); }

  bool waiting() const { return pending_.has_value(); }
  const TrajectoryDeliveryCounts& counts() const { return counts_; }

 private:
  struct Pending {
    poly_trajectory_t msg;
    std::int64_t last_sent_utime = 0;
  };
  TrajectoryDeliveryOptions options_;
  bool tracker_heard_ = false;
  std::optional<Pending> pending_;
  TrajectoryDeliveryCounts counts_;
};

}  // namespace topay::planner
