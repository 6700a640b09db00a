#pragma once
// The faults topay-faults injects into the running demo graph (config/graphs/demo.yaml: the
// closed-loop mission through CAN), what each does and what the stack must do about it. One
// episode = one injection during a mission, measured from the graph's bus (fault_episode.h).

#include <string>
#include <vector>

namespace topay::tools {

enum class FaultFamily {
  kKill,     ///< SIGKILL of one process of the graph (the launcher must restart it)
  kCan,      ///< a CAN fault in the motor simulator (MOTORSIM_FAULT, run time)
  kLcm,      ///< the LCM bus: lost, reordered or stale messages, a frozen map, a goal flood
  kGoal,     ///< hostile goals to the planner (GOAL)
  kHostile,  ///< oversized and malformed payloads on every channel
};

struct FaultSpec {
  std::string name;            ///< e.g. "kill-tracker", "can-bus-off"
  FaultFamily family = FaultFamily::kKill;
  std::string target;          ///< kKill: the graph process ("tracker"); else empty
  std::string what;            ///< what is injected, one line
  std::string expected;        ///< the safe reaction the stack must show, one line
  double hold_s = 0.0;         ///< how long the fault lasts before it is cleared (0: at once)
  /// The drives must be commanded to stop (the bridge STOPPED/FAULT, or every drive command 0);
  /// the episode's time to the safe state is measured to that.
  bool stop_expected = false;
  /// The command stream to the bridge is what is lost: the time to the safe state is measured
  /// from the last CONTROL_COMMAND on the bus (the 100 ms), not from the injection.
  bool from_last_command = false;
  /// The stop must begin within the 100 ms (kill-tracker: of the last command; kill-canbridge:
  /// of the kill, the drives' own watchdogs).
  bool stop_within_limit = false;
  bool ends_mission = false;   ///< the mission cannot go on (kill of the mission process)
  bool operator_reset = false; ///< needs FAULT_RESET on DRIVE_COMMAND (sent by the tool, as an operator)
  /// The planner must fail the tool's goal with a reason (PLANNER_STATUS FAILED): no recovery
  /// counts before it has (on a loaded machine the robot may drive on before the status comes).
  bool refusal_expected = false;
};

/// Every fault, in the order of the report.
std::vector<FaultSpec> FaultCatalog();

/// The faults named in `names` (all when empty). Throws std::invalid_argument naming an unknown
/// name and listing the known ones.
std::vector<FaultSpec> SelectFaults(const std::vector<std::string>& names);

std::string FamilyName(FaultFamily family);

}  // namespace topay::tools
