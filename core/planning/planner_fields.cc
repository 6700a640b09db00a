#include "core/planning/planner_fields.h"

#include <algorithm>

#include "core/planning/base_band.h"

namespace topay {

SceneDistanceFieldsOptions PlannerFieldOptions(const Kinematics& kinematics) {
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.05;
  options.base_resolution_m = 0.01;
  options.base_exact_cap_m = 1.0;
  const RigidLowerBody body = RigidLowerBodyOf(kinematics);
  options.base_band = HeightBand{0.0, body.chassis_top_m};
  if (body.top_m > body.chassis_top_m) {
    // Up to the rigid top plus one 2D cell: the rigid spheres never move up or down, so an
    // obstacle whose underside lies higher than that (a table top at 0.50 m over the 0.4915 m
    // shoulder) lets the base pass under it, and the moving spheres near it are then the 3D
    // field's (or, near an exact start or goal, the exact scene's) to keep clear. A band
    // reaching the 3D field's margin (0.087 m) above the rigid top left 13 of 50 tight
    // Tables small goals unreachable by the base search instead of 8 (docs/benchmarks.md,
    // "Close quarters").
    // The rigid spheres themselves are checked by this band exactly (offset = radius - their
    // reach, no 3D margin; SpheresToCheckOnArmField).
    const double rigid_top_clearance_m = options.base_resolution_m;
    options.base_upper_band = HeightBand{0.0, body.top_m + rigid_top_clearance_m};
    options.base_upper_band_offset_m =
        std::max(0.0, kinematics.model().base_cylinder.radius_m - body.sphere_reach_m);
  }
  return options;
}

}  // namespace topay
