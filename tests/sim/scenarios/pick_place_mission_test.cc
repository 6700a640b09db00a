// The pick-and-place scenario's mission text: topay-mission's loader takes it, with the six
// steps in order and the goals' poses and hints exactly.

#include "sim/scenarios/pick_place_mission.h"

#include <gtest/gtest.h>

#include "procs/mission/mission_spec.h"
#include "scenario_robot.h"

namespace topay::test {
namespace {

TEST(PickPlaceMission, LoadsWithSixStepsAndTheGoalsExactly) {
  const PickPlaceScenarioOptions options;
  const PickPlaceScenario& s = DefaultScenario(2);
  const mission::Mission m = mission::ParseMission(PickPlaceMissionYaml(s, options), "mission.yaml");
  mission::CheckMissionForRobot(m, TopayKinematics().num_joints());
  EXPECT_EQ(m.name, "pick_and_place");
  ASSERT_EQ(m.steps.size(), 6u);
  using mission::StepType;
  const StepType types[6] = {StepType::kGoto, StepType::kGripper, StepType::kGoto,
                             StepType::kGripper, StepType::kWait, StepType::kHome};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(m.steps[i].type, types[i]) << "step " << i;
  EXPECT_EQ(m.steps[0].label, "pickup");
  EXPECT_EQ(m.steps[2].label, "dropoff");
  EXPECT_EQ(m.steps[1].gripper_position, 1.0);  // close
  EXPECT_EQ(m.steps[3].gripper_position, 0.0);  // open
  EXPECT_EQ(m.steps[4].duration_s, options.wait_s);
  const TableTopGoal* goals[2] = {&s.pickup, &s.dropoff};
  for (int g = 0; g < 2; ++g) {
    const mission::MissionStep& step = m.steps[2 * g];
    EXPECT_EQ(step.X_WE.translation(), goals[g]->X_WE.translation());
    EXPECT_TRUE(step.X_WE.rotation().isApprox(goals[g]->X_WE.rotation(), 1e-12));
    ASSERT_TRUE(step.hint.has_value());
    EXPECT_EQ(step.hint->x_m, goals[g]->state.x_m);
    EXPECT_EQ(step.hint->y_m, goals[g]->state.y_m);
    EXPECT_EQ(step.hint->yaw_rad, goals[g]->state.yaw_rad);
    EXPECT_EQ(step.hint->q_rad, goals[g]->state.q_rad);
  }
}

}  // namespace
}  // namespace topay::test
