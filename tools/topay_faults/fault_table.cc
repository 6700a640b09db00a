#include "fault_table.h"

#include <map>

#include <fmt/format.h>

#include "tools/report/sample_stats.h"

namespace topay::tools {
namespace {

// "median / max" of the samples, or "-" for none.
std::string MedianMax(const std::vector<double>& samples, const char* format) {
  if (samples.empty()) return "-";
  return fmt::format(fmt::runtime(std::string(format) + " / " + format), report::Percentile(samples, 50.0),
                     report::Max(samples));
}

// The safe evidence seen most often, without its numbers (e.g. "bridge STOPPED: stale command").
std::string CommonEvidence(const std::vector<const EpisodeResult*>& episodes) {
  std::map<std::string, int> counts;
  for (const EpisodeResult* e : episodes) {
    std::string evidence = e->safe_ms >= 0.0 ? e->safe_evidence : "no stop";
    const std::size_t paren = evidence.find(" (");
    if (paren != std::string::npos) evidence.resize(paren);
    ++counts[evidence];
  }
  std::string text;
  for (const auto& [evidence, n] : counts) text += fmt::format("{}{} x{}", text.empty() ? "" : "; ", evidence, n);
  return text.empty() ? "-" : text;
}

std::string Cell(std::string text) {
  for (char& c : text) {
    if (c == '|' || c == '\n') c = ' ';
  }
  return text;
}

}  // namespace

std::string FaultSummaryTable(const std::vector<FaultSpec>& faults, const std::vector<EpisodeResult>& episodes) {
  std::string table =
      "| fault | runs | reaction seen (count) | to safe state ms, median / max | every drive at 0 ms, median / max "
      "| recovered | to recovery s, median / max | other restarts | contacts |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const FaultSpec& fault : faults) {
    std::vector<const EpisodeResult*> runs;
    int refused = 0;
    for (const EpisodeResult& e : episodes) {
      if (e.fault != fault.name) continue;
      if (e.injected) runs.push_back(&e); else ++refused;
    }
    std::vector<double> safe_ms, zero_ms, recover_s;
    int recovered = 0, restarts = 0;
    long contacts = 0;
    for (const EpisodeResult* e : runs) {
      if (e->safe_ms >= 0.0) safe_ms.push_back(e->safe_ms);
      if (e->zero_ms >= 0.0) zero_ms.push_back(e->zero_ms);
      if (e->recovered) ++recovered, recover_s.push_back(e->recover_s);
      restarts += e->other_restarts;
      contacts += static_cast<long>(e->contacts);
    }
    table += fmt::format("| {} | {}{} | {} | {} | {} | {} / {} | {} | {} | {} |\n", fault.name, runs.size(),
                         refused > 0 ? fmt::format(" ({} not injected)", refused) : "", Cell(CommonEvidence(runs)),
                         MedianMax(safe_ms, "{:.0f}"), MedianMax(zero_ms, "{:.0f}"), recovered, runs.size(), MedianMax(recover_s, "{:.1f}"),
                         restarts, contacts);
  }
  return table;
}

std::string EpisodeTable(const std::vector<EpisodeResult>& episodes) {
  std::string table = "| fault | seed | injected | safe ms | recovered s | contacts | reaction |\n|---|---|---|---|---|---|---|\n";
  for (const EpisodeResult& e : episodes) {
    table += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", e.fault, e.seed, e.injected ? "yes" : "no: " + Cell(e.notes),
                         e.safe_ms >= 0.0 ? fmt::format("{:.0f}", e.safe_ms) : "-",
                         e.recovered ? fmt::format("{:.1f}", e.recover_s) : "no", e.contacts, Cell(e.reaction));
  }
  return table;
}

}  // namespace topay::tools
