#pragma once

#include "core/map/scene_distance_fields.h"
#include "core/robot/kinematics.h"

namespace topay {

/// The distance-field settings the planner is tuned for (front end and back end), in one place
/// so that the benchmark, the CLI and the tests map scenes alike:
///  - 3D arm field at 0.05 m of exact box distances at the cell centres, capped at 1.0 m
///    (SceneDistanceFieldsOptions::arm_exact_cap_m): the arm's exactness margin
///    (WholeBodyValidityOptions) is sqrt(3) / 2 x 0.05 = 0.043 m (an EDT field's would be
///    sqrt(3) x 0.05 = 0.087 m, which kept the base from under table tops less than 0.087 m
///    above the rigid shoulder; at the benchmark's 0.1 m it would be 0.173 m);
///  - 2D base field at 0.01 m of exact footprint distances at the cell centres, capped at
///    1.0 m (SceneDistanceFieldsOptions::base_exact_cap_m, above every distance the planner
///    compares with): the base's margin is 0.01 / sqrt(2) = 0.007 m (an EDT field's would be
///    sqrt(2) x 0.01 = 0.014 m). The base (radius 0.40 m) must pass gaps barely wider than
///    itself in the Tables rooms: on 100 Tables medium tasks, start and goal were connected
///    for 98 at the exact radius, 92 at +0.028 m and 74 at +0.071 m; at 0.01 m instead of
///    0.02 m cells the planner solved 95 instead of 92 of 100 Tables medium tasks and 79-80
///    instead of 77 large ones, for +5 ms of front end (the map build doubles, outside T.P.;
///    docs/benchmarks.md, "Sixth measurement");
///  - the 2D field in two bands (SceneDistanceFieldsOptions::base_upper_band): obstacles up
///    to the chassis top against the base cylinder, and obstacles up to the top of the rigid
///    lower body (chassis and the arm's rigid spheres, RigidLowerBodyOf) plus the 3D field's
///    margin against the rigid spheres' horizontal reach (0.195 m on the TopAY arm): the base
///    may stand partly under a
///    low table top, as long as its shoulder stays clear, but never under anything lower than
///    its shoulder. The field declares that band (offset_band), so the rigid spheres are
///    checked by it exactly (at the 2D margin) and not again on the 3D field at its larger
///    margin (SpheresToCheckOnArmField).
/// Map build time at these settings: see docs/benchmarks.md ("Large scenes"); it grows
/// linearly with the boxes (BuildSceneDistanceFields). It is not part of the planning time, as
/// in the paper, except in PlanInScene (core/planner/plan_in_scene.h), whose time limit covers
/// it.
SceneDistanceFieldsOptions PlannerFieldOptions(const Kinematics& kinematics);

}  // namespace topay
