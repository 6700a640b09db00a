#include "core/planning/base_band.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/random.h"

namespace topay {

HeightBand FrontEndBaseBand(const Kinematics& kinematics, double arm_margin_m) {
  const RobotModel& model = kinematics.model();
  const int num_spheres = static_cast<int>(model.spheres.size());
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  kinematics.Update(state, &cache);
  std::vector<double> z0(num_spheres), variation(num_spheres, 0.0);
  for (int s = 0; s < num_spheres; ++s) z0[s] = cache.p_WS[s].z();
  Rng rng(1);
  constexpr int kSamples = 64;
  for (int k = 0; k < kSamples; ++k) {
    for (int j = 0; j < model.num_joints(); ++j) {
      state.q_rad(j) = rng.Uniform(model.joint_limits.q_min_rad(j), model.joint_limits.q_max_rad(j));
    }
    kinematics.Update(state, &cache);
    for (int s = 0; s < num_spheres; ++s) {
      variation[s] = std::max(variation[s], std::abs(cache.p_WS[s].z() - z0[s]));
    }
  }
  double top_m = model.base_cylinder.height_m;
  for (int s = 0; s < num_spheres; ++s) {
    if (variation[s] < 1e-6) top_m = std::max(top_m, z0[s] + model.spheres[s].radius_m);
  }
  return HeightBand{0.0, top_m + std::max(arm_margin_m, 0.0)};
}

}  // namespace topay
