// Planning task files from untrusted text (sim/scenes/task_json.h TaskFromJson), without a
// robot (expected_num_joints -1) and against a robot's joint count. Bad input must be a
// ConfigError naming the file; a task that loads must hold what the format promises (finite
// states with equal joint counts, a base distance that matches them, a rigid goal pose,
// consistent tight info), load against a robot exactly when the joint count is the robot's,
// and round-trip: TaskToJson then TaskFromJson gives the same task (the goal pose to rounding:
// it is written as a quaternion).
// Input: [joint count][task JSON text]; the first byte is the robot's joint count.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "core/common/error.h"
#include "sim/scenes/task_json.h"
#include "tests/fuzz/fuzz_reader.h"
#include "tests/fuzz/loader_checks.h"
#include "tests/fuzz/loader_rigid.h"

namespace topay::fuzz {
namespace {

constexpr const char* kSource = "fuzz_task.json";
constexpr const char* kRoundTripSource = "fuzz_task_written.json";

bool Finite(const WholeBodyState& state) {
  return std::isfinite(state.x_m) && std::isfinite(state.y_m) && std::isfinite(state.yaw_rad) &&
         state.q_rad.allFinite();
}

void CheckTask(const PlanningTask& task) {
  FuzzCheck(Finite(task.start) && Finite(task.goal), "start and goal are finite");
  FuzzCheck(task.start.num_joints() == task.goal.num_joints(), "start and goal have the same joints");
  FuzzCheck(std::isfinite(task.base_distance_m), "the base distance is finite");
  const double distance = std::hypot(task.goal.x_m - task.start.x_m, task.goal.y_m - task.start.y_m);
  FuzzCheck(std::abs(distance - task.base_distance_m) <= 1e-6, "the base distance matches start and goal");
  FuzzCheck(IsRigid(task.X_WE_goal), "the goal pose is a finite rigid transform");
  if (task.tight) {
    const TightTaskInfo& tight = *task.tight;
    FuzzCheck(std::isfinite(tight.start.clearance_m) && std::isfinite(tight.goal.clearance_m), "clearances are finite");
    FuzzCheck(tight.start.box >= 0 && tight.goal.box >= 0, "tight ends name a box");
    FuzzCheck((tight.goal_kind == TightGoalKind::kNearBox) == (tight.goal_table_top < 0),
              "a table top exactly when the goal is on or under a table");
  }
}

bool SameState(const WholeBodyState& a, const WholeBodyState& b) {
  return a.x_m == b.x_m && a.y_m == b.y_m && a.yaw_rad == b.yaw_rad && a.q_rad == b.q_rad;
}

bool SameTight(const std::optional<TightTaskInfo>& a, const std::optional<TightTaskInfo>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  const auto same_end = [](const TightEnd& x, const TightEnd& y) {
    return x.clearance_m == y.clearance_m && x.box == y.box && x.body == y.body;
  };
  return same_end(a->start, b->start) && same_end(a->goal, b->goal) && a->goal_kind == b->goal_kind &&
         a->goal_table_top == b->goal_table_top;
}

void CheckRoundTrip(const PlanningTask& task) {
  std::optional<PlanningTask> again;
  try {
    again = TaskFromJson(TaskToJson(task), kRoundTripSource, task.start.num_joints());
  } catch (const ConfigError&) {
    FuzzCheck(false, "a written task reads back");
  }
  FuzzCheck(again->range == task.range && again->seed == task.seed && again->scene_seed == task.scene_seed &&
                again->base_distance_m == task.base_distance_m,
            "a task's header round-trips");
  FuzzCheck(SameState(again->start, task.start) && SameState(again->goal, task.goal), "start and goal round-trip");
  FuzzCheck(again->X_WE_goal.translation() == task.X_WE_goal.translation(), "the goal position round-trips");
  FuzzCheck((again->X_WE_goal.linear() - task.X_WE_goal.linear()).cwiseAbs().maxCoeff() <= 1e-12,
            "the goal rotation round-trips to rounding");
  FuzzCheck(SameTight(again->tight, task.tight), "tight info round-trips");
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const int robot_joints = in.Byte();
  const std::string text = in.RestAsString();

  std::optional<PlanningTask> task;
  try {
    task = TaskFromJson(text, kSource);
  } catch (const ConfigError& e) {
    CheckConfigError(e, kSource);
  }
  bool loads_for_robot = false;
  try {
    TaskFromJson(text, kSource, robot_joints);
    loads_for_robot = true;
  } catch (const ConfigError& e) {
    CheckConfigError(e, kSource);
  }
  FuzzCheck(loads_for_robot == (task && task->start.num_joints() == robot_joints),
            "a task loads for a robot exactly when it loads and has the robot's joint count");
  if (!task) return 0;
  CheckTask(*task);
  CheckRoundTrip(*task);
  return 0;
}
