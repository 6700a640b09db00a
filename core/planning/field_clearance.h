#pragma once

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/planning/whole_body_validity.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Whole-body clearance (m) of a state on the distance fields, beyond the margins the validity
/// requires, for ranking goal candidates (core/planning/goal_candidates.h):
///   c = min( base_field(p_WB) - r_base - base_margin,
///            min_s arm_field(p_WS) - r_s - arm_margin ),
/// so c >= 0 where the field checks pass. A state that fails validity.Check (joint limits,
/// self-collision, chassis, or a field check) gets c = -1 whatever the fields say, so
/// c > 0 implies the state is valid. The fields must be the ones `validity` was built on.
/// Allocation-free given a workspace from validity.MakeWorkspace().
double FieldClearance(const WholeBodyValidity& validity, const SignedDistanceField2& base_field,
                      const SignedDistanceField3& arm_field, const WholeBodyState& state,
                      WholeBodyValidityWorkspace* workspace);

}  // namespace topay
