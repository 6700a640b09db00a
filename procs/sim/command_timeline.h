#pragma once
// Commands applied at the plant step of their own stamp (docs/simulator.md, "Time base"). A
// simulator process that stalls (a loaded machine) catches up afterwards by running the steps it
// missed in a burst; the commands that arrived meanwhile are then all waiting, and handed to the
// plant on arrival the plant would drive the whole stall on the command from before it (a robot in
// a bend went straight on at its old speed). The timeline keeps each command until the step whose
// time reaches its stamp, so the caught-up plant has followed the commands as the drives would have
// received them. In real time nothing changes but a wait of at most one step.
//
// Stamps are utimes of the wall clock, which the sim's clock follows (SimUtime). A stamp more
// than max_lead_us ahead of the wall clock is not trusted (another clock, a corrupted copy): the
// command is taken as stamped now. A command stamped before the newest one kept (waiting or
// taken) is out of order (reordered on the way, or a copy): it is dropped, counted, so that an
// old command never replaces a newer.

#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "sim/plant/actuator_command.h"

namespace topay::simproc {

struct CommandTimelineOptions {
  /// A stamp further ahead of the wall clock is taken as now, us. The simulator's publishers run
  /// on its machine (one clock), so a true stamp is never ahead; a corrupted copy that still
  /// decodes can then hold back the true commands after it for this long at most.
  std::int64_t max_lead_us = 2'000;
  std::int64_t behind_us = 10'000;    ///< a command stamped this far ahead of the plant counts as caught up, us
  std::size_t max_pending = 4096;     ///< commands kept waiting at most (beyond: the oldest dropped)
};

struct CommandTimelineCounts {
  std::int64_t received = 0;
  std::int64_t caught_up = 0;     ///< stamped behind_us or more ahead of the plant (it had stalled)
  std::int64_t largest_lead_us = 0;  ///< the most a stamp was ahead of the plant on arrival, us
  std::int64_t restamped = 0;     ///< stamped more than max_lead_us ahead: taken as now
  std::int64_t out_of_order = 0;  ///< stamped before a command already taken or waiting: dropped
  std::int64_t overflowed = 0;    ///< the oldest waiting dropped because max_pending were waiting
};

class CommandTimeline {
 public:
  explicit CommandTimeline(const CommandTimelineOptions& options = {}) : options_(options) {}

  /// A command that arrived at wall_utime, the plant's last step at plant_utime. Returns "" when
  /// kept, else why it was dropped.
  std::string Push(std::int64_t stamp_utime, const sim::ActuatorCommand& command, std::int64_t plant_utime,
                   std::int64_t wall_utime);

  /// Moves the commands due at the step of step_utime (stamp <= step_utime) to *due, oldest first
  /// (the plant takes each in turn; the last one stands). *due is cleared first.
  void TakeDue(std::int64_t step_utime, std::vector<sim::ActuatorCommand>* due);

  std::size_t pending() const { return pending_.size(); }
  const CommandTimelineCounts& counts() const { return counts_; }
  /// "commands 12034: 812 caught up after stalls (up to 0.412 s), 0 restamped, 1 out of order, 0 overflowed"
  std::string Report() const;

 private:
  struct Stamped {
    std::int64_t stamp_utime;
    sim::ActuatorCommand command;
  };

  CommandTimelineOptions options_;
  std::deque<Stamped> pending_;           // in stamp order
  std::int64_t last_stamp_utime_ = std::numeric_limits<std::int64_t>::min();  // the newest stamp kept so far
  CommandTimelineCounts counts_;
};

}  // namespace topay::simproc
