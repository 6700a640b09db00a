#include "core/planning/arm_rrt_star.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/planning/layered_rrt_search.h"

// The search itself (and how it maps onto paper Algorithm 1) is in layered_rrt_search.h.

namespace topay {
namespace {

ArmRrtStarResult Failure(ArmRrtStarStatus status, std::string message) {
  ArmRrtStarResult result;
  result.status = status;
  result.message = std::move(message);
  return result;
}


/// Empty if every base layer and every translation between layers is clear on the 2D field.
std::string CheckBasePath(const DiscreteSE2Path& base, const WholeBodyValidity& validity) {
  const double step = validity.options().max_edge_step_m;
  for (int l = 0; l < base.num_layers(); ++l) {
    const Se2Layer& layer = base.layers[static_cast<std::size_t>(l)];
    const Eigen::Vector2d p(layer.x_m, layer.y_m);
    if (l == 0) {
      if (!validity.IsBaseValid(p)) return "base layer 0 not clear on the 2D field";
      continue;
    }
    const Se2Layer& previous = base.layers[static_cast<std::size_t>(l - 1)];
    const Eigen::Vector2d p0(previous.x_m, previous.y_m);
    const int steps = std::max(1, static_cast<int>(std::ceil((p - p0).norm() / step)));
    for (int k = 1; k <= steps; ++k) {
      if (!validity.IsBaseValid(p0 + (p - p0) * (static_cast<double>(k) / steps))) {
        return "base motion into layer " + std::to_string(l) + " not clear on the 2D field";
      }
    }
  }
  return {};
}

std::string CheckSequence(const DiscreteSE2Path& base) {
  if (base.layers.empty()) return "empty base sequence";
  for (std::size_t l = 0; l < base.layers.size(); ++l) {
    const Se2Layer& layer = base.layers[l];
    if (!std::isfinite(layer.x_m) || !std::isfinite(layer.y_m) || !std::isfinite(layer.yaw_rad) ||
        !std::isfinite(layer.time_s) || !(layer.step_time_s >= 0.0)) {
      return "base layer " + std::to_string(l) + " has a non-finite value or negative time";
    }
  }
  return {};
}

}  // namespace

std::string CheckArmRrtStarOptions(const ArmRrtStarOptions& options, int num_joints) {
  if (!(options.time_budget_s > 0.0)) return "options.time_budget_s must be > 0";
  if (options.max_iterations < 0) return "options.max_iterations must be >= 0";
  if (!(options.goal_bias >= 0.0 && options.goal_bias <= 1.0)) {
    return "options.goal_bias must be in [0, 1]";
  }
  if (!(options.stow_bias >= 0.0 && options.stow_bias <= 1.0)) {
    return "options.stow_bias must be in [0, 1]";
  }
  if (!(options.rewire_radius_rad >= 0.0)) return "options.rewire_radius_rad must be >= 0";
  if (options.max_neighbours < 1) return "options.max_neighbours must be >= 1";
  if (options.max_informed_draws < 0) return "options.max_informed_draws must be >= 0";
  if (options.max_nodes < 2) return "options.max_nodes must be >= 2";
  const Eigen::VectorXd& w = options.joint_weights;
  if (w.size() != 0 && ((num_joints >= 0 && w.size() != num_joints) || !w.allFinite() || !(w.array() > 0.0).all())) {
    return "options.joint_weights must be empty or " + std::to_string(num_joints) +
           " positive finite values";
  }
  return {};
}

ArmRrtStarResult PlanArmRrtStar(const DiscreteSE2Path& base_sequence,
                                const Eigen::VectorXd& q_start_rad,
                                const Eigen::VectorXd& q_goal_rad,
                                const WholeBodyValidity& validity, const ArmRrtStarOptions& options,
                                std::stop_token stop) {
  const int n = validity.model().num_joints();
  if (std::string problem = CheckSequence(base_sequence); !problem.empty()) {
    return Failure(ArmRrtStarStatus::kInvalidInput, problem);
  }
  if (q_start_rad.size() != n || q_goal_rad.size() != n) {
    return Failure(ArmRrtStarStatus::kInvalidInput,
                   "start/goal joint vectors must have " + std::to_string(n) + " entries");
  }
  if (std::string problem = CheckArmRrtStarOptions(options, n); !problem.empty()) {
    return Failure(ArmRrtStarStatus::kInvalidInput, problem);
  }
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  const int last = base_sequence.num_layers() - 1;
  const ValidityFailure start = validity.Check(base_sequence.State(0, q_start_rad), &workspace);
  if (start != ValidityFailure::kNone) {
    return Failure(ArmRrtStarStatus::kStartInvalid, "start state: " + std::string(ToString(start)));
  }
  const ValidityFailure goal = validity.Check(base_sequence.State(last, q_goal_rad), &workspace);
  if (goal != ValidityFailure::kNone) {
    return Failure(ArmRrtStarStatus::kGoalInvalid, "goal state: " + std::string(ToString(goal)));
  }
  if (std::string problem = CheckBasePath(base_sequence, validity); !problem.empty()) {
    return Failure(ArmRrtStarStatus::kBasePathInvalid, problem);
  }
  const Eigen::VectorXd reach =
      validity.model().joint_limits.qd_max_radps * base_sequence.total_time_s();
  if (((q_goal_rad - q_start_rad).cwiseAbs().array() > reach.array() * (1.0 + 1e-9)).any()) {
    return Failure(ArmRrtStarStatus::kNoSolution,
                   "goal joints not reachable at the joint speed limits within the base "
                   "sequence's " +
                       std::to_string(base_sequence.total_time_s()) + " s");
  }
  if (last == 0) {  // start and goal on one layer, and (from the check above) the same q
    ArmRrtStarResult result;
    result.status = ArmRrtStarStatus::kSuccess;
    result.path.states.push_back(base_sequence.State(0, q_start_rad));
    result.path.times_s.push_back(0.0);
    result.stats.final_cost = result.stats.first_cost = 0.0;
    result.stats.time_to_first_solution_s = 0.0;
    if (options.on_first_solution) options.on_first_solution(0.0);
    return result;
  }
  const Eigen::VectorXd weights =
      options.joint_weights.size() == 0 ? Eigen::VectorXd::Ones(n) : options.joint_weights;
  LayeredRrtSearch search(base_sequence, q_start_rad, q_goal_rad, validity, options, weights,
                          std::move(stop));
  return search.Run();
}

std::string_view ToString(ArmRrtStarStatus status) {
  switch (status) {
    case ArmRrtStarStatus::kSuccess:
      return "success";
    case ArmRrtStarStatus::kInvalidInput:
      return "invalid input";
    case ArmRrtStarStatus::kStartInvalid:
      return "start state invalid";
    case ArmRrtStarStatus::kGoalInvalid:
      return "goal state invalid";
    case ArmRrtStarStatus::kBasePathInvalid:
      return "base path invalid";
    case ArmRrtStarStatus::kNoSolution:
      return "no solution";
    case ArmRrtStarStatus::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace topay
