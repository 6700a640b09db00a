#include "core/planner/plan_in_scene.h"

#include <chrono>
#include <sstream>
#include <string>
#include <utility>

#include "core/collision/scene_clearance.h"
#include "core/collision/start_target_diagnosis.h"
#include "core/common/stopwatch.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/planning/stop_deadline.h"

namespace topay {
namespace {

using Clock = Stopwatch::Clock;

// What is wrong with the start or the target, found exactly against the scene.
struct InputProblem {
  PlanStatus status = PlanStatus::kSuccess;
  FrontEndStatus front_end = FrontEndStatus::kSuccess;
  std::string reason;  // as the front end words it: "start state: ..."
};

InputProblem Problem(PlanStatus status, FrontEndStatus front_end, std::string reason) {
  return {status, front_end, std::move(reason)};
}

// The exact diagnosis's words (start_target_diagnosis.h: which joint, box and body) for a
// problem found here, or `fallback` if it finds none at these margins.
std::string StartReason(const Kinematics& kinematics, const Scene& scene,
                        const WholeBodyState& start, const TrajectoryValidatorOptions& margins,
                        const std::string& fallback) {
  StartDiagnosisOptions options;
  options.obstacle_margin_m = margins.obstacle_margin_m;
  options.self_margin_m = margins.self_margin_m;
  const auto diagnosis = DiagnoseStartState(kinematics, scene, start, options);
  return diagnosis ? "start state: " + *diagnosis : fallback;
}

InputProblem CheckStart(const Kinematics& kinematics, const Scene& scene,
                        const SceneClearanceChecker& checker, const WholeBodyState& start,
                        const TrajectoryValidatorOptions& margins) {
  const RobotModel& model = kinematics.model();
  std::ostringstream why;
  if (start.num_joints() != kinematics.num_joints() || !start.IsFinite()) {
    why << "start state: " << (start.IsFinite() ? "wrong joint count" : "contains NaN or infinity");
    return Problem(PlanStatus::kInvalidInput, FrontEndStatus::kInvalidInput, why.str());
  }
  const JointLimits& limits = model.joint_limits;
  for (int j = 0; j < kinematics.num_joints(); ++j) {
    if (start.q_rad(j) < limits.q_min_rad(j) || start.q_rad(j) > limits.q_max_rad(j)) {
      why << "start state: joint limit (" << model.joint_names[j] << ")";
      return Problem(PlanStatus::kFrontEndFailed, FrontEndStatus::kStartInvalid,
                     StartReason(kinematics, scene, start, margins, why.str()));
    }
  }
  const SceneClearance c = checker.Compute(start);
  if (!(c.base_m > margins.obstacle_margin_m)) {
    why << "start state: base collision (box " << c.base_box << ", clearance " << c.base_m
        << " m)";
  } else if (!(c.spheres_m > margins.obstacle_margin_m)) {
    why << "start state: arm collision (sphere " << c.sphere << " vs box " << c.sphere_box
        << ", clearance " << c.spheres_m << " m)";
  } else if (!(c.self_m > margins.self_margin_m)) {
    why << "start state: self collision (pair " << c.self_pair << ")";
  } else if (!(c.chassis_m > margins.self_margin_m)) {
    why << "start state: arm below the chassis top (sphere " << c.chassis_sphere << ")";
  } else {
    return {};
  }
  return Problem(PlanStatus::kFrontEndFailed, FrontEndStatus::kStartInvalid,
                 StartReason(kinematics, scene, start, margins, why.str()));
}

InputProblem CheckTarget(const Scene& scene, const SceneClearanceChecker& checker,
                         const Eigen::Isometry3d& X_WE_goal) {
  if (!X_WE_goal.matrix().allFinite()) {
    return Problem(PlanStatus::kInvalidInput, FrontEndStatus::kInvalidInput,
                   "target pose X_WE: contains NaN or infinity");
  }
  const Eigen::Vector3d p = X_WE_goal.translation();
  std::ostringstream why;
  if (!scene.bounds_W_m.contains(p)) {
    why << "target position (" << p.x() << ", " << p.y() << ", " << p.z()
        << ") m lies outside the scene's bounds";
  } else if (int box = -1; checker.PointClearance(p, 0.0, &box) < 0.0) {
    why << "target position lies inside box " << box;
  } else {
    return {};
  }
  const auto diagnosis = DiagnoseTarget(scene, X_WE_goal);  // below the floor, which box, ...
  return Problem(PlanStatus::kFrontEndFailed, FrontEndStatus::kNoGoal,
                 diagnosis ? "target: " + *diagnosis : why.str());
}

}  // namespace

ScenePlan PlanInScene(const Kinematics& kinematics, const Scene& scene,
                      const WholeBodyPlannerOptions& options, const WholeBodyState& start,
                      const Eigen::Isometry3d& X_WE_goal,
                      const std::optional<WholeBodyState>& hint, std::stop_token stop,
                      const std::optional<SceneDistanceFieldsOptions>& field_options) {
  const Clock::time_point t0 = Clock::now();
  CheckWholeBodyPlannerOptions(options);
  const Clock::time_point deadline = DeadlineAfter(t0, options.time_limit_s);
  ScenePlan plan;
  WholeBodyPlanResult& result = plan.result;
  const auto finish = [&](PlanStatus status, PlanStage stage, std::string reason) {
    result.status = status;
    result.stopped_stage = stage;
    result.failure_reason = std::move(reason);
    result.timings.total_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
    return std::move(plan);
  };

  // 1. Start and target, exactly (no field yet).
  {
    const SceneClearanceChecker checker(kinematics, scene);
    InputProblem problem = CheckStart(kinematics, scene, checker, start, options.validator);
    if (problem.reason.empty()) problem = CheckTarget(scene, checker, X_WE_goal);
    result.timings.start_check_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
    if (!problem.reason.empty()) {
      result.front_end.status = problem.front_end;
      result.front_end.failure_reason = problem.reason;
      return finish(problem.status, PlanStage::kNone, "front end: " + problem.reason);
    }
  }

  // 2. The fields, within the limit.
  const Clock::time_point t_map = Clock::now();
  std::stop_source map_stop;
  bool map_stopped = false;
  {
    const std::stop_callback forward(stop, [&map_stop] { map_stop.request_stop(); });
    const StopDeadline limit(&map_stop, deadline);
    plan.fields.emplace(BuildSceneDistanceFields(
        scene, field_options.value_or(PlannerFieldOptions(kinematics)), map_stop.get_token()));
    map_stopped = plan.fields->summary.stopped;
  }
  result.timings.map_ms = Stopwatch::MillisecondsBetween(t_map, Clock::now());
  if (map_stopped) {
    plan.fields.reset();
    if (stop.stop_requested()) {
      return finish(PlanStatus::kCancelled, PlanStage::kMapBuilding, "cancelled while building "
                                                                     "the distance fields");
    }
    return finish(PlanStatus::kTimeLimit, PlanStage::kMapBuilding,
                  TimeLimitPrefix(options.time_limit_s, PlanStage::kMapBuilding) +
                      "the distance fields were not finished");
  }

  // 3. The plan, by the same deadline.
  const WholeBodyPlanner planner(kinematics, plan.fields->base_field_2d, plan.fields->field_3d,
                                 scene, options);
  const PlanTimings before = result.timings;
  result = planner.PlanBy(deadline, start, X_WE_goal, hint, stop);
  result.timings.start_check_ms = before.start_check_ms;
  result.timings.map_ms = before.map_ms;
  result.timings.total_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
  return plan;
}

}  // namespace topay
