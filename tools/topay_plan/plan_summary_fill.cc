#include "tools/topay_plan/plan_summary_fill.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

namespace topay::plan {

void FillQueryInputs(const PlanToolOptions& o, const PlanQuery& q, PlanToolSummary* s) {
  s->scene_kind = q.scene.kind;
  s->scene_seed = q.scene.seed;
  s->scene_source = q.scene_source;
  s->num_boxes = static_cast<int>(q.scene.boxes.size());
  s->scene_size_m = q.scene.bounds_W_m.sizes();
  s->task_source = q.task_source;
  s->task_range = q.task_range;
  s->task_seed = q.task_seed;
  if (q.goal_state) {
    s->base_distance_m =
        std::hypot(q.goal_state->x_m - q.start.x_m, q.goal_state->y_m - q.start.y_m);
  }
  s->start = q.start;
  s->X_WE_goal = q.X_WE_goal;
  s->used_goal_hint = o.use_goal_hint && q.goal_state.has_value();
}

void FillPlannerSettings(const WholeBodyPlannerOptions& in_force, BaseLimitChoice choice,
                         PlanToolSummary* s) {
  s->sequential = in_force.sequential;
  s->time_limit_s = in_force.time_limit_s;
  s->num_threads = in_force.num_threads > 0
                       ? in_force.num_threads
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  s->limit_choice = choice;
  s->base_limits = in_force.base_limits.value_or(BaseLimits{});
}

TrajectoryMetadata MetadataOf(const PlanToolOptions& o, const PlanToolSummary& s) {
  TrajectoryMetadata m;
  m.scene_kind = s.scene_kind;
  m.scene_seed = s.scene_seed;
  m.scene_file = o.scene_file;
  m.num_boxes = s.num_boxes;
  m.task_source =
      s.task_source == "generated" || s.task_source == "command line" ? s.task_source : "task file";
  m.task_file = o.task_file;
  m.task_range = s.task_range;
  m.task_seed = s.task_seed;
  m.start = s.start;
  m.X_WE_goal = s.X_WE_goal;
  m.base_limits_source = std::string(BaseLimitChoiceName(s.limit_choice));
  m.base_limits = s.base_limits;
  m.status = std::string(ToString(s.plan.status));
  m.failure_reason = s.plan.failure_reason;
  m.timings = s.plan.timings;
  m.map_build_ms = s.map_build_ms;
  if (const CandidateReport* c = s.plan.chosen_candidate(); c != nullptr && c->validation) {
    m.validation = FiguresOf(*c->validation);
  }
  return m;
}

}  // namespace topay::plan
