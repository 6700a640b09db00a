#pragma once
// What the robot can be expected to reach on a sensed map: base positions joined to the start
// through passages kSensedPassageClearanceM wider than the robot (docs/planner.md, "Goals
// behind tight passages"). Used to draw goals (the graph tests, the pick-and-place scenario)
// and to place scripted boxes that leave the goal reachable (topay-director).

#include <optional>

#include <Eigen/Core>

#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/planning/base_reachability.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// The clearance (m) each passage on the way to a goal keeps beyond the robot's footprint
/// (ProvenBaseRegion's openness). The sensed map's voxels stand out of the surfaces they hold
/// by up to ~0.10 m (voxel centres up to 8 cm off with the LiDAR's 2 cm range noise, plus half
/// a voxel), and the planner's base search keeps the validator's margin and 5 % of the base
/// radius more: a gap narrower than the robot + 2 x ~0.12 m is closed on the map although the
/// exact room has it open.
inline constexpr double kSensedPassageClearanceM = 0.15;

/// The base positions the robot at `from` is proven to reach through passages
/// kSensedPassageClearanceM wider than it (2 cm grid: the proof stays conservative).
/// The scene and the kinematics must outlive the region.
ProvenBaseRegion SensedReachableRegion(const Scene& scene, const Kinematics& kinematics,
                                       const Eigen::Vector2d& from);

/// A goal configuration (the arm at `q_rad`, random yaw) r_min_m-r_max_m from `from`, exactly
/// clear of `scene` by 0.3 m and whose base the base at `from` is proven to reach through
/// passages kSensedPassageClearanceM wider than the robot (nullopt if none in 20 000 draws).
/// Draws per try, in order: the distance, the bearing, the yaw.
std::optional<WholeBodyState> ReachableGoal(const Scene& scene, const Kinematics& kinematics,
                                            const Eigen::Vector2d& from, double r_min_m, double r_max_m,
                                            const Eigen::VectorXd& q_rad, Rng* rng);

}  // namespace topay
