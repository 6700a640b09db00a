#include "procs/sim/command_timeline.h"

#include <fmt/format.h>

#include <algorithm>

namespace topay::simproc {

std::string CommandTimeline::Push(std::int64_t stamp_utime, const sim::ActuatorCommand& command,
                                  std::int64_t plant_utime, std::int64_t wall_utime) {
  ++counts_.received;
  if (stamp_utime > wall_utime + options_.max_lead_us) {
    ++counts_.restamped;
    stamp_utime = wall_utime;
  }
  if (stamp_utime < last_stamp_utime_) {
    ++counts_.out_of_order;
    // In double: a corrupted stamp may be anywhere in the int64 range.
    return fmt::format("stamped {:.3f} s before the newest command kept",
                       1e-6 * (static_cast<double>(last_stamp_utime_) - static_cast<double>(stamp_utime)));
  }
  // stamp <= wall + max_lead here, so a stamp ahead of the plant is at most that far ahead of it.
  const std::int64_t lead_us = stamp_utime > plant_utime ? stamp_utime - plant_utime : 0;
  if (lead_us >= options_.behind_us) ++counts_.caught_up;
  counts_.largest_lead_us = std::max(counts_.largest_lead_us, lead_us);
  if (pending_.size() >= options_.max_pending) {
    pending_.pop_front();
    ++counts_.overflowed;
  }
  pending_.push_back({stamp_utime, command});
  last_stamp_utime_ = stamp_utime;
  return "";
}

void CommandTimeline::TakeDue(std::int64_t step_utime, std::vector<sim::ActuatorCommand>* due) {
  due->clear();
  while (!pending_.empty() && pending_.front().stamp_utime <= step_utime) {
    due->push_back(pending_.front().command);
    pending_.pop_front();
  }
}

std::string CommandTimeline::Report() const {
  return fmt::format("commands {}: {} caught up after stalls (up to {:.3f} s ahead of the plant), {} restamped, {} out of "
                     "order, {} overflowed",
                     counts_.received, counts_.caught_up, 1e-6 * static_cast<double>(counts_.largest_lead_us),
                     counts_.restamped, counts_.out_of_order, counts_.overflowed);
}

}  // namespace topay::simproc
