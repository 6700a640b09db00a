#include "procs/msgs/map_publish_schedule.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay::msgs {

MapPublishSchedule::MapPublishSchedule(const MapPublishScheduleOptions& options)
    : options_(options), next_seq_(options.first_map_seq) {
  if (!(std::isfinite(options.snapshot_period_s) && options.snapshot_period_s > 0.0)) {
    throw std::invalid_argument("MapPublishScheduleOptions.snapshot_period_s: " +
                                std::to_string(options.snapshot_period_s) +
                                " (must be finite and > 0)");
  }
}

MapPublishStep MapPublishSchedule::Next(double now_s) {
  if (!std::isfinite(now_s)) {
    throw std::invalid_argument("MapPublishSchedule::Next: now_s is not finite");
  }
  MapPublishStep step{SnapshotDue(now_s), next_seq_++};
  if (step.is_full) {
    last_snapshot_s_ = now_s;
    snapshot_requested_ = false;
  }
  return step;
}

bool MapPublishSchedule::SnapshotDue(double now_s) const {
  return snapshot_requested_ || now_s < last_snapshot_s_ ||
         now_s - last_snapshot_s_ >= options_.snapshot_period_s;
}

}  // namespace topay::msgs
