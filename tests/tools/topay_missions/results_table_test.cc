#include "tools/topay_missions/results_table.h"

#include <gtest/gtest.h>

namespace topay::tools {
namespace {

MissionRunRow Row(std::uint64_t seed, const std::string& result, std::int64_t contacts, double time_s) {
  MissionRunRow r;
  r.seed = seed;
  r.result = result;
  r.contact_events = contacts;
  r.mission_time_s = time_s;
  r.replans = 2;
  r.boxes_appeared = 1;
  r.position_rms_m = 0.0123;
  return r;
}

TEST(MissionRunRow, SuccessNeedsTheMissionAndNoContact) {
  EXPECT_TRUE(Row(1, "SUCCEEDED", 0, 10).Success());
  EXPECT_FALSE(Row(1, "SUCCEEDED", 1, 10).Success());
  EXPECT_FALSE(Row(1, "SUCCEEDED", -1, 10).Success());  // unknown contacts are no success
  EXPECT_FALSE(Row(1, "FAILED", 0, 10).Success());
  EXPECT_FALSE(Row(1, "TIMEOUT", 0, 10).Success());
  EXPECT_TRUE(Row(1, "NO SCENARIO", -1, 0).NoScenario());
  EXPECT_FALSE(Row(1, "FAILED", 0, 0).NoScenario());
}

TEST(ResultsTable, OneRowPerSeedAndTotals) {
  const std::string table = ResultsTable({Row(3, "SUCCEEDED", 0, 80.0), Row(4, "FAILED", 2, 30.0),
                                          Row(5, "SUCCEEDED", 0, 100.0), Row(6, "NO SCENARIO", -1, 0.0)});
  EXPECT_NE(table.find("| 3 | yes | SUCCEEDED | 0 | 80.0 | 2 | 1 | 1.23 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 4 | NO | FAILED | 2 | 30.0 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 0.0000 | 0.0000 | - |\n"), std::string::npos) << table;  // no estimator: not measured
  EXPECT_NE(table.find("| 6 | NO | NO SCENARIO | ? |"), std::string::npos) << table;
  EXPECT_NE(table.find("2 / 3 missions succeeded without contact; 2 ground-truth contacts in all; median mission "
                       "time 90.0 s (successful runs); 1 seed(s) without a scenario (no mission run)"),
            std::string::npos)
      << table;
}

TEST(ResultsTable, TheEstimatorsErrorWhereMeasured) {
  MissionRunRow row = Row(8, "SUCCEEDED", 0, 50.0);
  row.estimation_rms_m = 0.0042;
  EXPECT_NE(ResultsTable({row}).find("| 0.42 |\n"), std::string::npos) << ResultsTable({row});
}

TEST(ResultsTable, JsonHasEveryField) {
  const nlohmann::json j = ToJson(Row(7, "SUCCEEDED", 0, 12.5));
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["success"], true);
  EXPECT_EQ(j["mission_time_s"], 12.5);
  EXPECT_EQ(j["contact_events"], 0);
  EXPECT_EQ(j["replans"], 2);
  EXPECT_EQ(j["estimation_rms_m"], -1.0);
}

}  // namespace
}  // namespace topay::tools
