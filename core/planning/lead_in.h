#pragma once

#include <string>
#include <vector>

#include "core/collision/scene_clearance.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/moving_state.h"
#include "core/robot/robot_model.h"

namespace topay {

/// Options of MakeLeadIn (issue 18, planning from a moving start).
struct LeadInOptions {
  /// Below this forward speed (|v|, m/s) there is no lead-in: the base can still turn on the
  /// spot, the front end plans from the start itself.
  double min_speed_mps = 0.05;
  /// Arc length beyond the braking distance v^2 / (2 a_max) (m): room for the optimizer to
  /// brake less hard than a_max.
  double extra_distance_m = 0.10;
  /// Spacing of the lead-in's states along its arc (m). Each state is checked (CheckLeadIn).
  double step_m = 0.02;
};

/// Throws std::invalid_argument ("LeadInOptions: <field> must ...") unless every field is
/// finite, min_speed_mps >= 0, extra_distance_m >= 0 and step_m > 0.
void CheckLeadInOptions(const LeadInOptions& options);

/// The base's braking motion along its current heading and curvature: the states the
/// whole-body path begins with when the start moves, and the state the front end plans from.
struct LeadIn {
  /// states[0] is the start; states.back() the lead-in's end. One state (the start) when the
  /// start is slower than min_speed_mps.
  std::vector<WholeBodyState> states;
  /// Times of a braking profile at a_max from |v| (s), same size as states.
  std::vector<double> times_s;
  double distance_m = 0.0;  ///< Arc length of the lead-in (>= 0, driven in v's direction).

  bool empty() const { return states.size() <= 1; }
  const WholeBodyState& end() const { return states.back(); }
};

/// The lead-in of a moving start (issue 18). A base moving at v cannot turn in place, so
/// the new path leaves along the arc the base is on: constant curvature kappa = omega / v
/// (the unicycle of the paper's eqs. (1)-(2), x' = s' cos yaw, y' = s' sin yaw, with
/// dyaw/ds = kappa), in the direction of v, over the braking distance v^2 / (2 a_max) plus
/// extra_distance_m. The joints move towards their own braking positions, q + qd |qd| /
/// (2 qdd_max) (clamped to the limits), linearly along the arc. For |v| < min_speed_mps the
/// lead-in is the start alone. Throws std::invalid_argument for bad options, a state or
/// rates that are not finite or of the wrong joint count, or bad limits.
LeadIn MakeLeadIn(const MovingState& start, const BaseLimits& base_limits,
                  const JointLimits& joint_limits, const LeadInOptions& options = {});

/// Checks every lead-in state after the start: valid on the fields (validity, without its
/// exact zones), or else, if `exact` is given, collision free on the exact scene with the
/// given margins (*used_exact is then set to true). Returns "" if all pass, else
/// "moving start: the lead-in along the current heading collides at <d> m (<why>)".
std::string CheckLeadIn(const LeadIn& lead_in, const WholeBodyValidity& validity,
                        const SceneClearanceChecker* exact, double obstacle_margin_m,
                        double self_margin_m, bool* used_exact);

}  // namespace topay
