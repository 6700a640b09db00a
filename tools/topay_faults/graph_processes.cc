#include "graph_processes.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace topay::tools {
namespace {

struct ProcStat {
  pid_t pid = 0;
  pid_t parent = 0;
  char state = '?';
  unsigned long long start_ticks = 0;
  std::string comm;
};

// /proc/<pid>/stat: "pid (comm) state ppid ... starttime(22nd field) ..."; comm may hold spaces
// and parentheses, so it is taken up to the last ')'.
bool ReadStat(pid_t pid, ProcStat* stat) {
  std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(file, text)) return false;
  const std::size_t open = text.find('('), close = text.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  stat->pid = pid;
  stat->comm = text.substr(open + 1, close - open - 1);
  std::istringstream rest(text.substr(close + 1));
  rest >> stat->state >> stat->parent;
  std::string field;
  for (int i = 5; i < 22 && rest >> field; ++i) {
  }
  rest >> stat->start_ticks;
  return static_cast<bool>(rest);
}

}  // namespace

std::map<std::string, pid_t> DescendantProcesses(pid_t ancestor) {
  std::map<pid_t, ProcStat> all;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    ProcStat stat;
    if (ReadStat(static_cast<pid_t>(std::stol(name)), &stat)) all[stat.pid] = stat;
  }
  std::map<std::string, pid_t> found;
  std::map<std::string, unsigned long long> started;
  for (const auto& [pid, stat] : all) {
    if (stat.state == 'Z' || stat.state == 'X') continue;
    bool descends = false;
    for (pid_t up = stat.parent; up > 1 && !descends; up = all.count(up) ? all[up].parent : 0) {
      descends = up == ancestor;
    }
    if (!descends) continue;
    if (!found.count(stat.comm) || stat.start_ticks > started[stat.comm]) {
      found[stat.comm] = pid;
      started[stat.comm] = stat.start_ticks;
    }
  }
  return found;
}

std::map<std::string, pid_t> GraphProcesses(pid_t ancestor) {
  std::map<std::string, pid_t> graph = DescendantProcesses(ancestor);
  std::erase_if(graph, [](const auto& entry) { return entry.first != "lcm-logger" && !entry.first.starts_with("topay-"); });
  return graph;
}

std::string CommandNameOf(const std::string& graph_process) {
  return graph_process == "logger" ? "lcm-logger" : "topay-" + graph_process;
}

}  // namespace topay::tools
