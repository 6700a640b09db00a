#pragma once

#include <chrono>
#include <stop_token>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "core/optimization/lbfgs_objective.h"

namespace topay {

/// Options of the inner solver (Ceres' GradientProblemSolver, L-BFGS direction, Wolfe line
/// search). Defaults: the authors' code's L-BFGS figures.
struct LbfgsOptions {
  /// Memory (rank of the inverse Hessian approximation).
  int memory = 256;
  /// Iterations per solve.
  int max_iterations = 8000;
  /// Relative-decrease stop: after iteration k >= past, stop when
  /// (f_{k - past} - f_k) / max(|f_k|, 1) < relative_decrease_delta.
  double relative_decrease_delta = 1e-4;
  int relative_decrease_past = 3;
  /// Wolfe line search: sufficient decrease (Armijo) and curvature constants.
  double sufficient_decrease = 1e-4;
  double curvature = 0.9;
  /// Oren's scaling of the initial inverse Hessian (gamma = s^T y / y^T y), Nocedal & Wright's
  /// usual choice; off, Ceres starts every update from the identity.
  bool approximate_eigenvalue_scaling = true;
};

/// How an inner solve ended.
enum class LbfgsStop {
  kConverged,       ///< Relative-decrease stop or Ceres' own tolerances.
  kMaxIterations,
  kTimeLimit,       ///< The deadline passed.
  kCancelled,       ///< The stop token was triggered.
  kFailed,          ///< Ceres failed (line search, evaluation at the start, ...).
};
std::string_view ToString(LbfgsStop stop);

struct LbfgsResult {
  LbfgsStop stop = LbfgsStop::kFailed;
  std::string message;  ///< Ceres' message.
  int iterations = 0;
  int evaluations = 0;  ///< Objective evaluations (with or without gradient).
  double initial_cost = 0.0;
  double final_cost = 0.0;
};

/// Throws std::invalid_argument unless memory, max_iterations and relative_decrease_past are
/// >= 1, relative_decrease_delta >= 0 and 0 < sufficient_decrease < curvature < 1.
void CheckLbfgsOptions(const LbfgsOptions& options);

/// Minimises the objective's current terms from *x (updated in place: the last accepted
/// iterate) with ceres::GradientProblemSolver (LBFGS, WOLFE). The stop token is polled inside
/// every objective evaluation (the objectives' set_stop_token: an evaluation after a stop
/// request fails at once) and by an iteration callback that aborts the solver; the deadline
/// is checked by the callback and passed to Ceres as its time limit.
/// Throws std::invalid_argument for options out of range or a wrong x size.
LbfgsResult SolveWithLbfgs(LbfgsObjective* objective, Eigen::VectorXd* x,
                           const LbfgsOptions& options,
                           std::chrono::steady_clock::time_point deadline,
                           std::stop_token stop);

}  // namespace topay
