// The mission YAML loader (procs/mission/mission_spec.h): a good file in every form a step may
// take, and each kind of bad input rejected with an error naming the file, the step and the field.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "procs/mission/mission_options.h"
#include "procs/mission/mission_spec.h"

namespace topay::mission {
namespace {

constexpr const char* kGood = R"(
name: pick_and_place
steps:
  - type: goto
    name: pickup
    position_m: [1.0, 2.0, 0.8]
    rpy_rad: [0.0, 0.0, 1.5707963267948966]
    hint: {x_m: 0.5, y_m: 2.0, yaw_rad: 0.1, q_rad: [0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1]}
    tolerance: {position_m: 0.05, orientation_rad: 0.2}
    timeout_s: 60
  - type: gripper
    action: close
    settle_s: 0.5
  - type: goto
    position_m: [3.0, -1.0, 0.5]
    quat_wxyz: [1.0, 0.0, 0.0, 0.0]
  - type: gripper
    position: 0.25
  - type: wait
    duration_s: 2.5
  - type: home
)";

// The error of parsing `text` ("" if none).
std::string ErrorOf(const std::string& text) {
  try {
    ParseMission(text, "m.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// A mission of one step with these lines (indented under "- ").
std::string OneStep(const std::string& step) { return "name: m\nsteps:\n  - " + step + "\n"; }

TEST(MissionSpecTest, AGoodFileGivesEveryStep) {
  const Mission m = ParseMission(kGood, "good.yaml");
  EXPECT_EQ(m.name, "pick_and_place");
  EXPECT_EQ(m.source, "good.yaml");
  ASSERT_EQ(m.steps.size(), 6u);
  const MissionStep& pickup = m.steps[0];
  EXPECT_EQ(pickup.type, StepType::kGoto);
  EXPECT_EQ(pickup.Describe(), "goto pickup");
  EXPECT_TRUE(pickup.X_WE.translation().isApprox(Eigen::Vector3d(1.0, 2.0, 0.8)));
  EXPECT_TRUE(pickup.X_WE.linear().isApprox(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix()));
  ASSERT_TRUE(pickup.hint.has_value());
  EXPECT_EQ(pickup.hint->num_joints(), 7);
  EXPECT_DOUBLE_EQ(pickup.hint->yaw_rad, 0.1);
  ASSERT_TRUE(pickup.tolerance.has_value());
  EXPECT_DOUBLE_EQ(pickup.tolerance->position_m, 0.05);
  EXPECT_DOUBLE_EQ(pickup.tolerance->orientation_rad, 0.2);
  EXPECT_EQ(pickup.timeout_s, 60.0);
  EXPECT_EQ(m.steps[1].type, StepType::kGripper);
  EXPECT_DOUBLE_EQ(m.steps[1].gripper_position, 1.0);
  EXPECT_EQ(m.steps[1].settle_s, 0.5);
  EXPECT_EQ(m.steps[1].Describe(), "gripper close");
  EXPECT_FALSE(m.steps[2].hint.has_value());
  EXPECT_FALSE(m.steps[2].tolerance.has_value());
  EXPECT_TRUE(m.steps[2].X_WE.linear().isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_DOUBLE_EQ(m.steps[3].gripper_position, 0.25);
  EXPECT_FALSE(m.steps[3].settle_s.has_value());
  EXPECT_EQ(m.steps[4].type, StepType::kWait);
  EXPECT_DOUBLE_EQ(m.steps[4].duration_s, 2.5);
  EXPECT_EQ(m.steps[5].type, StepType::kHome);
  EXPECT_NO_THROW(CheckMissionForRobot(m, 7));
  EXPECT_THROW(CheckMissionForRobot(m, 6), ConfigError);
}

TEST(MissionSpecTest, TheShippedExampleLoads) {
  const Mission m = LoadMission(std::string(TOPAY_SOURCE_DIR) + "/config/missions/pick_and_place.yaml");
  EXPECT_FALSE(m.steps.empty());
  EXPECT_NO_THROW(CheckMissionForRobot(m, 7));
}

TEST(MissionSpecTest, AMissingFileIsNamed) {
  try {
    LoadMission("/nonexistent/mission.yaml");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/mission.yaml"), std::string::npos) << e.what();
  }
}

TEST(MissionSpecTest, AnUnknownStepTypeNamesTheStep) {
  const std::string text = "name: m\nsteps:\n  - {type: wait, duration_s: 1}\n  - {type: fly, to: moon}\n";
  const std::string error = ErrorOf(text);
  EXPECT_NE(error.find("m.yaml"), std::string::npos) << error;
  EXPECT_NE(error.find("steps[1].type"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown step type 'fly'"), std::string::npos) << error;
}

TEST(MissionSpecTest, NaNAndInfinityAreRejectedWithTheirField) {
  EXPECT_NE(ErrorOf(OneStep("{type: goto, position_m: [1, .nan, 0.5], rpy_rad: [0, 0, 0]}")).find("steps[0].position_m[1]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: goto, position_m: [1, 2, 0.5], rpy_rad: [0, 0, .nan]}")).find("steps[0].rpy_rad"),
            std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: wait, duration_s: .nan}")).find("steps[0].duration_s"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: wait, duration_s: .inf}")).find("steps[0].duration_s"), std::string::npos);
  const std::string hint = ErrorOf(OneStep(
      "{type: goto, position_m: [1, 2, 0.5], rpy_rad: [0, 0, 0], hint: {x_m: .inf, y_m: 0, yaw_rad: 0, q_rad: [0]}}"));
  EXPECT_NE(hint.find("steps[0].hint.x_m"), std::string::npos) << hint;
}

TEST(MissionSpecTest, ANonUnitQuaternionIsRejected) {
  const std::string error = ErrorOf(OneStep("{type: goto, position_m: [1, 2, 0.5], quat_wxyz: [1, 0.1, 0, 0]}"));
  EXPECT_NE(error.find("steps[0].quat_wxyz"), std::string::npos) << error;
  EXPECT_NE(error.find("not a unit quaternion"), std::string::npos) << error;
  // Within 1e-3 of unit length it is normalised.
  const Mission m = ParseMission(OneStep("{type: goto, position_m: [1, 2, 0.5], quat_wxyz: [1.0005, 0, 0, 0]}"), "m");
  EXPECT_TRUE(m.steps[0].X_WE.linear().isApprox(Eigen::Matrix3d::Identity()));
}

TEST(MissionSpecTest, MissingFieldsAreNamed) {
  EXPECT_NE(ErrorOf("steps: [{type: home}]").find("name"), std::string::npos);
  EXPECT_NE(ErrorOf("name: m\n").find("steps"), std::string::npos);
  EXPECT_NE(ErrorOf("name: m\nsteps: []\n").find("steps"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{name: x}")).find("steps[0].type"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: goto, rpy_rad: [0, 0, 0]}")).find("steps[0].position_m"), std::string::npos);
  const std::string no_orientation = ErrorOf(OneStep("{type: goto, position_m: [1, 2, 3]}"));
  EXPECT_NE(no_orientation.find("steps[0].rpy_rad"), std::string::npos) << no_orientation;
  EXPECT_NE(no_orientation.find("missing"), std::string::npos) << no_orientation;
  EXPECT_NE(ErrorOf(OneStep("{type: goto, position_m: [1, 2, 3], rpy_rad: [0, 0, 0], quat_wxyz: [1, 0, 0, 0]}"))
                .find("not both"),
            std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: wait}")).find("steps[0].duration_s"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: gripper}")).find("steps[0].action"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: goto, position_m: [1, 2, 3], rpy_rad: [0, 0, 0], hint: {x_m: 0, y_m: 0}}"))
                .find("steps[0].hint.yaw_rad"),
            std::string::npos);
}

