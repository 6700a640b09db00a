#pragma once

#include "tools/topay_plan/plan_query.h"
#include "core/planner/whole_body_planner_options.h"
#include "tools/topay_plan/plan_tool.h"
#include "tools/topay_plan/trajectory_record.h"

namespace topay::plan {

/// The parts of a PlanToolSummary that come from the options and the query (before the map
/// and the plan): scene (kind, seed, source, boxes, size), task (source, range, seed, start,
/// goal pose, base distance when the query has a goal state), whether the goal hint is used,
/// and the planner settings (threads: 0 becomes the hardware's count). Used by topay-plan
/// and topay-bench.
void FillQueryInputs(const PlanToolOptions& options, const PlanQuery& query,
                     PlanToolSummary* summary);

/// The planner settings in force (after the YAML and the flags) for the report.
void FillPlannerSettings(const WholeBodyPlannerOptions& in_force, BaseLimitChoice choice,
                         PlanToolSummary* summary);

/// The trajectory file's metadata of a plan: scene, task, base limits, status, reason,
/// timings, map build time and the chosen candidate's validator figures (if any).
TrajectoryMetadata MetadataOf(const PlanToolOptions& options, const PlanToolSummary& summary);

}  // namespace topay::plan
