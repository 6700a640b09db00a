#include "core/planning/field_clearance.h"

#include <algorithm>

namespace topay {

double FieldClearance(const WholeBodyValidity& validity, const SignedDistanceField2& base_field,
                      const SignedDistanceField3& arm_field, const WholeBodyState& state,
                      WholeBodyValidityWorkspace* workspace) {
  if (validity.Check(state, workspace) != ValidityFailure::kNone) return -1.0;
  const RobotModel& model = validity.model();
  double clearance_m = base_field.Distance(Eigen::Vector2d(state.x_m, state.y_m)) -
                       model.base_cylinder.radius_m - validity.base_margin_m();
  validity.kinematics().Update(state, &workspace->cache);
  for (const int s : validity.arm_field_spheres()) {
    clearance_m = std::min(clearance_m, arm_field.Distance(workspace->cache.p_WS[s]) -
                                            model.spheres[s].radius_m - validity.arm_margin_m());
  }
  return clearance_m;
}

}  // namespace topay
