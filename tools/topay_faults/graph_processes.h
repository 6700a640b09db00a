#pragma once
// The processes of a graph this tool started, found in /proc: every descendant of this process,
// by its command name (comm: "topay-planner", "lcm-logger"; at most 15 characters). The fault
// episodes use it to kill a process by name and to see restarts (a new pid under a name).

#include <map>
#include <string>
#include <sys/types.h>

namespace topay::tools {

/// comm -> pid of every live (not zombie) descendant of `ancestor`. A name that occurs twice
/// keeps the newest (largest start time) pid.
std::map<std::string, pid_t> DescendantProcesses(pid_t ancestor);

/// DescendantProcesses with graph processes' command names only ("topay-*", "lcm-logger"): what
/// an episode counts on to run again. A shell, a tool, or a child of this process not yet past
/// its exec (still under this process's name) is left out: one seen when a fault was injected
/// and gone later (exec'd under another name) was once waited for as a process that never came
/// back.
std::map<std::string, pid_t> GraphProcesses(pid_t ancestor);

/// The command name of a graph process (graph name "logger" -> "lcm-logger", else "topay-<name>").
std::string CommandNameOf(const std::string& graph_process);

}  // namespace topay::tools
