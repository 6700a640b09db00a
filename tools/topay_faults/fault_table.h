#pragma once
// The fault-injection report: per fault, how many episodes were injected, the safe reaction
// seen most, the time to the safe state (median and max over the episodes that stopped), how
// many recovered and how fast, restarts of other processes and ground-truth contacts; and the
// episodes one by one, in Markdown (docs/reliability.md; the JSON file: fault_results_file.h).

#include <string>
#include <vector>

#include "fault_catalog.h"
#include "fault_episode.h"

namespace topay::tools {

/// The summary table, one row per fault of `faults` (in that order).
std::string FaultSummaryTable(const std::vector<FaultSpec>& faults, const std::vector<EpisodeResult>& episodes);

/// Every episode: fault, seed, safe time, recovery, reaction.
std::string EpisodeTable(const std::vector<EpisodeResult>& episodes);

}  // namespace topay::tools