TEST(MissionSpecTest, BadValuesAreRejected) {
  EXPECT_NE(ErrorOf(OneStep("{type: gripper, action: squeeze}")).find("steps[0].action"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: gripper, position: 1.5}")).find("steps[0].position"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: wait, duration_s: -1}")).find("steps[0].duration_s"), std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: goto, position_m: [1, 2], rpy_rad: [0, 0, 0]}")).find("expected 3 numbers"),
            std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: home, tolerance: {position_m: -0.1}}")).find("steps[0].tolerance.position_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf(OneStep("{type: home, timeout_s: 0}")).find("steps[0].timeout_s"), std::string::npos);
  // A misspelt field is an error, not ignored.
  EXPECT_NE(ErrorOf(OneStep("{type: wait, duration_s: 1, duraton_s: 2}")).find("steps[0].duraton_s"),
            std::string::npos);
  EXPECT_NE(ErrorOf("name: m\nsteps: [{type: home}]\nextra: 1\n").find("extra"), std::string::npos);
  EXPECT_NE(ErrorOf("name: m\nsteps: [[1, 2]]\n").find("steps[0]"), std::string::npos);
}

TEST(MissionOptionsTest, DefaultsAndAFileWithEveryKey) {
  const MissionOptions defaults;
  EXPECT_EQ(defaults.max_attempts, 3);
  EXPECT_DOUBLE_EQ(defaults.tolerance.position_m, 0.03);
  EXPECT_DOUBLE_EQ(defaults.tolerance.orientation_rad, 0.1);
  EXPECT_DOUBLE_EQ(defaults.status_period_s, 0.5);
  const MissionOptions shipped = LoadMissionOptions(std::string(TOPAY_SOURCE_DIR) + "/config/mission/mission.yaml");
  EXPECT_EQ(shipped.max_attempts, defaults.max_attempts);
  EXPECT_EQ(defaults.max_preemptions, 10);
  EXPECT_EQ(shipped.max_preemptions, defaults.max_preemptions);
  EXPECT_DOUBLE_EQ(shipped.step_timeout_s, defaults.step_timeout_s);
  EXPECT_DOUBLE_EQ(shipped.arrival_settle_s, defaults.arrival_settle_s);
  EXPECT_DOUBLE_EQ(shipped.goal_repeat_period_s, defaults.goal_repeat_period_s);
  EXPECT_DOUBLE_EQ(defaults.goal_repeat_period_s, 1.0);

  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/mission_options";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/bad.yaml") << "max_attempts: 0\n";
  EXPECT_THROW(LoadMissionOptions(dir + "/bad.yaml"), ConfigError);
  std::ofstream(dir + "/preemptions.yaml") << "max_preemptions: -1\n";
  EXPECT_THROW(LoadMissionOptions(dir + "/preemptions.yaml"), ConfigError);
  std::ofstream(dir + "/preemptions_ok.yaml") << "max_preemptions: 0\n";
  EXPECT_EQ(LoadMissionOptions(dir + "/preemptions_ok.yaml").max_preemptions, 0);
  std::ofstream(dir + "/typo.yaml") << "tolerance: {position: 0.1}\n";
  EXPECT_THROW(LoadMissionOptions(dir + "/typo.yaml"), ConfigError);
  std::ofstream(dir + "/settle.yaml") << "arrival_settle_s: 0\n";
  EXPECT_THROW(LoadMissionOptions(dir + "/settle.yaml"), ConfigError);
  std::ofstream(dir + "/settle_ok.yaml") << "arrival_settle_s: 2.5\n";
  EXPECT_DOUBLE_EQ(LoadMissionOptions(dir + "/settle_ok.yaml").arrival_settle_s, 2.5);
  std::ofstream(dir + "/repeat.yaml") << "goal_repeat_period_s: -1\n";
  EXPECT_THROW(LoadMissionOptions(dir + "/repeat.yaml"), ConfigError);
  std::ofstream(dir + "/repeat_off.yaml") << "goal_repeat_period_s: 0\n";
  EXPECT_DOUBLE_EQ(LoadMissionOptions(dir + "/repeat_off.yaml").goal_repeat_period_s, 0.0);
}

}  // namespace
}  // namespace topay::mission
