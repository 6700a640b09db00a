#pragma once
// The supervisor's record of one process and of one output pipe (private to supervisor*.cc).

#include <sys/types.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "procs/launch/supervisor.h"

namespace topay::launch {

struct Supervisor::Process {
  ProcessSpec spec;
  int index = 0;
  ProcState state = ProcState::kWaiting;
  pid_t pid = 0;
  std::ofstream log;
  int restarts = 0;
  int consecutive_failures = 0;
  bool ever_ready = false;     // first heartbeat seen (dependencies may start)
  bool killed_silent = false;  // killed for a missing heartbeat: counts as a failure
  bool term_sent = false;
  Clock::time_point started, last_heartbeat, restart_at;
  std::int8_t health = -1;
  std::string status;
  double cpu_percent = 0.0, last_cpu_s = 0.0;
  std::int64_t rss_kB = 0;
  Clock::time_point last_cpu_at;

  bool alive() const { return pid > 0; }
};

struct Supervisor::Stream {
  int fd = -1;
  Process* process = nullptr;
  std::string partial;
};

}  // namespace topay::launch
