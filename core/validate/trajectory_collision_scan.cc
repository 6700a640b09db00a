#include "core/validate/trajectory_collision_scan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace topay {
namespace {

void CheckScanInput(const TrajectoryCollisionScanOptions& options, double t_from_s, double t_to_s) {
  if (!std::isfinite(options.sample_period_s) || options.sample_period_s <= 0.0) {
    throw std::invalid_argument("FirstPredictedCollision: sample_period_s must be finite and > 0");
  }
  if (!std::isfinite(options.obstacle_margin_m) || options.obstacle_margin_m < 0.0) {
    throw std::invalid_argument("FirstPredictedCollision: obstacle_margin_m must be finite and >= 0");
  }
  if (!std::isfinite(t_from_s) || !std::isfinite(t_to_s)) {
    throw std::invalid_argument("FirstPredictedCollision: times must be finite");
  }
}

}  // namespace

std::optional<PredictedCollision> FirstPredictedCollision(
    const ArcYawTrajectory& trajectory, double t_from_s, double t_to_s,
    const SceneClearanceChecker& checker, const TrajectoryCollisionScanOptions& options) {
  CheckScanInput(options, t_from_s, t_to_s);
  const double t_begin = std::clamp(t_from_s, 0.0, trajectory.duration_s());
  const double t_end = std::clamp(t_to_s, t_begin, trajectory.duration_s());
  const TrajectorySampler along = [&trajectory](double t_s, TrajectorySample* sample) { trajectory.Evaluate(t_s, sample); };
  return FirstPredictedCollisionOf(along, trajectory.MakePoint(), t_begin, t_end, checker, options);
}

std::optional<PredictedCollision> FirstPredictedCollisionOf(const TrajectorySampler& motion, TrajectorySample point,
                                                            double t_begin_s, double t_end_s,
                                                            const SceneClearanceChecker& checker,
                                                            const TrajectoryCollisionScanOptions& options) {
  CheckScanInput(options, t_begin_s, t_end_s);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  // Boxes farther than the margin cannot make a sample collide: the cutoff skips them.
  const double cutoff_m = options.obstacle_margin_m + 1e-9;
  const double steps = std::ceil((t_end_s - t_begin_s) / options.sample_period_s);
  if (!(steps < 1e7)) throw std::invalid_argument("FirstPredictedCollision: more than 1e7 samples asked for");
  const int n = std::max(0, static_cast<int>(steps));
  for (int k = 0; k <= n; ++k) {
    const double t = std::min(t_begin_s + k * options.sample_period_s, t_end_s);
    motion(t, &point);
    checker.kinematics().Update(point.state, &workspace.cache);
    SceneClearance clearance;
    checker.ComputeObstacleParts(workspace.cache, cutoff_m, &clearance);
    if (clearance.obstacle_m() <= options.obstacle_margin_m) return PredictedCollision{t, clearance};
  }
  return std::nullopt;
}

}  // namespace topay
