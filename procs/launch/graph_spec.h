#pragma once
// The process graph file (config/graphs/*.yaml) as data: processes, their commands and
// environment, dependencies, restart policies, heartbeat supervision and real-time settings.
// docs/running.md documents every key.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace topay::launch {

/// A bad graph file. what() names the file, the line and the field, e.g.
/// "config/graphs/sim.yaml:12: processes[1] (planner).depends_on: unknown process 'mappr'".
class GraphError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class RestartPolicy { kNever, kOnFailure, kAlways };
const char* ToString(RestartPolicy policy);

/// Applied to the child between fork and exec where permitted; the launcher checks each and
/// warns about what did not take effect (e.g. SCHED_FIFO without CAP_SYS_NICE).
struct RealtimeSettings {
  std::optional<int> nice;           ///< nice level -20..19 (unset: inherited)
  std::optional<int> fifo_priority;  ///< SCHED_FIFO priority 1..99 (unset: SCHED_OTHER)
  std::vector<int> cpus;             ///< CPU affinity (empty: every CPU)
  bool mlockall = false;  ///< lock memory: set as TOPAY_MLOCKALL=1, done by the process itself
};

struct ProcessSpec {
  std::string name;                         ///< unique in the graph; the heartbeat's name
  std::string command;                      ///< executable (PATH is searched), required
  std::vector<std::string> args;            ///< arguments
  std::map<std::string, std::string> env;   ///< added to the launcher's environment
  std::string working_dir;                  ///< empty: the launcher's working directory
  std::vector<std::string> depends_on;      ///< started after these are ready
  RestartPolicy restart = RestartPolicy::kOnFailure;  ///< default on-failure
  double restart_delay_s = 0.1;       ///< first restart delay; doubles per consecutive failure
  double restart_delay_max_s = 5.0;   ///< cap of the exponential backoff
  int max_restarts = -1;              ///< -1: unlimited
  bool heartbeat = true;              ///< supervised by HEARTBEAT (false: ready once started)
  /// How late a heartbeat may be: the process is reported silent and restarted after
  /// heartbeat_period_s + heartbeat_timeout_s without one (default 3 s late, i.e. 4 s silent). A
  /// heartbeat is the bus's HEARTBEAT or the watchdog datagram on the launcher's local socket
  /// (procs/runtime/watchdog_notify.h), which a lossy bus cannot lose (with 2 s, and once with
  /// 4 s, lost datagrams of a 10 %-lossy bus killed working processes: docs/reliability.md); a
  /// dead process is seen by its exit at once.
  double heartbeat_timeout_s = 3.0;
  double startup_timeout_s = 5.0;     ///< time allowed to the first heartbeat
  double ready_delay_s = 0.3;  ///< without heartbeat: counted ready this long after its start
  std::string group;                  ///< label; --group GROUP starts only those groups
  bool autostart = true;              ///< false: started only when its group is selected
  std::vector<std::string> publishes; ///< channels it publishes (left out of a replay)
  /// The graph's job (e.g. a mission): once it exits for good (not restarted), the launcher
  /// stops the graph and exits with its exit code (128 + signal if it was killed).
  bool ends_graph = false;
  RealtimeSettings realtime;
};

struct GraphSpec {
  std::string file;            ///< path it was loaded from
  std::string name;            ///< default: the file's stem
  bool isolated = false;       ///< default of --isolated: a private network namespace
  std::string lcm_url;         ///< LCM_DEFAULT_URL for the children (empty: inherited)
  double grace_period_s = 3.0; ///< SIGTERM -> SIGKILL on stop, s
  double heartbeat_period_s = 1.0;  ///< the processes' heartbeat period (the stack's 1 Hz), s
  std::string run_root = "out/runs";   ///< run folders are <run_root>/<date-time>/
  std::vector<ProcessSpec> processes;  ///< in start order (dependencies first)
};

/// Values of ${VAR} in command, args, env and working_dir.
struct GraphVariables {
  std::map<std::string, std::string> values;  ///< e.g. BIN_DIR, GRAPH_DIR, RUN_DIR
};

/// Loads and validates a graph file: unknown keys, wrong types, a missing command, duplicate
/// names, unknown dependencies, dependency cycles and values out of range are GraphErrors.
/// Processes come back in a start order that respects depends_on (file order otherwise).
/// Variables are not expanded here (ExpandVariables).
GraphSpec LoadGraph(const std::string& path);

/// As LoadGraph, from the graph file's text: `path` stands for the file (GraphSpec::file, the
/// default name and every GraphError name it). Malformed YAML is a GraphError too.
GraphSpec ParseGraph(const std::string& yaml_text, const std::string& path);

/// Replaces ${NAME} in every command, argument, environment value and working directory.
/// Throws GraphError naming the process and field for an unknown variable.
void ExpandVariables(const GraphVariables& variables, GraphSpec* graph);

/// Keeps the processes of `groups` (none given: every process with autostart) and everything
/// they depend on, start order kept.
void SelectGroups(const std::vector<std::string>& groups, GraphSpec* graph);

/// Drops the processes of `groups` (e.g. the demo's viewer: `--without viewer`). Throws
/// GraphError naming both if a process that stays depends on one that goes.
void ExcludeGroups(const std::vector<std::string>& groups, GraphSpec* graph);

}  // namespace topay::launch
