#include "core/planning/base_band.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/random.h"

namespace topay {

RigidLowerBody RigidLowerBodyOf(const Kinematics& kinematics) {
  const RobotModel& model = kinematics.model();
  const int num_spheres = static_cast<int>(model.spheres.size());
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  kinematics.Update(state, &cache);
  std::vector<Eigen::Vector3d> p0(num_spheres);
  std::vector<double> variation(num_spheres, 0.0);
  for (int s = 0; s < num_spheres; ++s) p0[s] = cache.p_WS[s];
  Rng rng(1);
  constexpr int kSamples = 64;
  for (int k = 0; k < kSamples; ++k) {
    for (int j = 0; j < model.num_joints(); ++j) {
      state.q_rad(j) = rng.Uniform(model.joint_limits.q_min_rad(j), model.joint_limits.q_max_rad(j));
    }
    kinematics.Update(state, &cache);
    for (int s = 0; s < num_spheres; ++s) {
      variation[s] = std::max(variation[s], (cache.p_WS[s] - p0[s]).norm());
    }
  }
  RigidLowerBody body;
  body.chassis_top_m = model.base_cylinder.height_m;
  body.top_m = body.chassis_top_m;
  for (int s = 0; s < num_spheres; ++s) {
    if (variation[s] >= 1e-6) continue;
    const double radius = model.spheres[s].radius_m;
    const RigidLowerBody::Sphere sphere{s, p0[s].z() + radius, p0[s].z() - radius,
                                        p0[s].head<2>().norm() + radius};
    body.spheres.push_back(sphere);
    body.top_m = std::max(body.top_m, sphere.top_m);
    body.sphere_reach_m = std::max(body.sphere_reach_m, sphere.reach_m);
  }
  return body;
}

std::vector<int> SpheresToCheckOnArmField(const Kinematics& kinematics,
                                          const SignedDistanceField2& base_field) {
  const int num_spheres = static_cast<int>(kinematics.model().spheres.size());
  std::vector<bool> covered(num_spheres, false);
  if (const auto& band = base_field.offset_band()) {
    const double reach_limit_m = kinematics.model().base_cylinder.radius_m - band->offset_m;
    for (const RigidLowerBody::Sphere& s : RigidLowerBodyOf(kinematics).spheres) {
      covered[s.index] = s.top_m <= band->band.z_max_m && s.bottom_m >= band->band.z_min_m &&
                         s.reach_m <= reach_limit_m;
    }
  }
  std::vector<int> checked;
  for (int s = 0; s < num_spheres; ++s) {
    if (!covered[s]) checked.push_back(s);
  }
  return checked;
}

HeightBand FrontEndBaseBand(const Kinematics& kinematics, double arm_margin_m) {
  return HeightBand{0.0, RigidLowerBodyOf(kinematics).top_m + std::max(arm_margin_m, 0.0)};
}

}  // namespace topay
