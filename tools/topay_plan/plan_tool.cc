#include "tools/topay_plan/plan_tool.h"

#include <sstream>

#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/plan_in_scene.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "tools/topay_plan/candidate_table.h"
#include "tools/topay_plan/plan_query.h"
#include "tools/topay_plan/plan_summary_fill.h"
#include "tools/topay_plan/trajectory_json.h"
#include "tools/viz/png_io.h"
#include "tools/viz/time_plot.h"
#include "tools/viz/trajectory_view.h"

namespace topay::plan {
namespace {

// The planner options in force: the YAML's (or the defaults), then the flags that were given.
WholeBodyPlannerOptions PlannerOptionsInForce(const PlanToolOptions& o, const RobotModel& model,
                                              BaseLimitChoice* choice) {
  WholeBodyPlannerOptions options =
      o.planner_config.empty() ? WholeBodyPlannerOptions{} : LoadPlannerOptions(o.planner_config);
  PlannerOverrides overrides = o.overrides;
  if (!o.base_limits.empty()) overrides.base_limits = ParseBaseLimitChoice(o.base_limits);
  *choice = ApplyPlannerOverrides(overrides, model, &options);
  return options;
}

void WriteJson(const PlanToolOptions& o, PlanToolSummary* s) {
  TrajectoryFile file;
  file.metadata = MetadataOf(o, *s);
  file.sample_period_s = o.sample_period_s;
  if (s->plan.trajectory) {
    file.pieces = PiecesOf(*s->plan.trajectory);
    file.samples = SampleTrajectory(*s->plan.trajectory, o.sample_period_s);
  }
  WriteTrajectoryJson(o.trajectory_json_out, file);
  s->trajectory_json = o.trajectory_json_out;
  s->num_samples = static_cast<int>(file.samples.size());
}

std::string SceneTitle(const PlanToolSummary& s) {
  std::ostringstream out;
  out << (s.scene_kind.empty() ? "scene" : s.scene_kind) << " seed " << s.scene_seed << ", "
      << s.num_boxes << " boxes";
  return out.str();
}

std::string PlanTitle(const PlanToolSummary& s) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(1);
  out << (s.task_range.empty() ? "" : s.task_range + " ") << "task (" << s.task_source << "): ";
  if (s.plan.trajectory) {
    out << "trajectory " << s.plan.trajectory->duration_s() << " s, planned in "
        << s.plan.timings.total_ms << " ms";
  } else {
    out << "plan failed (" << ToString(s.plan.status) << ")";
  }
  return out.str();
}

void WritePathPng(const PlanToolOptions& o, const PlanQuery& q,
                  const std::optional<SceneDistanceFields>& fields, const Kinematics& kinematics,
                  PlanToolSummary* s) {
  viz::TrajectoryView view;
  view.scene = &q.scene;
  view.base_field = fields ? &fields->base_field_2d : nullptr;  // none if the start was refused
  view.kinematics = &kinematics;
  view.start = q.start;
  view.X_WE_goal = q.X_WE_goal;
  view.trajectory = s->plan.trajectory ? &*s->plan.trajectory : nullptr;
  view.title_lines = {SceneTitle(*s), PlanTitle(*s)};
  viz::TrajectoryViewOptions options;
  options.scene.px_per_m = o.px_per_m;
  options.trajectory.footprint_interval_s = o.footprint_interval_s;
  const viz::Image image = viz::RenderTrajectoryView(view, options);
  viz::WritePng(image, o.path_png_out);
  s->path_png = o.path_png_out;
  s->path_png_width_px = image.width();
  s->path_png_height_px = image.height();
}

void WriteTimePng(const PlanToolOptions& o, const Kinematics& kinematics, PlanToolSummary* s) {
  if (!s->plan.trajectory) {
    s->time_png_skipped = "no trajectory to plot";
    return;
  }
  viz::TimePlotLimits limits;
  limits.base = s->base_limits;
  limits.q_min_rad = kinematics.model().joint_limits.q_min_rad;
  limits.q_max_rad = kinematics.model().joint_limits.q_max_rad;
  viz::TimePlotOptions options;
  options.title = SceneTitle(*s) + "\n" + PlanTitle(*s);
  const viz::Image image = viz::RenderTimePlots(
      viz::SampleTimePlotData(*s->plan.trajectory, o.sample_period_s), limits, options);
  viz::WritePng(image, o.time_png_out);
  s->time_png = o.time_png_out;
  s->time_png_width_px = image.width();
  s->time_png_height_px = image.height();
}

}  // namespace

PlanToolSummary RunPlanTool(const PlanToolOptions& options) {
  CheckPlanToolOptions(options);
  CheckOutputFolders(options);
  const RobotModel model = LoadRobotModel(options.robot_urdf, options.robot_yaml);
  const Kinematics kinematics(model);
  const PlanQuery query = ResolvePlanQuery(options, kinematics);

  PlanToolSummary summary;
  FillQueryInputs(options, query, &summary);
  BaseLimitChoice choice = BaseLimitChoice::kBenchmark;
  const WholeBodyPlannerOptions planner_options = PlannerOptionsInForce(options, model, &choice);
  FillPlannerSettings(planner_options, choice, &summary);

  // One time limit over everything: the exact start and target check, the fields, the plan.
  const SceneDistanceFieldsOptions field_options = PlannerFieldOptions(kinematics);
  ScenePlan scene_plan =
      PlanInScene(kinematics, query.scene, planner_options, query.start, query.X_WE_goal,
                  summary.used_goal_hint ? query.goal_state : std::nullopt, {}, field_options);
  summary.plan = std::move(scene_plan.result);
  summary.map_build_ms = summary.plan.timings.map_ms;
  summary.arm_field_resolution_m = field_options.resolution_m;
  summary.base_field_resolution_m = field_options.base_resolution_m > 0.0
                                        ? field_options.base_resolution_m
                                        : field_options.resolution_m;
  if (scene_plan.fields) summary.arm_field_cells = scene_plan.fields->field_3d.geometry().dims;
  summary.candidates = CandidateRows(summary.plan);

  if (!options.trajectory_json_out.empty()) WriteJson(options, &summary);
  if (!options.path_png_out.empty()) {
    WritePathPng(options, query, scene_plan.fields, kinematics, &summary);
  }
  if (!options.time_png_out.empty()) WriteTimePng(options, kinematics, &summary);
  return summary;
}

}  // namespace topay::plan
