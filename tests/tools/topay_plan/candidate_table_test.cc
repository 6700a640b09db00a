#include "tools/topay_plan/candidate_table.h"

#include <gtest/gtest.h>

#include <sstream>

namespace topay::plan {
namespace {

// Three candidates: a validated one (chosen), one the validator rejected, one never started.
WholeBodyPlanResult MakePlan() {
  WholeBodyPlanResult plan;
  for (int i = 0; i < 3; ++i) {
    FrontEndPath path;
    path.base_path.length_m = 9.5 + i;
    path.base_path.homotopy_class = i;
    path.base_path.source =
        i == 2 ? BasePathSource::kJumpPointSearch : BasePathSource::kTopologicalPrm;
    plan.front_end.paths.push_back(path);
  }
  CandidateReport ok;
  ok.path_index = 0;
  ok.started = true;
  ok.optimization.status = BackEndStatus::kSuccess;
  ok.optimization.duration_s = 14.25;
  ok.optimization.stage1_iterations = 100;
  ok.optimization.stage2_iterations = 312;
  ok.wall_ms = 180.5;
  ok.validation = ValidationReport{};
  ok.validation->ok = true;
  CandidateReport rejected = ok;
  rejected.path_index = 1;
  rejected.validation->ok = false;
  rejected.validation->first_failure.message = "arm collision at t = 3.2 s";
  CandidateReport queued;
  queued.path_index = 2;
  plan.candidates = {ok, rejected, queued};
  plan.chosen = 0;
  return plan;
}

TEST(CandidateTableTest, RowsDescribeEachCandidate) {
  const std::vector<CandidateRow> rows = CandidateRows(MakePlan());
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].base_path, "PRM class 0, 9.5 m");
  EXPECT_EQ(rows[0].optimizer, "success");
  EXPECT_EQ(rows[0].duration_s, 14.25);
  EXPECT_EQ(rows[0].iterations, 412);
  EXPECT_EQ(rows[0].verdict, "validated");
  EXPECT_TRUE(rows[0].chosen);
  EXPECT_EQ(rows[1].verdict, "rejected: arm collision at t = 3.2 s");
  EXPECT_FALSE(rows[1].chosen);
  EXPECT_EQ(rows[2].base_path, "JPS, 11.5 m");
  EXPECT_EQ(rows[2].optimizer, "not started");
  EXPECT_EQ(rows[2].iterations, 0);
}

TEST(CandidateTableTest, TableHasAHeaderAndOneAlignedLinePerCandidate) {
  const std::string table = FormatCandidateTable(CandidateRows(MakePlan()), "  ");
  std::istringstream in(table);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_NE(lines[0].find("base path"), std::string::npos);
  EXPECT_NE(lines[0].find("optimizer"), std::string::npos);
  EXPECT_NE(lines[1].find("0*"), std::string::npos);
  EXPECT_NE(lines[1].find("14.25 s"), std::string::npos);
  EXPECT_NE(lines[1].find("(chosen)"), std::string::npos);
  EXPECT_EQ(lines[2].find("(chosen)"), std::string::npos);
  EXPECT_NE(lines[3].find("not started"), std::string::npos);
  // Columns line up: "optimizer" starts at the same column as each row's status.
  const std::size_t column = lines[0].find("optimizer");
  EXPECT_EQ(lines[1].find("success"), column);
  EXPECT_EQ(lines[3].find("not started"), column);
  EXPECT_EQ(FormatCandidateTable({}), "");
}

}  // namespace
}  // namespace topay::plan
