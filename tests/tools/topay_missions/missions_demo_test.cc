// The closed-loop demo end to end, as `make demo` runs it: topay-missions runs one seed's
// pick-and-place mission (topay-scenario's room and mission, the demo graph through
// topay-launch, isolated: sim, director, mapper, planner, tracker, mission, logger) and reports
// it. Asserted: the whole pipeline ran (scenario, graph, report, results), the robot reached
// the pickup above a table top through the closed loop, the simulator's collision monitor saw
// no contact, and the exit code and results agree with the mission's result. Whether the whole
// mission succeeds is NOT asserted: on two shared cores under the test suite's load, plans out
// of the tight table-top poses sometimes fail (the success rate over seeds is measured by
// `make missions`, docs/benchmarks.md "Closed-loop missions"). Skipped, with the reason, where
// the launcher cannot make a private network namespace. About 1-3 minutes.
// Runs only under `make test-demo` (TOPAY_DEMO_TEST=1), not in `make test`: in one of its first
// CI runs the robot touched the scripted box (a planner start-state bug, fixed since, with the
// rest of that run's drift replans still under study; docs/demo.md "Known problems"), and the
// two-goal closed-loop mission test (MissionGraph) is CI's closed-loop check.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/common/tool_test.h"

namespace topay {
namespace {

class MissionsDemo : public ToolTest {
 protected:
  MissionsDemo() : ToolTest("topay-missions") {}
};

TEST_F(MissionsDemo, OneSeedRunsThroughTheWholeGraphWithoutContactAndIsReported) {
  const char* enabled = std::getenv("TOPAY_DEMO_TEST");
  if (enabled == nullptr || std::string(enabled) != "1") {
    GTEST_SKIP() << "the end-to-end demo runs under `make test-demo` (TOPAY_DEMO_TEST=1), not in make test";
  }
  // Kept after the test (the log, the plots and every process's log are its artefacts).
  const std::string out = std::string(TOPAY_BINARY_DIR) + "/test_out/tools/MissionsDemo";
  std::filesystem::remove_all(out);
  const RunResult r = Run("--seeds 1 --first-seed 1 --timeout-s 400 --out '" + out + "'");
  const std::string launcher = ReadText(out + "/seed-1/launcher.out");
  if (launcher.find("cannot create a private network namespace") != std::string::npos) {
    GTEST_SKIP() << "topay-launch: cannot create a private network namespace (see " << out << "/seed-1/launcher.out)";
  }
  const std::string logs = r.out + "\n--- stderr\n" + r.err + "\n--- launcher\n" + launcher;
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << logs;  // not a file, usage or interrupt error
  const nlohmann::json results = nlohmann::json::parse(ReadText(out + "/results.json"));
  ASSERT_EQ(results["runs"].size(), 1u);
  const nlohmann::json& run = results["runs"][0];
  const std::string result = run["result"];
  EXPECT_TRUE(result == "SUCCEEDED" || result == "FAILED") << logs;  // the mission ended by itself
  EXPECT_EQ(run["contact_events"], 0) << logs;
  EXPECT_EQ(r.exit_code == 0, run["success"].get<bool>()) << logs;
  EXPECT_EQ(run["success"].get<bool>(), result == "SUCCEEDED") << logs;
  const nlohmann::json summary = nlohmann::json::parse(ReadText(out + "/seed-1/summary.json"));
  EXPECT_EQ(summary["mission"]["result"], result);
  EXPECT_GT(summary["distance_driven_m"].get<double>(), 1.0);
  for (const char* file : {"path.png", "time_plots.png", "graph.lcmlog", "mission.yaml", "room.json", "mission.log"}) {
    const std::string path = out + "/seed-1/" + file;
    EXPECT_TRUE(std::filesystem::exists(path) && std::filesystem::file_size(path) > 100) << path;
  }
  // Progress was printed, and the closed loop brought the end effector to the pickup.
  EXPECT_NE(r.out.find("step 1/6: goto pickup"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("step 1/6 done"), std::string::npos) << logs;
  EXPECT_NE(r.out.find("missions succeeded without contact"), std::string::npos) << r.out;
}

TEST_F(MissionsDemo, UsageErrorsExit2) {
  EXPECT_EQ(Run("--seeds 0").exit_code, 2);
  EXPECT_EQ(Run("--first-seed -3").exit_code, 2);
  EXPECT_EQ(Run("--graph /nonexistent.yaml").exit_code, 2);
}

}  // namespace
}  // namespace topay
