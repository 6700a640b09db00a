#pragma once

#include "core/map/occupancy_grid2.h"
#include "core/robot/kinematics.h"

namespace topay {

/// The height band of obstacles that the base's 2D field should hold for the front end
/// (SceneDistanceFieldsOptions::base_band): from the ground to the top of the robot's rigid
/// lower body plus arm_margin_m. The rigid lower body is the chassis and every collision
/// sphere whose height does not depend on the joints (on the TopAY arm: the two link-1
/// spheres and the shoulder sphere, top at 0.4915 m); they lie over the base's footprint, so
/// the base cannot pass under anything lower than their top whatever the arm does. With only
/// the chassis band (0.155 m) the topological base paths run under floating boxes and table
/// tops where no arm configuration is valid (the facts sheet's "weak point" of the reference
/// harness), and the arm search on them is bound to fail.
/// arm_margin_m: the margin of the arm spheres on the 3D field (WholeBodyValidity's default is
/// sqrt(3) x the 3D field's resolution). A sphere is rigid when its height varies by less
/// than 1 um over q = 0 and 64 seeded random joint vectors within the limits.
HeightBand FrontEndBaseBand(const Kinematics& kinematics, double arm_margin_m);

}  // namespace topay
