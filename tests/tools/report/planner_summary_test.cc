// Replans, stopping trajectories, planning times and failures from PLANNER_STATUS sequences
// made here: repeated statuses count once.

#include "tools/report/planner_summary.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

using test::Planner;  // a PLANNER_STATUS with these fields (crafted_run_log.h)

TEST(PlannerSummary, NothingIsZero) {
  const PlannerSummary p = SummarizePlanner({Planner(planner_status_t::IDLE, 0, 0, 0.0, 0)});
  EXPECT_EQ(p.goals, 0);  // goal id 0: none
  EXPECT_EQ(p.replans, 0);
  EXPECT_EQ(p.planning_ms.count, 0);
}

TEST(PlannerSummary, MaxReplansPerGoalSummedAndEachPlanOnce) {
  using P = planner_status_t;
  const PlannerSummary p = SummarizePlanner(
      {Planner(P::SUCCEEDED, 1, 10, 50.0, 0), Planner(P::PLANNING, 1, 10, 50.0, 2), Planner(P::SUCCEEDED, 1, 11, 70.0, 2),
       Planner(P::SUCCEEDED, 1, 11, 70.0, 1),  // a lower count later does not lower the max
       Planner(P::STOPPING, 2, 20, 0.0, 4), Planner(P::STOPPING, 2, 21, 0.0, 5), Planner(P::STOPPING, 2, 21, 0.0, 5),
       Planner(P::FAILED, 3, 0, 0.0, 0, "x"), Planner(P::FAILED, 3, 0, 0.0, 0, "x"),
       Planner(P::CANCELLED, 4, 0, 0.0, 1)});
  EXPECT_EQ(p.goals, 4);
  EXPECT_EQ(p.replans, 2 + 5 + 0 + 1);
  EXPECT_EQ(p.stopping, 2);
  EXPECT_EQ(p.planning_ms.count, 2);
  EXPECT_DOUBLE_EQ(p.planning_ms.median, 60.0);
  EXPECT_DOUBLE_EQ(p.planning_ms.max, 70.0);
  EXPECT_EQ(p.failures, 1);
  EXPECT_EQ(p.failure_reasons.at("x"), 1);
}

TEST(PlannerSummary, AStatusKeepingAnotherGoalsTrajectoryIsNoPlan) {
  using P = planner_status_t;
  planner_status_t at_rest = Planner(P::SUCCEEDED, 2, 10, 50.0, 0);  // goal 2, goal 1's trajectory and time
  at_rest.detail = "goal reached at rest: end effector 0.010 m / 0.020 rad from the target";
  planner_status_t later = at_rest;
  later.detail = "";  // a periodic repeat with another detail is still goal 1's trajectory
  const PlannerSummary p = SummarizePlanner({Planner(P::SUCCEEDED, 1, 10, 50.0, 0), at_rest, later,
                                             Planner(P::SUCCEEDED, 3, 0, 80.0, 0)});  // no trajectory id
  EXPECT_EQ(p.planning_ms.count, 1);
  EXPECT_DOUBLE_EQ(p.planning_ms.max, 50.0);
  EXPECT_EQ(p.reached_at_rest, 1);
  EXPECT_EQ(p.goals, 3);
}

}  // namespace
}  // namespace topay::report
