#pragma once

#include <string>

#include "core/collision/scene_clearance.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/planning/exact_zones.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// What the goal search's clearance function decided, state by state, and why.
struct GoalClearanceTally {
  int field_accepted = 0;   ///< Clear on the fields.
  int exact_accepted = 0;   ///< Rejected by the fields, exactly clear (tight goals).
  int joint_limit = 0;      ///< Rejected: a joint outside its limits.
  int self_collision = 0;   ///< Rejected: a self pair or the arm below the chassis top.
  int exact_base = 0;       ///< Rejected exactly: the base cylinder at or inside the margin.
  int exact_arm = 0;        ///< Rejected exactly: an arm sphere at or inside the margin.
  int field_only = 0;       ///< Rejected by the fields, with no exact check configured.

  int rejected() const {
    return joint_limit + self_collision + exact_base + exact_arm + field_only;
  }
  /// E.g. "12 states checked: 0 clear on the fields, 1 only exactly; rejected 3 arm sphere
  /// vs box, 8 base vs box (exact geometry)".
  std::string Describe() const;
};

/// The clearance (m) the front end gives the whole-body IK for goal states
/// (StateClearanceFn): the fields' clearance beyond the validity's margins
/// (FieldClearance) where they accept the state; where they reject it for the base or an arm
/// sphere and an exact checker is given, the exact scene decides at the zones' margins: an
/// exactly clear state gets kExactOnlyClearance (> 0, so it is a solution, ranked behind
/// every state clear on the fields), another -1. Counts every decision (tally()).
/// One per thread (scratch); the validity, fields and checker must outlive it.
class GoalClearance {
 public:
  /// Tiny positive clearance of a state only the exact scene accepts.
  static constexpr double kExactOnlyClearance = 1e-6;

  GoalClearance(const WholeBodyValidity& validity, const SignedDistanceField2& base_field,
                const SignedDistanceField3& arm_field, const SceneClearanceChecker* exact,
                const ExactZoneOptions& margins);

  double operator()(const WholeBodyState& state);
  const GoalClearanceTally& tally() const { return tally_; }

 private:
  const WholeBodyValidity& validity_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  const SceneClearanceChecker* exact_;
  ExactZoneOptions margins_;
  WholeBodyValidityWorkspace workspace_;
  SceneClearanceWorkspace exact_workspace_;
  GoalClearanceTally tally_;
};

}  // namespace topay
