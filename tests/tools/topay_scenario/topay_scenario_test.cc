// topay-scenario end to end: the three files for a seed (the room as topay-sim reads it, the
// mission as topay-mission loads it, scenario.json), one line per goal, and the exit codes.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sim/scenes/scene_json.h"
#include "tests/common/tool_test.h"

namespace topay {
namespace {

class TopayScenarioTest : public ToolTest {
 protected:
  TopayScenarioTest() : ToolTest("topay-scenario") {}
};

TEST_F(TopayScenarioTest, WritesTheRoomTheMissionAndTheGoals) {
  const RunResult r = Run("--seed 2 --out '" + Path("run") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("pickup: table top"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dropoff: table top"), std::string::npos) << r.out;
  std::vector<BoxRole> roles;
  const Scene room = ReadSceneJson(Path("run/room.json"), &roles);
  const nlohmann::json scenario = nlohmann::json::parse(ReadText(Path("run/scenario.json")));
  EXPECT_EQ(scenario["seed"], 2);
  ASSERT_EQ(scenario["goals"].size(), 2u);
  EXPECT_EQ(scenario["goals"][0]["name"], "pickup");
  EXPECT_EQ(scenario["goals"][1]["name"], "dropoff");
  for (const auto& goal : scenario["goals"]) {
    EXPECT_EQ(roles.at(goal["table_top"].get<int>()), BoxRole::kTableTop);
    EXPECT_EQ(goal["state"]["q_rad"].size(), 7u);
  }
  const std::string mission = ReadText(Path("run/mission.yaml"));
  EXPECT_NE(mission.find("name: pickup"), std::string::npos);
  EXPECT_NE(mission.find("name: dropoff"), std::string::npos);
  // The same seed again: the same files.
  ASSERT_EQ(Run("--seed 2 --out '" + Path("again") + "'").exit_code, 0);
  EXPECT_EQ(ReadText(Path("again/scenario.json")), ReadText(Path("run/scenario.json")));
  EXPECT_EQ(ReadText(Path("again/room.json")), ReadText(Path("run/room.json")));
}

TEST_F(TopayScenarioTest, BadConfigExitsOneNamingTheKey) {
  std::ofstream(Path("bad.yaml")) << "max_pickup: 3\n";
  const RunResult r = Run("--seed 2 --out '" + Path("run") + "' --config '" + Path("bad.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("max_pickup"), std::string::npos) << r.err;
}

TEST_F(TopayScenarioTest, NoScenarioExitsOneNamingTheSeed) {
  std::ofstream(Path("far.yaml")) << "dropoff_distance_min_m: 40\nmax_targets: 3\nmax_pickups: 1\n";
  const RunResult r = Run("--seed 5 --out '" + Path("run") + "' --config '" + Path("far.yaml") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("seed 5"), std::string::npos) << r.err;
}

TEST_F(TopayScenarioTest, UsageErrorsExitTwo) {
  EXPECT_EQ(Run("--out '" + Path("run") + "'").exit_code, 2);
  EXPECT_EQ(Run("--seed -1 --out '" + Path("run") + "'").exit_code, 2);
  EXPECT_EQ(Run("--seed 1").exit_code, 2);
}

}  // namespace
}  // namespace topay
