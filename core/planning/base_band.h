#pragma once

#include <vector>

#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"
#include "core/robot/kinematics.h"

namespace topay {

/// The height band of obstacles that the base's 2D field should hold for the front end
/// (SceneDistanceFieldsOptions::base_band): from the ground to the top of the robot's rigid
/// lower body plus arm_margin_m. The rigid lower body is the chassis and every collision
/// sphere whose height does not depend on the joints (on the TopAY arm: the two link-1
/// spheres and the shoulder sphere, top at 0.4915 m); they lie over the base's footprint, so
/// the base cannot pass under anything lower than their top whatever the arm does. With only
/// the chassis band (0.155 m) the topological base paths run under floating boxes and table
/// tops where no arm configuration is valid (the authors' code's "weak point" of the reference
/// harness), and the arm search on them is bound to fail.
/// arm_margin_m: the margin of the arm spheres on the 3D field (WholeBodyValidity's default is
/// the 3D field's exactness_margin_m()). A sphere is rigid when its position varies by less
/// than 1 um over q = 0 and 64 seeded random joint vectors within the limits.
HeightBand FrontEndBaseBand(const Kinematics& kinematics, double arm_margin_m);

/// The part of the robot that no joint motion moves relative to the base: the base cylinder
/// and the rigid collision spheres (same test as FrontEndBaseBand).
struct RigidLowerBody {
  double chassis_top_m = 0.0;  ///< Top of the base cylinder.
  double top_m = 0.0;          ///< Highest point of the chassis and the rigid spheres.
  /// Largest horizontal distance (m) from the base axis of any rigid sphere's surface (over
  /// every yaw): 0.115 + 0.08 = 0.195 m on the TopAY arm, well inside the 0.40 m cylinder.
  double sphere_reach_m = 0.0;
  /// The rigid spheres (RobotModel::spheres indices), with each one's top (m above the
  /// ground), bottom, and horizontal reach from the base axis (m, its surface, over every yaw).
  struct Sphere {
    int index = -1;
    double top_m = 0.0;
    double bottom_m = 0.0;
    double reach_m = 0.0;
  };
  std::vector<Sphere> spheres;
};
RigidLowerBody RigidLowerBodyOf(const Kinematics& kinematics);

/// The collision spheres to check on the 3D arm field, given the base's 2D field: every
/// sphere except the rigid ones that the base field's offset band (SignedDistanceField2::
/// offset_band) already keeps clear wherever the base cylinder passes its own field check
/// (field >= radius + margin): a rigid sphere lying within the band's heights and within
/// radius - offset of the base axis. Such a sphere is then checked exactly by the 2D field (at
/// its 2D margin) instead of by the 3D field at the larger 3D margin (sqrt(3) / 2 x 0.05 =
/// 0.043 m), which lets the base pass 6 % more of the Tables large tasks (docs/benchmarks.md).
/// All spheres if the field has no offset band. In increasing index order.
std::vector<int> SpheresToCheckOnArmField(const Kinematics& kinematics,
                                          const SignedDistanceField2& base_field);

}  // namespace topay
