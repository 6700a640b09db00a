#pragma once

#include <string>

namespace topay {

/// What the NMPC solver did: the last solve and counters since construction.
struct NmpcSummary {
  // The last solve.
  double solve_ms = 0.0;          ///< Wall time of the whole solve (base + joints + projection).
  double base_solve_ms = 0.0;     ///< The base problem's Ceres solve.
  double joint_solve_ms = 0.0;    ///< The joint problems' Ceres solves, together.
  int base_iterations = 0;        ///< Ceres iterations of the base problem.
  int joint_iterations = 0;       ///< Ceres iterations of the joint problems, summed.
  double base_initial_cost = 0.0; ///< Ceres cost of the base problem at the warm start.
  double base_final_cost = 0.0;   ///< ... and at the solution.
  bool fell_back = false;         ///< Over budget (or failed): the shifted previous solution.
  int projected_inputs = 0;       ///< Inputs the final projection moved (> 1e-9) in this solve.

  // Since construction.
  int num_solves = 0;
  int num_over_budget = 0;        ///< Solves over time_budget_s (fell back).
  int num_failed = 0;             ///< Solves Ceres reported as failed (fell back).
  int num_warm_resets = 0;        ///< Warm starts reset (new trajectory).

  /// A few readable lines.
  std::string Report() const;
};

}  // namespace topay
