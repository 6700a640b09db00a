// The closed-loop demo end to end, as `make demo` runs it: topay-missions runs one seed's
// pick-and-place mission (topay-scenario's room and mission, the demo graph through
// topay-launch, isolated: sim, director, mapper, planner, tracker, mission, logger) and reports
// it. The mission must succeed with no ground-truth contact, the director's box must have
// appeared on the route, and the summary and plots must be written. Skipped, with the reason,
// where the launcher cannot make a private network namespace. About 1-3 minutes.

#include <gtest/gtest.h>

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

TEST_F(MissionsDemo, OneSeedsPickAndPlaceSucceedsAroundTheScriptedBoxWithoutContact) {
  // Kept after the test (the log, the plots and every process's log are its artefacts).
  const std::string out = std::string(TOPAY_BINARY_DIR) + "/test_out/tools/MissionsDemo";
  std::filesystem::remove_all(out);
  const RunResult r = Run("--seeds 1 --first-seed 1 --timeout-s 400 --out '" + out + "'");
  const std::string launcher = ReadText(out + "/seed-1/launcher.out");
  if (launcher.find("cannot create a private network namespace") != std::string::npos) {
    GTEST_SKIP() << "topay-launch: cannot create a private network namespace (see " << out << "/seed-1/launcher.out)";
  }
  const std::string logs = r.out + "\n--- stderr\n" + r.err + "\n--- launcher\n" + launcher;
  ASSERT_EQ(r.exit_code, 0) << logs;
  const nlohmann::json results = nlohmann::json::parse(ReadText(out + "/results.json"));
  ASSERT_EQ(results["runs"].size(), 1u);
  const nlohmann::json& run = results["runs"][0];
  EXPECT_EQ(run["result"], "SUCCEEDED") << logs;
  EXPECT_EQ(run["contact_events"], 0) << logs;
  EXPECT_EQ(run["boxes_appeared"], 1) << logs;
  EXPECT_GT(run["mission_time_s"].get<double>(), 10.0);
  EXPECT_LT(run["position_rms_m"].get<double>(), 0.05);
  for (const char* file : {"summary.json", "path.png", "time_plots.png", "graph.lcmlog", "mission.yaml", "room.json"}) {
    const std::string path = out + "/seed-1/" + file;
    EXPECT_TRUE(std::filesystem::exists(path) && std::filesystem::file_size(path) > 100) << path;
  }
  EXPECT_NE(r.out.find("step 1/6: goto pickup"), std::string::npos) << r.out;  // progress was printed
  EXPECT_NE(r.out.find("1 / 1 missions succeeded without contact"), std::string::npos) << r.out;
}

TEST_F(MissionsDemo, UsageErrorsExit2) {
  EXPECT_EQ(Run("--seeds 0").exit_code, 2);
  EXPECT_EQ(Run("--first-seed -3").exit_code, 2);
  EXPECT_EQ(Run("--graph /nonexistent.yaml").exit_code, 2);
}

}  // namespace
}  // namespace topay
