#pragma once

namespace topay {

/// What the inner L-BFGS solve (lbfgs_solve.h) needs of an objective: both parameterisations'
/// objectives (TrajectoryObjective, the arc length-yaw one of eqs. (6)-(23), and
/// FlatnessObjective, the baseline) implement it.
class LbfgsObjective {
 public:
  virtual ~LbfgsObjective() = default;
  virtual int num_parameters() const = 0;
  /// f(x) and, if gradient is non-null, df/dx. False: not evaluable here (or stopped).
  virtual bool Evaluate(const double* x, double* cost, double* gradient) = 0;
  /// True once an evaluation failed because a stop was requested.
  virtual bool stopped() const = 0;
  virtual int num_evaluations() const = 0;
};

}  // namespace topay
