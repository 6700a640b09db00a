#include "core/planning/planner_fields.h"

#include <algorithm>

#include "core/planning/base_band.h"

namespace topay {

SceneDistanceFieldsOptions PlannerFieldOptions(const Kinematics& kinematics) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.05;
  options.base_resolution_m = 0.01;
  options.base_exact_cap_m = 1.0;
  options.arm_exact_cap_m = 1.0;
  const RigidLowerBody body = RigidLowerBodyOf(kinematics);
  options.base_band = HeightBand{0.0, body.chassis_top_m};
  if (body.top_m > body.chassis_top_m) {
    // Up to the rigid top plus the 3D field's margin: the arm, however folded, reaches at
    // least the rigid top, and its moving spheres need that margin on the 3D field, so the
    // base must not pass under anything lower. The rigid spheres themselves are checked by this
    // band exactly (offset = radius - their reach, no 3D margin; SpheresToCheckOnArmField).
    const double arm_margin_m = ArmFieldMargin(options);  // WholeBodyValidity's
    options.base_upper_band = HeightBand{0.0, body.top_m + arm_margin_m};
    options.base_upper_band_offset_m =
        std::max(0.0, kinematics.model().base_cylinder.radius_m - body.sphere_reach_m);
  }
  return options;
}

}  // namespace topay
