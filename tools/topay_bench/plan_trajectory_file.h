#pragma once

#include <vector>

#include "core/planner/whole_body_plan_result.h"
#include "core/trajectory/trajectory_sample.h"
#include "tools/topay_plan/trajectory_record.h"

namespace topay::bench {

/// Samples of any validated trajectory (either parameterisation) in the trajectory file's
/// form: t = 0, period, 2 period, ... (below the end by more than 1e-9 s) and the exact end,
/// as plan::SampleTrajectory. s_m is the travelled arc length, the trapezoid integral of
/// |v| over the samples. Throws std::invalid_argument for a period outside [1e-4, 10] s or a
/// trajectory without a sampler.
std::vector<TrajectorySample> SampleForFile(const SampledTrajectory& trajectory,
                                           double period_s);

/// The trajectory file (tools/topay_plan/trajectory_json.h) of a plan with the given metadata: for
/// the arc length-yaw trajectory its pieces and plan::SampleTrajectory's samples, as
/// topay-plan writes them; for the flatness baseline no pieces (trajectory null) and
/// SampleForFile's samples; for a failure, metadata only.
plan::TrajectoryFile PlanTrajectoryFile(const plan::TrajectoryMetadata& metadata,
                                        const WholeBodyPlanResult& plan, double period_s);

}  // namespace topay::bench
