#pragma once
// topay-faults' work: the closed-loop pick-and-place mission (config/graphs/demo.yaml, through
// CAN) run again and again, each run hosting fault episodes one after another, until every
// chosen fault has been injected `runs` times. The tool is in the graph's private network
// namespace (it launches the graph there with --no-isolated), so it sees and speaks on the
// graph's bus. Each mission's folder keeps the graph's log and every process's log.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "fault_catalog.h"
#include "fault_episode.h"

namespace topay::tools {

struct FaultCampaignOptions {
  std::vector<FaultSpec> faults;        ///< what to inject (FaultCatalog() by default)
  int runs = 20;                        ///< episodes per fault
  std::vector<std::uint64_t> seeds = {1, 5, 7, 8};  ///< mission rooms, cycled (rooms the mission succeeds in)
  std::string out_dir = "out/faults";   ///< mission folders <out>/mission-<k>/
  std::string graph_file;               ///< config/graphs/demo.yaml
  std::string bin_dir;                  ///< topay-launch, topay-scenario
  double mission_timeout_s = 900.0;     ///< a graph still running after this long is stopped
  int episodes_per_mission = 8;         ///< then a fault that ends the mission (kill -9 of it), if one is due
  int max_missions = 0;                 ///< stop after this many missions (0: 2 x faults x runs)
  std::vector<EpisodeResult> earlier;   ///< episodes of an earlier run (--resume): counted, not run again
  int first_mission = 1;                ///< the first mission folder's number (after an earlier run's)
  FaultEpisodeOptions episode;
};

/// One mission of the campaign.
struct CampaignMission {
  int index = 0;
  std::uint64_t seed = 0;
  std::string run_dir;
  int launcher_exit_code = -1;
  std::string note;        ///< why it did not run, if it did not
};

struct CampaignResult {
  std::vector<EpisodeResult> episodes;  ///< the earlier ones first, then this run's
  std::vector<CampaignMission> missions;
  bool interrupted = false;
};

/// Runs the campaign (call inside a private network namespace: the graph's bus is joined here)
/// until every fault has `runs` episodes, counting `earlier` ones.
/// Progress lines go to `progress`; `stop_requested` is polled (true: the graph is stopped and
/// the campaign ends with what it has). Throws std::runtime_error if the graph file cannot be read.
CampaignResult RunFaultCampaign(const FaultCampaignOptions& options, std::ostream& progress,
                                const std::function<bool()>& stop_requested);

}  // namespace topay::tools
