#pragma once
// One fault episode during a mission: wait until the robot moves under a running bridge (some
// drive's output not zero now, and above the moving threshold within 0.3 s), inject
// the fault, watch for the safe state (the bridge STOPPED or FAULT, or every drive commanded to
// 0, or the graph ended), clear the fault after its hold time, and watch for recovery (every
// process of the graph alive again, the bridge RUNNING, the robot moving or the mission a step
// further or done). Driven by Tick() from the tool's loop; the result says what was seen.

#include <cstdint>
#include <map>
#include <string>
#include <sys/types.h>

#include "fault_catalog.h"
#include "fault_injector.h"
#include "graph_monitor.h"

namespace topay::tools {

struct FaultEpisodeOptions {
  double ready_timeout_s = 60.0;    ///< give up waiting for the robot to move (not injected)
  double recover_timeout_s = 45.0;  ///< after the fault is cleared: not recovered after this long
  double settle_s = 2.0;            ///< after recovery, before the next episode
  double reset_after_s = 1.0;       ///< an operator's FAULT_RESET this long after a FAULT, then every 0.5 s
};

struct EpisodeResult {
  std::string fault;
  std::uint64_t seed = 0;
  bool injected = false;
  bool refused = false;           ///< the injector could not inject it (notes say why)
  std::string notes;              ///< what the injector did, or why it could not
  double safe_ms = -1.0;          ///< reference -> safe state, ms (-1: no stop seen)
  std::string safe_evidence;      ///< what showed the safe state
  double zero_ms = -1.0;          ///< reference -> every drive's output at 0, ms (-1: not seen)
  bool recovered = false;
  double recover_s = -1.0;        ///< injection -> recovery, s (-1: not recovered)
  std::string reaction;           ///< what the graph did, readable
  int other_restarts = 0;         ///< processes other than the target that came back with a new pid
  std::int64_t contacts = 0;      ///< ground-truth contacts that started during the episode
};

class FaultEpisode {
 public:
  FaultEpisode(const FaultSpec& fault, std::uint64_t seed, FaultInjector* injector, pid_t graph_ancestor,
               const FaultEpisodeOptions& options = {});

  /// Advances the episode with the monitor's view; true once it is over.
  bool Tick(const GraphView& view);
  /// The graph ended (the launcher exited with `exit_code`): the episode ends now.
  void GraphEnded(const GraphView& view, int exit_code);
  bool Injected() const { return result_.injected; }
  const EpisodeResult& Result() const { return result_; }

 private:
  enum class Phase { kWaitReady, kFault, kRecover, kSettle, kDone };

  bool Ready(const GraphView& view) const;
  void Inject(const GraphView& view);
  void WatchSafeState(const GraphView& view, double graph_end_s);
  void FindSafeState(const GraphView& view, double graph_end_s);
  void OperatorReset(const GraphView& view);
  // Notes the planner's answer to an injected goal: a refusal (FAILED naming it), or that it
  // took the goal (PLANNING naming it).
  void WatchPlannerGoal(const GraphView& view);
  bool Recovered(const GraphView& view);
  // Notes what recovery waits for (the report of an episode that timed out) and returns false.
  bool Awaiting(std::string what);
  void Finish(const GraphView& view, const std::string& outcome);
  void AddReaction(const std::string& text);

  FaultSpec fault_;
  FaultInjector* injector_;
  pid_t ancestor_;
  FaultEpisodeOptions options_;
  EpisodeResult result_;
  Phase phase_ = Phase::kWaitReady;
  double start_s_ = -1.0;
  double inject_s_ = 0.0;
  double safe_reference_s_ = 0.0;  // what the safe state was timed from (the injection or the last command)
  double clear_s_ = 0.0;
  double recovered_at_s_ = 0.0;
  double last_reset_s_ = -1.0;
  double fault_seen_s_ = -1.0;
  int resets_sent_ = 0;
  std::int64_t contacts_at_start_ = 0;
  int mission_step_at_start_ = -1;
  std::map<std::string, pid_t> pids_at_start_;
  bool planner_failure_noted_ = false;
  std::string awaiting_;           // what recovery waits for (Recovered's last "no": for the report)
  bool tool_goal_taken_ = false;   // the planner's status named one of the injector's goals
  bool superseded_noted_ = false;  // ... and then the mission's goal (no refusal can come)
};

}  // namespace topay::tools
