#include "tools/topay_frontend_bench/front_end_tally.h"

#include <gtest/gtest.h>

namespace topay::frontend_bench {
namespace {

FrontEndResult ResultWithPaths(int num_paths, int goal_attempts) {
  FrontEndResult result;
  result.status = num_paths > 0 ? FrontEndStatus::kSuccess : FrontEndStatus::kInvalidInput;
  result.paths.resize(num_paths);
  result.stats.total_ms = 12.5;
  result.stats.num_goal_attempts = goal_attempts;
  result.stats.topology_ms = 4.0;
  ArmJobReport finished;
  finished.started = true;
  finished.status = ArmRrtStarStatus::kSuccess;
  finished.stats.time_to_first_solution_s = 0.003;
  ArmJobReport cancelled;
  cancelled.started = true;
  cancelled.status = ArmRrtStarStatus::kCancelled;
  result.jobs = {finished, cancelled};
  return result;
}

TEST(FrontEndTallyTest, CountsTasksPathsJobsAndStageTimes) {
  FrontEndTally tally;
  AddToTally(ResultWithPaths(2, 1), FrontEndTaskOutcome{0, false, {}}, &tally);
  EXPECT_EQ(tally.tasks, 1);
  EXPECT_EQ(tally.tasks_ok, 1);
  EXPECT_EQ(tally.paths, 2);
  EXPECT_EQ(tally.jobs_succeeded, 1);
  EXPECT_EQ(tally.jobs_finished, 1);
  EXPECT_EQ(tally.jobs_cancelled, 1);
  ASSERT_EQ(tally.rrt_first_ms.size(), 1u);
  EXPECT_DOUBLE_EQ(tally.rrt_first_ms[0], 3.0);
  ASSERT_EQ(tally.topology_ms.size(), 1u);
  EXPECT_DOUBLE_EQ(tally.topology_ms[0], 4.0);
  EXPECT_EQ(tally.statuses.at(std::string(ToString(FrontEndStatus::kSuccess))), 1);
}

TEST(FrontEndTallyTest, ATaskWithAPathFailingTheExactCheckIsNotOk) {
  FrontEndTally tally;
  AddToTally(ResultWithPaths(1, 1), FrontEndTaskOutcome{7, false, {"arm hits box 3"}}, &tally);
  EXPECT_EQ(tally.tasks_ok, 0);
  EXPECT_EQ(tally.paths_failing_exact_check, 1);
  ASSERT_EQ(tally.exact_failures.size(), 1u);
  EXPECT_EQ(tally.exact_failures[0], "task 7: arm hits box 3");
}

TEST(FrontEndTallyTest, NoGoalAttemptAddsNoStageTimesAndUnreachableIsCounted) {
  FrontEndTally tally;
  AddToTally(ResultWithPaths(0, 0), FrontEndTaskOutcome{1, true, {}}, &tally);
  EXPECT_TRUE(tally.topology_ms.empty());
  EXPECT_EQ(tally.total_ms.size(), 1u);
  EXPECT_EQ(tally.unreachable, 1);
  EXPECT_EQ(tally.unreachable_ok, 0);
  AddToTally(ResultWithPaths(1, 1), FrontEndTaskOutcome{2, true, {}}, &tally);
  EXPECT_EQ(tally.unreachable_ok, 1);  // a path for a certified unsolvable task: a bug flag
}

}  // namespace
}  // namespace topay::frontend_bench
