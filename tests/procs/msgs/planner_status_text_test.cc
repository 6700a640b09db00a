// The planner's "goal reached" reports (procs/msgs/planner_status_text.h): what the planner
// writes is what the mission and the tests read, and nothing else passes for it.

#include "procs/msgs/planner_status_text.h"

#include <gtest/gtest.h>

namespace topay::msgs {
namespace {

planner_status_t Status(std::int8_t state, const std::string& detail) {
  planner_status_t s{};
  s.state = state;
  s.detail = detail;
  return s;
}

TEST(PlannerStatusText, TheWrittenDetailsAreTheOnesRead) {
  EXPECT_EQ(TrajectoryEndedDetail(1796661282243839), "trajectory 1796661282243839 ended");
  EXPECT_EQ(ReachedAtRestDetail(0.000424629, 0.0123456),
            "goal reached at rest: end effector 0.000 m / 0.012 rad from the target");
  const planner_status_t ended = Status(planner_status_t::SUCCEEDED, TrajectoryEndedDetail(7));
  const planner_status_t at_rest = Status(planner_status_t::SUCCEEDED, ReachedAtRestDetail(0.01, 0.02));
  EXPECT_TRUE(ReportsTrajectoryEnded(ended));
  EXPECT_FALSE(ReportsReachedAtRest(ended));
  EXPECT_TRUE(ReportsReachedAtRest(at_rest));
  EXPECT_FALSE(ReportsTrajectoryEnded(at_rest));
  EXPECT_TRUE(ReportsGoalReached(ended));
  EXPECT_TRUE(ReportsGoalReached(at_rest));
}

TEST(PlannerStatusText, OnlyASucceededStatusReportsTheGoalReached) {
  for (const std::int8_t state : {planner_status_t::IDLE, planner_status_t::PLANNING, planner_status_t::FAILED,
                                  planner_status_t::CANCELLED, planner_status_t::STOPPING}) {
    EXPECT_FALSE(ReportsGoalReached(Status(state, TrajectoryEndedDetail(7)))) << int(state);
    EXPECT_FALSE(ReportsGoalReached(Status(state, ReachedAtRestDetail(0.0, 0.0)))) << int(state);
  }
}

// A plan's trigger is a SUCCEEDED detail too (the goal under way); one naming a trajectory or
// a stop is no arrival.
TEST(PlannerStatusText, APlansTriggerIsNoArrival) {
  for (const char* trigger : {"goal: new goal 1", "map_collision: map seq 55: trajectory 17 collides 3.58 s ahead",
                              "retry: replanning from the safe stop", "trajectory 17 ended early", "trajectory  ended",
                              "trajectory x ended", "the trajectory ended", "", "goal reached"}) {
    EXPECT_FALSE(ReportsGoalReached(Status(planner_status_t::SUCCEEDED, trigger))) << trigger;
  }
}

}  // namespace
}  // namespace topay::msgs
