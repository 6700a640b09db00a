#pragma once
// The tracker's watch on the planner whose trajectories it follows (docs/tracker.md, fault
// campaign finding 24). The planner guards the trajectory the robot is on: it checks the rest of
// it against every map update and replans, or publishes a stop, when it collides. A planner that
// was killed and restarted knows nothing of the trajectories its predecessor published (they
// were planned on an older map and nobody checks them any more), and a planner gone silent
// checks nothing: in both cases the tracker must stop driving on them. The watch reads the
// planner's HEARTBEAT (1 Hz, every process's) by process name and tells
//  - a restart: a heartbeat of another process id that is a new process (its seq counts from 0
//    again: lower than the last one seen) or comes after the last instance fell silent for more
//    than kSameInstanceGapS; a stray or corrupted copy of a heartbeat with another pid but the
//    seq of the live planner is not a restart (counted, ignored);
//  - a silence: no heartbeat of the planner for options.silence_s, once it has been heard.
// It never engages before a planner has been heard (a tracker fed by a test or a tool).

#include <cstdint>
#include <string>
#include <vector>

#include "topay/heartbeat_t.hpp"

namespace topay::tracker {

struct PlannerWatchOptions {
  /// The heartbeat process names of the planner: the graphs' name (`planner`) and the
  /// program's own (`topay-planner`, run by hand). Empty: no watch.
  std::vector<std::string> process_names = {"planner", "topay-planner"};
  /// A planner heard before and silent for longer than this (s) guards nothing: the tracker
  /// brakes. Three heartbeat periods (one lost heartbeat, or a 10 % datagram loss, is not a
  /// silence). 0: never. >= 0.
  double silence_s = 3.0;
};

class PlannerWatch {
 public:
  /// A heartbeat of another pid this long after the last one of the known planner is a new
  /// planner even if its seq is not lower (the previous one died soon after its start).
  static constexpr double kSameInstanceGapS = 1.5;

  enum class Event { kNone, kFirstHeard, kRestarted, kIgnored };

  explicit PlannerWatch(PlannerWatchOptions options) : options_(std::move(options)) {}

  /// One HEARTBEAT (any process's) received at now_utime (us, the receiver's clock).
  Event OnHeartbeat(const heartbeat_t& msg, std::int64_t now_utime);
  /// True if the planner was heard and has been silent for more than silence_s at now_utime.
  bool Silent(std::int64_t now_utime) const;

  bool heard() const { return heard_; }
  std::int32_t pid() const { return pid_; }
  std::int32_t previous_pid() const { return previous_pid_; }
  std::int64_t restarts() const { return restarts_; }
  std::int64_t ignored() const { return ignored_; }
  /// Seconds since the planner's last heartbeat at now_utime (0 if never heard).
  double SilenceS(std::int64_t now_utime) const;

 private:
  bool IsPlanner(const std::string& name) const;

  PlannerWatchOptions options_;
  bool heard_ = false;
  std::int32_t pid_ = 0, previous_pid_ = 0;
  std::int64_t seq_ = 0;
  std::int64_t last_utime_ = 0;
  std::int64_t restarts_ = 0, ignored_ = 0;
};

}  // namespace topay::tracker
