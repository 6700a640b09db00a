#include "sim/scenarios/sensed_reachability.h"

#include <cmath>
#include <numbers>

#include "core/collision/scene_clearance.h"

namespace topay {

ProvenBaseRegion SensedReachableRegion(const Scene& scene, const Kinematics& kinematics,
                                       const Eigen::Vector2d& from) {
  BaseOpennessOptions openness;
  openness.clearance_m = kSensedPassageClearanceM;
  BaseReachabilityOptions grid;
  grid.resolution_m = 0.02;  // a quarter of the 1 cm default's cells (the proof stays conservative)
  return ProvenBaseRegion(scene, kinematics, from, openness, grid);
}

std::optional<WholeBodyState> ReachableGoal(const Scene& scene, const Kinematics& kinematics,
                                            const Eigen::Vector2d& from, double r_min_m, double r_max_m,
                                            const Eigen::VectorXd& q_rad, Rng* rng) {
  constexpr double kPi = std::numbers::pi;
  const ProvenBaseRegion region = SensedReachableRegion(scene, kinematics, from);
  const SceneClearanceChecker checker(kinematics, scene);
  for (int k = 0; k < 20000; ++k) {
    const double r = rng->Uniform(r_min_m, r_max_m), a = rng->Uniform(-kPi, kPi);
    WholeBodyState s;
    s.x_m = from.x() + r * std::cos(a);
    s.y_m = from.y() + r * std::sin(a);
    s.yaw_rad = rng->Uniform(-kPi, kPi);
    s.q_rad = q_rad;
    if (!region.Reaches({s.x_m, s.y_m})) continue;
    if (checker.Compute(s).obstacle_m() > 0.3) return s;
  }
  return std::nullopt;
}

}  // namespace topay
