#include "procs/planner/trajectory_delivery.h"

#include <cmath>

namespace topay::planner {

void TrajectoryDelivery::Sent(const poly_trajectory_t& msg, std::int64_t now_utime) {
  pending_ = Pending{msg, now_utime};
}

void TrajectoryDelivery::OnTrackerStatus(const tracker_status_t& status) {
  tracker_heard_ = true;
  if (!pending_) return;
  if (status.state == tracker_status_t::HELD) {
    pending_.reset();  // every trajectory dropped: the planner plans anew on the release
  } else if (status.trajectory_id >= pending_->msg.trajectory_id) {
    ++counts_.confirmed;
    pending_.reset();
  }
}

const poly_trajectory_t* TrajectoryDelivery::Due(std::int64_t now_utime) {
  if (!pending_ || !tracker_heard_ || options_.resend_period_s <= 0.0) return nullptr;
  const auto micros = [](double s) { return static_cast<std::int64_t>(std::llround(s * 1e6)); };
  if (now_utime > pending_->msg.start_utime + micros(options_.give_up_s)) {
    ++counts_.given_up;
    pending_.reset();
    return nullptr;
  }
  if (now_utime - pending_->last_sent_utime < micros(options_.resend_period_s)) return nullptr;
  pending_->last_sent_utime = now_utime;
  ++counts_.resent;
  return &pending_->msg;
}

}  // namespace topay::planner
