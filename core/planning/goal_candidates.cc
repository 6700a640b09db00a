#include "core/planning/goal_candidates.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/angles.h"
#include "core/common/stopwatch.h"

namespace topay {

void CheckGoalCandidatesOptions(const GoalCandidatesOptions& o) {
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) {
      throw std::invalid_argument(std::string("GoalCandidatesOptions::") + field + " must be " +
                                  rule);
    }
  };
  require(o.max_candidates >= 1, "max_candidates", ">= 1");
  require(o.travel_weight >= 0.0, "travel_weight", ">= 0");
  require(o.yaw_weight_m_per_rad >= 0.0, "yaw_weight_m_per_rad", ">= 0");
  require(o.clearance_weight >= 0.0, "clearance_weight", ">= 0");
  require(o.clearance_saturation_m >= 0.0, "clearance_saturation_m", ">= 0");
}

namespace {

GoalCandidate MakeCandidate(const IkSolution& solution, const WholeBodyState& start,
                            const GoalCandidatesOptions& o) {
  GoalCandidate candidate;
  candidate.state = solution.state;
  candidate.from_hint = solution.from_hint;
  candidate.base_stays = solution.base_stays;
  candidate.clearance_m = solution.clearance_m;
  candidate.base_travel_m = std::hypot(solution.state.x_m - start.x_m,
                                       solution.state.y_m - start.y_m);
  const double yaw_change_rad = std::abs(WrapAngle(solution.state.yaw_rad - start.yaw_rad));
  const double clearance_shortfall_m =
      std::max(0.0, o.clearance_saturation_m - solution.clearance_m);
  candidate.cost = o.travel_weight * candidate.base_travel_m +
                   o.yaw_weight_m_per_rad * yaw_change_rad +
                   o.clearance_weight * clearance_shortfall_m;
  return candidate;
}

}  // namespace

GoalCandidatesResult FindGoalCandidates(const WholeBodyIk& ik, const Eigen::Isometry3d& X_WE_target,
                                        const WholeBodyState& start,
                                        const std::optional<WholeBodyState>& hint,
                                        const StateClearanceFn& clearance,
                                        const GoalCandidatesOptions& options) {
  CheckGoalCandidatesOptions(options);
  const Stopwatch watch;
  GoalCandidatesResult result;
  WholeBodyIkQuery query;
  query.hint = hint;
  query.reference_base = Eigen::Vector3d(start.x_m, start.y_m, start.yaw_rad);
  if (options.standing_candidate) query.standing = start;
  query.reference_q_rad = start.q_rad;  // goals on the joints' nearest turns (finding 29)
  result.ik = ik.Solve(X_WE_target, clearance, query);
  if (!result.ik.success()) {
    result.failure_reason = "goal: " + result.ik.failure_reason;
  }
  for (const IkSolution& solution : result.ik.solutions) {
    result.candidates.push_back(MakeCandidate(solution, start, options));
  }
  std::stable_sort(result.candidates.begin(), result.candidates.end(),
                   [&options](const GoalCandidate& a, const GoalCandidate& b) {
                     if (options.hint_first && a.from_hint != b.from_hint) return a.from_hint;
                     return a.cost < b.cost;
                   });
  if (static_cast<int>(result.candidates.size()) > options.max_candidates) {
    result.candidates.resize(options.max_candidates);
  }
  result.time_s = watch.ElapsedS();
  return result;
}

}  // namespace topay
