// The mission's result and steps from MISSION_STATUS sequences made here.

#include "tools/report/mission_summary.h"

#include <gtest/gtest.h>

namespace topay::report {
namespace {

mission_status_t Status(std::int8_t state, int step, const std::string& what, int attempts, double elapsed_s) {
  mission_status_t m;
  m.utime = static_cast<std::int64_t>(elapsed_s * 1e6);
  m.mission = "m";
  m.state = state;
  m.step_index = step;
  m.num_steps = 2;
  m.step = what;
  m.goal_id = 0;
  m.attempts = attempts;
  m.elapsed_s = elapsed_s;
  m.detail = "d" + std::to_string(step);
  return m;
}

TEST(MissionSummary, NoStatusIsNone) {
  const MissionSummary m = SummarizeMission({});
  EXPECT_EQ(m.result, MissionResult::kNone);
  EXPECT_EQ(ToString(m.result), "none");
  EXPECT_TRUE(m.steps.empty());
}

TEST(MissionSummary, ALogEndingWhileRunningIsNoneWithTheStepsSoFar) {
  const MissionSummary m = SummarizeMission({Status(mission_status_t::RUNNING, 0, "goto a", 1, 1.0),
                                             Status(mission_status_t::RUNNING, 1, "wait", 1, 2.5),
                                             Status(mission_status_t::RUNNING, 1, "wait", 1, 4.0)});
  EXPECT_EQ(m.result, MissionResult::kNone);
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_DOUBLE_EQ(m.steps[0].time_s, 1.5);
  EXPECT_DOUBLE_EQ(m.steps[1].time_s, 1.5);  // until the last status
  EXPECT_EQ(m.steps[1].attempts, 0);         // not a goto / home
  EXPECT_DOUBLE_EQ(m.elapsed_s, 4.0);
}

TEST(MissionSummary, FailedAndAbortedAreFinalWithTheirDetail) {
  MissionSummary m = SummarizeMission({Status(mission_status_t::RUNNING, 0, "goto a", 1, 1.0),
                                       Status(mission_status_t::FAILED, 0, "goto a", 3, 7.0)});
  EXPECT_EQ(m.result, MissionResult::kFailed);
  EXPECT_EQ(ToString(m.result), "FAILED");
  EXPECT_EQ(m.detail, "d0");
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].attempts, 3);
  EXPECT_DOUBLE_EQ(m.steps[0].time_s, 6.0);
  m = SummarizeMission({Status(mission_status_t::ABORTED, 1, "home", 1, 2.0)});
  EXPECT_EQ(m.result, MissionResult::kAborted);
  EXPECT_TRUE(m.steps[0].moving);
}

}  // namespace
}  // namespace topay::report
