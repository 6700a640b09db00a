#include "procs/tracker/planner_watch.h"

#include <algorithm>

namespace topay::tracker {

bool PlannerWatch::IsPlanner(const std::string& name) const {
  return std::find(options_.process_names.begin(), options_.process_names.end(), name) !=
         options_.process_names.end();
}

PlannerWatch::Event PlannerWatch::OnHeartbeat(const heartbeat_t& msg, std::int64_t now_utime) {
  if (!IsPlanner(msg.process_name)) return Event::kNone;
  Event event = Event::kNone;
  if (!heard_) {
    event = Event::kFirstHeard;
  } else if (msg.pid != pid_) {
    const bool counts_again = msg.seq < seq_;
    const bool after_silence = SilenceS(now_utime) > kSameInstanceGapS;
    if (!counts_again && !after_silence) {
      ++ignored_;  // a stray or corrupted copy: the live planner keeps its place
      return Event::kIgnored;
    }
    ++restarts_;
    previous_pid_ = pid_;
    event = Event::kRestarted;
  } else if (msg.seq < seq_) {
    ++ignored_;  // an old copy (reordered, repeated) of the live planner's
    return Event::kIgnored;
  }
  heard_ = true;
  pid_ = msg.pid;
  seq_ = msg.seq;
  last_utime_ = now_utime;
  return event;
}

double PlannerWatch::SilenceS(std::int64_t now_utime) const {
  return heard_ ? 1e-6 * static_cast<double>(now_utime - last_utime_) : 0.0;
}

bool PlannerWatch::Silent(std::int64_t now_utime) const {
  return heard_ && options_.silence_s > 0.0 && SilenceS(now_utime) > options_.silence_s;
}

}  // namespace topay::tracker
