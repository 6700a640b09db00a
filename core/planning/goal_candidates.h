#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/robot/whole_body_ik.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of FindGoalCandidates (Ceres style: documented defaults).
struct GoalCandidatesOptions {
  /// At most this many candidates are returned (the front end tries them in order).
  int max_candidates = 3;
  /// Ranking: cost = travel_weight * |p_B - p_B,start| (straight line, m)
  ///               + yaw_weight_m_per_rad * |yaw - yaw_start| (wrapped)
  ///               + clearance_weight * max(0, clearance_saturation_m - clearance_m).
  /// The yaw term is small: the base turns at every path vertex anyway.
  double travel_weight = 1.0;
  double yaw_weight_m_per_rad = 0.1;
  double clearance_weight = 2.0;
  double clearance_saturation_m = 0.3;
  /// A candidate found from the hint (the benchmark's generating goal state, or the hint
  /// polished by the IK) is placed first whatever its cost.
  bool hint_first = true;
  /// Ours: the start's base pose with the arm alone (WholeBodyIkQuery::standing: one arm-only
  /// IK run from the start's joints) is a candidate too, ranked like the rest (no base travel).
  /// A robot stopped next to its goal, where the base cannot turn (finding 29), finishes with
  /// the arm; a start out of the arm's reach costs one IK run that does not converge.
  bool standing_candidate = true;
};

/// One whole-body goal state for the end-effector target.
struct GoalCandidate {
  WholeBodyState state;
  double base_travel_m = 0.0;  ///< Straight-line base distance from the start.
  double clearance_m = 0.0;    ///< From the clearance function the IK was given.
  double cost = 0.0;           ///< Ranking cost (GoalCandidatesOptions).
  bool from_hint = false;
  /// The start's base pose exactly (GoalCandidatesOptions::standing_candidate): only the arm
  /// moves.
  bool base_stays = false;
};

struct GoalCandidatesResult {
  /// Best first (hint first if GoalCandidatesOptions::hint_first). Empty on failure.
  std::vector<GoalCandidate> candidates;
  /// Empty on success; otherwise the IK's reason (bad input, out of reach, all rejected).
  std::string failure_reason;
  /// The IK's statistics (solutions, rejection counts, solve time).
  WholeBodyIkResult ik;
  double time_s = 0.0;

  bool success() const { return !candidates.empty(); }
};

/// Whole-body goal states (paper Sec. III-A: s_f from the end-effector SE(3) target): runs the
/// whole-body IK with the hint tried first and the start's base pose as the reference, keeps
/// the solutions whose whole body is clear by `clearance` (the IK checks it; its
/// min_clearance_m applies), and ranks them by base travel from the start and clearance.
/// Thread-safe when `clearance` is.
GoalCandidatesResult FindGoalCandidates(const WholeBodyIk& ik, const Eigen::Isometry3d& X_WE_target,
                                        const WholeBodyState& start,
                                        const std::optional<WholeBodyState>& hint,
                                        const StateClearanceFn& clearance,
                                        const GoalCandidatesOptions& options = {});

/// Throws std::invalid_argument naming the first option out of its range.
void CheckGoalCandidatesOptions(const GoalCandidatesOptions& options);

}  // namespace topay
