#include "sim/lidar/robot_body_rays.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/geometry/vertical_cylinder.h"
#include "sim/lidar/ray_primitives.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::sim {
namespace {

// The body's entry by the one-ray primitives: the reference.
double Reference(const RobotModel& model, const KinematicsCache& cache, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& d) {
  const VerticalCylinder base{cache.X_WB.translation().head<2>(), model.base_cylinder.radius_m,
                              0.0, model.base_cylinder.height_m};
  double best = RayCylinderEntry(base, o, d);
  for (std::size_t s = 0; s < model.spheres.size(); ++s) {
    best = std::min(best, RaySphereEntry(cache.p_WS[s], model.spheres[s].radius_m, o, d));
  }
  return best;
}

TEST(RobotBodyRaysTest, EqualsThePrimitivesOnRandomRaysAndStates) {
  const RobotModel model = testing::LoadTopayModel();
  const Kinematics kinematics(model);
  KinematicsCache cache = kinematics.MakeCache();
  RobotBodyRays body;
  Rng rng(8);
  int hits = 0, inside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const WholeBodyState state = testing::RandomState(model, &rng);
    kinematics.Update(state, &cache);
    // Origins near the robot (some inside its solids), rays towards and away from it.
    const Eigen::Vector3d o(state.x_m + rng.Uniform(-0.8, 0.8), state.y_m + rng.Uniform(-0.8, 0.8),
                            rng.Uniform(0.0, 1.3));
    body.Update(model, cache, o);
    for (int k = 0; k < 200; ++k) {
      const double z = rng.Uniform(-1, 1), a = rng.Uniform(0, 6.283185307179586);
      const Eigen::Vector3d d(std::sqrt(1 - z * z) * std::cos(a), std::sqrt(1 - z * z) * std::sin(a),
                              k % 50 == 0 ? 0.0 : z);
      const Eigen::Vector3d unit = d.normalized();
      const double expected = Reference(model, cache, o, unit);
      const double got = body.Entry(unit);
      if (expected == kNoHit) {
        ASSERT_EQ(got, kNoHit) << trial << " " << k;
      } else {
        ASSERT_NEAR(got, expected, 1e-12) << trial << " " << k;
        ++hits;
        inside += expected == 0.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(hits, 2000);
  EXPECT_GT(inside, 0);
}

}  // namespace
}  // namespace topay::sim
