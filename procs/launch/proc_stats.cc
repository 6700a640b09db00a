#include "procs/launch/proc_stats.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace topay::launch {

std::optional<ProcSample> ReadProcSample(pid_t pid) {
  std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(file, text)) return std::nullopt;
  // The command name (field 2) is in parentheses and may hold spaces: parse after the last ')'.
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos) return std::nullopt;
  std::istringstream rest(text.substr(close + 2));
  ProcSample sample;
  rest >> sample.state;
  // Fields 4..24 follow the state (field 3); utime is field 14, stime 15, rss 24.
  std::string skip;
  for (int field = 4; field < 14; ++field) rest >> skip;
  long long utime = 0, stime = 0, rss_pages = 0;
  rest >> utime >> stime;
  for (int field = 16; field < 24; ++field) rest >> skip;
  rest >> rss_pages;
  if (!rest) return std::nullopt;
  const double ticks = static_cast<double>(sysconf(_SC_CLK_TCK));
  sample.cpu_time_s = static_cast<double>(utime + stime) / ticks;
  sample.rss_kB = rss_pages * (sysconf(_SC_PAGESIZE) / 1024);
  return sample;
}

bool ProcessAlive(pid_t pid) {
  const std::optional<ProcSample> sample = ReadProcSample(pid);
  return sample.has_value() && sample->state != 'Z' && sample->state != 'X';
}

}  // namespace topay::launch
