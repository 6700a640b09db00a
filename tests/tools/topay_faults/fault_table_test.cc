// The fault-injection tables: per fault the median and max times over its episodes, recoveries,
// refused injections; every episode in the episode table.

#include <gtest/gtest.h>

#include "tools/topay_faults/fault_table.h"

namespace topay::tools {
namespace {

EpisodeResult Episode(double safe_ms, bool recovered, double recover_s) {
  EpisodeResult e;
  e.fault = "can-bus-off";
  e.injected = true;
  e.safe_ms = safe_ms;
  e.safe_evidence = "bridge STOPPED: bus-off";
  e.recovered = recovered;
  e.recover_s = recover_s;
  return e;
}

TEST(FaultTable, SummarisesEachFaultsEpisodes) {
  FaultSpec f;
  f.name = "can-bus-off";
  EpisodeResult refused;
  refused.fault = "can-bus-off";
  refused.notes = "no MOTORSIM";
  std::vector<EpisodeResult> episodes = {Episode(10, true, 2.0), Episode(30, true, 4.0), Episode(50, false, -1),
                                         refused};
  episodes[0].zero_ms = 200;  // the stop ramps ended: two of three seen
  episodes[1].zero_ms = 400;
  const std::string table = FaultSummaryTable({f}, episodes);
  EXPECT_NE(table.find("| can-bus-off | 3 (1 not injected) | bridge STOPPED: bus-off x3 | 30 / 50 | 300 / 400 | 2 / 3 | 3.0 / 4.0 | 0 | 0 |"),
            std::string::npos)
      << table;
  const std::string rows = EpisodeTable(episodes);
  EXPECT_NE(rows.find("| can-bus-off | 0 | no: no MOTORSIM |"), std::string::npos) << rows;
}

TEST(FaultTable, AFaultWithoutEpisodesShowsDashes) {
  FaultSpec f;
  f.name = "kill-logger";
  EXPECT_NE(FaultSummaryTable({f}, {}).find("| kill-logger | 0 | - | - | - | 0 / 0 | - | 0 | 0 |"), std::string::npos);
}

}  // namespace
}  // namespace topay::tools
