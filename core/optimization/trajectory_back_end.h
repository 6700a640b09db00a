#pragma once

#include <stop_token>

#include "core/optimization/back_end_summary.h"
#include "core/optimization/trajectory_problem.h"
#include "core/planning/whole_body_path.h"

namespace topay {

/// The planner's back end (paper Sec. III-B..C): from a front-end whole-body path to an
/// optimized trajectory that meets the end-effector target (eq. (7)) and the limits on the
/// fields. Two implementations: TrajectoryOptimizer (TopAY's arc length-yaw MINCO) and
/// FlatnessOptimizer (the REMANI-style flatness baseline); MakeTrajectoryBackEnd
/// (back_end_factory.h) picks one from the options.
///
/// Optimize never throws for bad input (kInvalidInput with the reason), is const and
/// thread-safe; `stop` is polled by every objective evaluation and after every L-BFGS
/// iteration (kCancelled with the last iterate's trajectory where there is one).
class TrajectoryBackEnd {
 public:
  virtual ~TrajectoryBackEnd() = default;

  virtual BackEndSummary Optimize(const TrajectoryProblem& problem,
                                  const WholeBodyPath& initial_path,
                                  std::stop_token stop = {}) const = 0;

  /// The trajectory this back end builds (the summaries' parameterisation).
  virtual TrajectoryParameterisation parameterisation() const = 0;
};

}  // namespace topay
