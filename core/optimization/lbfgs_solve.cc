#include "core/optimization/lbfgs_solve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>

namespace topay {
namespace {

using Clock = std::chrono::steady_clock;

/// The objective as Ceres sees it (owned by the GradientProblem; the objective is not).
class CeresFunction : public ceres::FirstOrderFunction {
 public:
  explicit CeresFunction(LbfgsObjective* objective) : objective_(objective) {}
  bool Evaluate(const double* parameters, double* cost, double* gradient) const override {
    return objective_->Evaluate(parameters, cost, gradient);
  }
  int NumParameters() const override { return objective_->num_parameters(); }

 private:
  LbfgsObjective* objective_;
};

/// Stops the solver on a stop request, at the deadline, or on a small relative decrease over
/// the last `past` iterations.
class StopCallback : public ceres::IterationCallback {
 public:
  StopCallback(const LbfgsOptions& options, Clock::time_point deadline, std::stop_token stop)
      : options_(options), deadline_(deadline), stop_(std::move(stop)) {
    costs_.reserve(1024);
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (stop_.stop_requested()) {
      cancelled_ = true;
      return ceres::SOLVER_ABORT;
    }
    if (Clock::now() >= deadline_) {
      timed_out_ = true;
      return ceres::SOLVER_ABORT;
    }
    costs_.push_back(summary.cost);
    const int past = options_.relative_decrease_past;
    const int k = static_cast<int>(costs_.size()) - 1;
    if (k >= past) {
      const double f = costs_[k];
      const double decrease = (costs_[k - past] - f) / std::max(std::abs(f), 1.0);
      if (decrease < options_.relative_decrease_delta) {
        converged_ = true;
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
    }
    return ceres::SOLVER_CONTINUE;
  }

  bool cancelled() const { return cancelled_; }
  bool timed_out() const { return timed_out_; }
  bool converged() const { return converged_; }

 private:
  const LbfgsOptions& options_;
  Clock::time_point deadline_;
  std::stop_token stop_;
  std::vector<double> costs_;
  bool cancelled_ = false;
  bool timed_out_ = false;
  bool converged_ = false;
};

}  // namespace

void CheckLbfgsOptions(const LbfgsOptions& o) {
  const auto require = [](bool ok, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("LbfgsOptions: ") + rule);
  };
  require(o.memory >= 1, "memory must be >= 1");
  require(o.max_iterations >= 1, "max_iterations must be >= 1");
  require(o.relative_decrease_past >= 1, "relative_decrease_past must be >= 1");
  require(o.relative_decrease_delta >= 0.0, "relative_decrease_delta must be >= 0");
  require(o.sufficient_decrease > 0.0, "sufficient_decrease must be > 0");
  require(o.curvature > o.sufficient_decrease && o.curvature < 1.0,
          "curvature must be in (sufficient_decrease, 1)");
}

std::string_view ToString(LbfgsStop stop) {
  switch (stop) {
    case LbfgsStop::kConverged: return "converged";
    case LbfgsStop::kMaxIterations: return "iteration limit";
    case LbfgsStop::kTimeLimit: return "time limit";
    case LbfgsStop::kCancelled: return "cancelled";
    case LbfgsStop::kFailed: return "failed";
  }
  return "unknown";
}

LbfgsResult SolveWithLbfgs(LbfgsObjective* objective, Eigen::VectorXd* x,
                           const LbfgsOptions& options, Clock::time_point deadline,
                           std::stop_token stop) {
  CheckLbfgsOptions(options);
  if (x->size() != objective->num_parameters()) {
    throw std::invalid_argument("SolveWithLbfgs: x has " + std::to_string(x->size()) +
                                " entries, the objective " +
                                std::to_string(objective->num_parameters()));
  }
  LbfgsResult result;
  const double remaining_s = std::chrono::duration<double>(deadline - Clock::now()).count();
  if (stop.stop_requested() || remaining_s <= 0.0) {
    result.stop = stop.stop_requested() ? LbfgsStop::kCancelled : LbfgsStop::kTimeLimit;
    return result;
  }
  StopCallback callback(options, deadline, stop);
  ceres::GradientProblemSolver::Options ceres_options;
  ceres_options.line_search_direction_type = ceres::LBFGS;
  ceres_options.line_search_type = ceres::WOLFE;
  ceres_options.max_lbfgs_rank = options.memory;
  ceres_options.use_approximate_eigenvalue_bfgs_scaling = options.approximate_eigenvalue_scaling;
  ceres_options.line_search_sufficient_function_decrease = options.sufficient_decrease;
  ceres_options.line_search_sufficient_curvature_decrease = options.curvature;
  ceres_options.max_num_iterations = options.max_iterations;
  ceres_options.max_solver_time_in_seconds = remaining_s;
  ceres_options.function_tolerance = 1e-12;  // the callback's relative decrease governs
  ceres_options.gradient_tolerance = 1e-12;
  ceres_options.parameter_tolerance = 1e-12;
  ceres_options.logging_type = ceres::SILENT;
  // x then always holds the last accepted iterate, also when Ceres ends with FAILURE or the
  // callback aborts (Ceres does not copy its final state back in those cases).
  ceres_options.update_state_every_iteration = true;
  ceres_options.callbacks.push_back(&callback);
  ceres::GradientProblem problem(new CeresFunction(objective));
  ceres::GradientProblemSolver::Summary summary;
  const int evaluations_before = objective->num_evaluations();
  ceres::Solve(ceres_options, problem, x->data(), &summary);
  result.message = summary.message;
  result.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  result.evaluations = objective->num_evaluations() - evaluations_before;
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  if (callback.cancelled() || objective->stopped()) {
    result.stop = LbfgsStop::kCancelled;
  } else if (callback.timed_out() || Clock::now() >= deadline) {
    result.stop = LbfgsStop::kTimeLimit;
  } else if (callback.converged() || summary.termination_type == ceres::CONVERGENCE ||
             summary.termination_type == ceres::USER_SUCCESS) {
    result.stop = LbfgsStop::kConverged;
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    result.stop = LbfgsStop::kMaxIterations;
  } else {
    result.stop = LbfgsStop::kFailed;
  }
  return result;
}

}  // namespace topay
