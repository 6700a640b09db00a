// summary.json's keys and values for a summary filled here.

#include "tools/report/summary_json.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

RunSummary Filled() {
  RunSummary s;
  s.log_path = "run/graph.lcmlog";
  s.mission.name = "m";
  s.mission.result = MissionResult::kFailed;
  s.mission.steps.push_back({0, "goto a", 0.5, 2.0, true, 3, 0});
  s.planner.replans = 4;
  s.planner.failure_reasons = {{"no goal", 2}};
  s.collisions.contact_events = 1;
  s.tracking.position_m = {10, 0.02, 0.05};
  s.tracking.solve_ms = {10, 1.0, 2.0, 3.0, 4.0};
  s.appeared_boxes.push_back({7, "b", true, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.4, 0.5, 0.6), 0.1});
  s.appeared_boxes.push_back({8, "c", false, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0});
  s.channels["X"] = {5, 2};
  s.decode_failures = 2;
  return s;
}

TEST(SummaryJson, EveryFieldUnderItsKey) {
  const nlohmann::json j = SummaryToJson(Filled());
  EXPECT_EQ(j["log"]["path"], "run/graph.lcmlog");
  EXPECT_EQ(j["success"], false);
  EXPECT_EQ(j["mission"]["result"], "FAILED");
  EXPECT_EQ(j["mission"]["steps"][0]["attempts"], 3);
  EXPECT_EQ(j["mission"]["steps"][0]["moving"], true);
  EXPECT_EQ(j["planner"]["replans"], 4);
  EXPECT_EQ(j["planner"]["failure_reasons"]["no goal"], 2);
  EXPECT_EQ(j["collisions"]["contact_events"], 1);
  EXPECT_EQ(j["tracking"]["position_m"]["rms"], 0.02);
  EXPECT_EQ(j["tracking"]["solve_ms"]["p99"], 3.0);
  EXPECT_EQ(j["appeared_boxes"][0]["size_m"][2], 0.6);
  EXPECT_FALSE(j["appeared_boxes"][1].contains("center_m"));  // no geometry
  EXPECT_EQ(j["channels"]["X"]["decode_failures"], 2);
  EXPECT_EQ(j["decode_failures"], 2);
}

TEST(SummaryJson, WritesTheFileOrSaysWhichCannotBeWritten) {
  const std::string dir = test::FreshTestDir("summary_json");
  WriteSummaryJson(Filled(), dir + "/s.json");
  std::ifstream file(dir + "/s.json");
  EXPECT_EQ(nlohmann::json::parse(file)["planner"]["replans"], 4);
  try {
    WriteSummaryJson(Filled(), dir + "/no/such/folder/s.json");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/folder/s.json: cannot write"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::report
