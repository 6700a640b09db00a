#pragma once
// CPU time and resident memory of a running process, from /proc/<pid>/stat.

#include <sys/types.h>

#include <cstdint>
#include <optional>

namespace topay::launch {

struct ProcSample {
  double cpu_time_s = 0.0;  ///< user + system time so far, seconds
  std::int64_t rss_kB = 0;  ///< resident set size, KiB
  char state = '?';         ///< R, S, D, T (stopped), Z (zombie), ...
};

/// nullopt if the process does not exist (or /proc cannot be read).
std::optional<ProcSample> ReadProcSample(pid_t pid);

/// True if `pid` exists and is not a zombie.
bool ProcessAlive(pid_t pid);

}  // namespace topay::launch
