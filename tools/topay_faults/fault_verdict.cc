#include "fault_verdict.h"

#include <fmt/format.h>

namespace topay::tools {
namespace {

bool ClearFailure(const EpisodeResult& e) {
  return e.reaction.find("mission FAILED") != std::string::npos || e.reaction.find("graph ended") != std::string::npos;
}

void Check(const FaultSpec& fault, const EpisodeResult& e, std::vector<std::string>* out) {
  const std::string who = fmt::format("{} (room seed {})", e.fault, e.seed);
  if (!e.injected) {
    out->push_back(who + ": could not be injected: " + e.notes);
    return;
  }
  if (e.contacts > 0) out->push_back(fmt::format("{}: {} ground-truth contact(s)", who, e.contacts));
  if (e.other_restarts > 0) out->push_back(fmt::format("{}: {} other process(es) died: {}", who, e.other_restarts, e.reaction));
  if (fault.stop_expected && e.safe_ms < 0.0) out->push_back(who + ": the drives were not commanded to stop");
  if (fault.stop_within_limit && e.safe_ms > kCommandLossStopLimitMs) {
    out->push_back(fmt::format("{}: stopped {:.0f} ms after {} (limit {:.0f} ms)", who, e.safe_ms,
                               fault.from_last_command ? "the last command" : "the fault", kCommandLossStopLimitMs));
  }
  if (!e.recovered && !ClearFailure(e)) out->push_back(who + ": neither recovered nor a clear failure: " + e.reaction);
}

}  // namespace

std::vector<std::string> Violations(const std::vector<FaultSpec>& faults, const std::vector<EpisodeResult>& episodes) {
  std::vector<std::string> violations;
  for (const EpisodeResult& e : episodes) {
    for (const FaultSpec& f : faults) {
      if (f.name == e.fault) Check(f, e, &violations);
    }
  }
  return violations;
}

}  // namespace topay::tools
