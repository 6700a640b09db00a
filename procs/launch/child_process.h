#pragma once
// Starting one child of the graph: its own process group, killed with the launcher
// (PR_SET_PDEATHSIG), output to a pipe, environment, working directory, real-time settings.

#include <signal.h>
#include <sys/types.h>

#include <map>
#include <string>
#include <vector>

#include "procs/launch/graph_spec.h"

namespace topay::launch {

struct SpawnedChild {
  pid_t pid = -1;      ///< also its process group id
  int output_fd = -1;  ///< read end of the pipe carrying its stdout and stderr (non-blocking)
};

/// Forks and execs spec.command with spec.args. In the child: a new process group, SIGKILL
/// when the launcher dies, stdin from /dev/null, stdout and stderr into one pipe,
/// `child_mask` as signal mask (the launcher's mask before it blocked its signals), the
/// environment plus spec.env and `extra_env`, the working directory and the real-time
/// settings (errors ignored there; see CheckRealtime). An exec failure exits with 127 after
/// writing the reason to the pipe. Throws std::system_error if fork or pipe fail.
SpawnedChild SpawnChild(const ProcessSpec& spec, const std::map<std::string, std::string>& extra_env,
                        const sigset_t& child_mask);

/// Compares what the running child got with spec.realtime; one warning text per setting that
/// did not take effect (e.g. "SCHED_FIFO 50 not applied (needs CAP_SYS_NICE)").
std::vector<std::string> CheckRealtime(const ProcessSpec& spec, pid_t pid);

/// Resolves `command` like execvp: a path with '/' must be executable, else PATH is searched.
/// Returns the empty string if not found.
std::string ResolveCommand(const std::string& command);

}  // namespace topay::launch
