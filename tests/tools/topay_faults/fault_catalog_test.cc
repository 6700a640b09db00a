// The fault catalogue: every process of the demo graph is killed by one fault (the viewer
// aside: it is left out of fault runs), every family of issue 22 is there, names are unique,
// an unknown name is refused naming it.

#include <gtest/gtest.h>

#include <set>

#include "procs/launch/graph_spec.h"
#include "tools/topay_faults/fault_catalog.h"

namespace topay::tools {
namespace {

TEST(FaultCatalog, KillsEveryProcessOfTheDemoGraphButTheViewer) {
  const launch::GraphSpec graph = launch::LoadGraph(std::string(TOPAY_SOURCE_DIR) + "/config/graphs/demo.yaml");
  std::set<std::string> killed;
  for (const FaultSpec& f : FaultCatalog()) {
    if (f.family == FaultFamily::kKill) killed.insert(f.target);
  }
  for (const launch::ProcessSpec& p : graph.processes) {
    if (p.group == "viewer") continue;
    EXPECT_TRUE(killed.count(p.name)) << p.name << " is never killed";
  }
}

TEST(FaultCatalog, HasEveryFamilyAndUniqueNames) {
  std::set<std::string> names;
  std::set<FaultFamily> families;
  for (const FaultSpec& f : FaultCatalog()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    families.insert(f.family);
    EXPECT_FALSE(f.what.empty());
    EXPECT_FALSE(f.expected.empty());
  }
  EXPECT_EQ(families.size(), 5u);
  for (const char* name : {"can-loss", "can-delay", "can-drive-fault", "can-heartbeat-loss", "can-bus-off",
                           "lcm-drop", "lcm-reorder", "lcm-stale-localisation", "lcm-map-frozen", "lcm-goal-flood",
                           "goal-nan", "goal-unreachable", "goal-in-obstacle", "goal-every-50ms", "hostile-payloads"}) {
    EXPECT_TRUE(names.count(name)) << name;
  }
}

TEST(FaultCatalog, SelectsByNameAndRefusesAnUnknownOne) {
  const std::vector<FaultSpec> chosen = SelectFaults({"can-bus-off", "kill-tracker"});
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(chosen[1].target, "tracker");
  EXPECT_TRUE(chosen[1].from_last_command);
  EXPECT_TRUE(chosen[1].stop_within_limit);
  // The 100 ms for the two command streams a kill cuts: the tracker's and the bridge's.
  const FaultSpec bridge = SelectFaults({"kill-canbridge"})[0];
  EXPECT_TRUE(bridge.stop_within_limit);
  EXPECT_FALSE(bridge.from_last_command);
  EXPECT_FALSE(SelectFaults({"kill-motorsim"})[0].stop_within_limit);
  EXPECT_EQ(SelectFaults({}).size(), FaultCatalog().size());
  try {
    SelectFaults({"kill-everything"});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown fault 'kill-everything'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("kill-tracker"), std::string::npos);
  }
}

}  // namespace
}  // namespace topay::tools
