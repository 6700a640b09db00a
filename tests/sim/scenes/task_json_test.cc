#include "sim/scenes/task_json.h"
#include "tests/common/temp_path.h"

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay {
namespace {

PlanningTask MakeTask() {
  PlanningTask task;
  task.start.x_m = -1.25;
  task.start.y_m = 3.5;
  task.start.yaw_rad = 0.1;
  task.start.q_rad = Eigen::VectorXd::LinSpaced(7, -1.0, 1.0);
  task.goal.x_m = 4.0;
  task.goal.y_m = -2.0 / 3.0;
  task.goal.yaw_rad = -3.0;
  task.goal.q_rad = Eigen::VectorXd::LinSpaced(7, 0.3, -0.2);
  task.X_WE_goal.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  task.X_WE_goal.translation() = Eigen::Vector3d(4.1, -0.5, 0.9);
  task.range = DistanceRange::kMedium;
  task.seed = 18446744073709551615ull;  // 2^64 - 1 survives
  task.scene_seed = 12;
  task.base_distance_m = std::hypot(task.goal.x_m - task.start.x_m,
                                    task.goal.y_m - task.start.y_m);
  return task;
}

TEST(TaskJsonTest, RoundTrip) {
  const PlanningTask task = MakeTask();
  const std::string path = UniqueTempPath("round_trip.json");
  WriteTaskJson(path, task);
  const PlanningTask read = ReadTaskJson(path, 7);
  EXPECT_EQ(read.start.ToVector(), task.start.ToVector());
  EXPECT_EQ(read.goal.ToVector(), task.goal.ToVector());
  EXPECT_EQ(read.range, task.range);
  EXPECT_EQ(read.seed, task.seed);
  EXPECT_EQ(read.scene_seed, task.scene_seed);
  EXPECT_EQ(read.base_distance_m, task.base_distance_m);
  EXPECT_EQ(read.X_WE_goal.translation(), task.X_WE_goal.translation());
  EXPECT_TRUE(read.X_WE_goal.linear().isApprox(task.X_WE_goal.linear(), 1e-15));
  EXPECT_EQ(TaskToJson(read), TaskToJson(task));
}

PlanningTask MakeTightTask() {
  PlanningTask task = MakeTask();
  TightTaskInfo info;
  info.start = {0.0123456789, 17, TightBody::kArm};
  info.goal = {1.0 / 3.0 * 0.1, 4, TightBody::kBase};
  info.goal_kind = TightGoalKind::kUnderTable;
  info.goal_table_top = 40;
  task.tight = info;
  return task;
}

TEST(TaskJsonTest, TightTaskRoundTrip) {
  const PlanningTask task = MakeTightTask();
  const std::string text = TaskToJson(task);
  EXPECT_NE(text.find("\"goal_kind\": \"under_table\""), std::string::npos) << text;
  const PlanningTask read = TaskFromJson(text, "tight.json", 7);
  ASSERT_TRUE(read.tight.has_value());
  EXPECT_EQ(read.tight->start.clearance_m, task.tight->start.clearance_m);
  EXPECT_EQ(read.tight->start.box, 17);
  EXPECT_EQ(read.tight->start.body, TightBody::kArm);
  EXPECT_EQ(read.tight->goal.clearance_m, task.tight->goal.clearance_m);
  EXPECT_EQ(read.tight->goal.box, 4);
  EXPECT_EQ(read.tight->goal.body, TightBody::kBase);
  EXPECT_EQ(read.tight->goal_kind, TightGoalKind::kUnderTable);
  EXPECT_EQ(read.tight->goal_table_top, 40);
  EXPECT_EQ(TaskToJson(read), text);
  // A near-box goal has no table top: null, read back as -1.
  PlanningTask near = task;
  near.tight->goal_kind = TightGoalKind::kNearBox;
  near.tight->goal_table_top = -1;
  const std::string near_text = TaskToJson(near);
  EXPECT_NE(near_text.find("\"goal_table_top\": null"), std::string::npos) << near_text;
  EXPECT_EQ(TaskFromJson(near_text, "near.json").tight->goal_table_top, -1);
  // An open task has no "tight" key and reads back without one.
  EXPECT_EQ(TaskToJson(MakeTask()).find("tight"), std::string::npos);
  EXPECT_FALSE(TaskFromJson(TaskToJson(MakeTask()), "open.json").tight.has_value());
}

class TaskJsonErrorTest : public ::testing::Test {
 protected:
  // The valid task's JSON with `from` replaced by `to` (which must occur once).
  static std::string Edit(const std::string& from, const std::string& to,
                          const PlanningTask& task = MakeTask()) {
    std::string text = TaskToJson(task);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
  }

  static void ExpectError(const std::string& text, const std::string& field,
                          const std::string& message_part, int expected_joints = -1) {
    const std::string path = UniqueTempPath("bad.json");
    std::ofstream(path, std::ios::binary) << text;
    try {
      ReadTaskJson(path, expected_joints);
      ADD_FAILURE() << "no error for field " << field;
    } catch (const ConfigError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_EQ(error.field(), field) << error.what();
      EXPECT_NE(std::string(error.what()).find(message_part), std::string::npos)
          << error.what();
    }
  }
};

TEST_F(TaskJsonErrorTest, MissingFileAndMalformedJson) {
  const std::string path = UniqueTempPath("missing.json");
  std::remove(path.c_str());
  EXPECT_THROW(ReadTaskJson(path), ConfigError);
  ExpectError("{\"range\": ", "", "malformed JSON");
}

TEST_F(TaskJsonErrorTest, BadFieldsNameTheField) {
  ExpectError(Edit("\"range\": \"medium\"", "\"range\": \"huge\""), "range", "unknown range");
  ExpectError(Edit("\"range\": \"medium\",", ""), "range", "missing");
  ExpectError(Edit("\"scene_seed\": 12", "\"scene_seed\": -12"), "scene_seed", "negative");
  ExpectError(Edit("\"x_m\": -1.25", "\"x_m\": null"), "start.x_m", "expected a number");
  ExpectError(Edit("\"x_m\": -1.25", "\"x_m\": 1e999"), "", "out of range");
  ExpectError(Edit("\"yaw_rad\": -3.0", "\"yaw_rad\": \"a\""), "goal.yaw_rad",
              "expected a number");
  ExpectError(Edit("\"q_rad\": [\n      -1.0,", "\"q_rad\": [\n"), "goal.q_rad",
              "start.q_rad has 6");
  ExpectError(TaskToJson(MakeTask()), "start.q_rad", "the robot has 6", 6);
  ExpectError(Edit("\"position_m\": [\n      4.1,", "\"position_m\": [\n"),
              "goal_end_effector.position_m", "expected 3 numbers");
  ExpectError(Edit("\"quaternion_wxyz\": [", "\"quaternion_wxyz\": [0.5,"),
              "goal_end_effector.quaternion_wxyz", "expected 4 numbers");
  ExpectError(Edit("\"base_distance_m\": ", "\"base_distance_m\": 1"), "base_distance_m",
              "disagrees");
  // start becomes 5; its old object becomes a first "goal", which the real one overrides.
  ExpectError(Edit("\"start\": {", "\"start\": 5, \"goal\": {"), "start",
              "expected an object");
}

TEST_F(TaskJsonErrorTest, UnknownKeysNameTheKey) {
  ExpectError(Edit("\"start\": {", "\"unused\": 1, \"start\": {"), "unused", "unknown field");
  ExpectError(Edit("\"x_m\": -1.25", "\"x_m\": -1.25, \"z_m\": 0"), "start.z_m",
              "unknown field");
  ExpectError(Edit("\"position_m\": [", "\"frame\": \"W\", \"position_m\": ["),
              "goal_end_effector.frame", "unknown field");
}

TEST_F(TaskJsonErrorTest, BadTightFieldsNameTheField) {
  const PlanningTask tight = MakeTightTask();
  ExpectError(Edit("\"goal_kind\": \"under_table\"", "\"goal_kind\": \"beside\"", tight),
              "tight.goal_kind", "unknown goal kind");
  ExpectError(Edit("\"body\": \"arm\"", "\"body\": \"leg\"", tight), "tight.start.body",
              "unknown body");
  ExpectError(Edit("\"box\": 17", "\"box\": -1", tight), "tight.start.box", "negative");
  ExpectError(Edit("\"goal_table_top\": 40", "\"goal_table_top\": null", tight),
              "tight.goal_table_top", "near_box");
  ExpectError(Edit("\"goal_kind\": \"under_table\"", "\"goal_kind\": \"near_box\"", tight),
              "tight.goal_table_top", "near_box");
  ExpectError(Edit("\"clearance_m\": 0.0123456789,", "", tight), "tight.start.clearance_m",
              "missing");
  ExpectError(Edit("\"goal_kind\"", "\"kind\": 1, \"goal_kind\"", tight), "tight.kind",
              "unknown field");
  ExpectError(Edit("\"box\": 17", "\"box\": 17, \"part\": 3", tight), "tight.start.part",
              "unknown field");
}

TEST_F(TaskJsonErrorTest, DirectoriesAndOversizedFilesAreErrors) {
  EXPECT_THROW(ReadTaskJson(::testing::TempDir()), ConfigError);
  const std::string path = UniqueTempPath("big.json");
  std::ofstream(path, std::ios::binary)
      << TaskToJson(MakeTask()) << std::string(kMaxTaskJsonBytes, ' ');
  try {
    ReadTaskJson(path);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_NE(std::string(error.what()).find("limit"), std::string::npos) << error.what();
  }
  std::remove(path.c_str());
}

TEST_F(TaskJsonErrorTest, NonUnitQuaternion) {
  std::string text = TaskToJson(MakeTask());
  const std::size_t at = text.find("\"quaternion_wxyz\": [");
  ASSERT_NE(at, std::string::npos);
  const std::size_t first = text.find_first_of("-0123456789", at + 20);
  text.insert(first, "1");  // the w component grows by 1 (or 10)
  ExpectError(text, "goal_end_effector.quaternion_wxyz", "not a unit quaternion");
}

}  // namespace
}  // namespace topay
