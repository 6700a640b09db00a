#include "core/collision/scene_clearance.h"
#include "tests/common/make_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "core/geometry/primitive_box_distance.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Boxes scattered around the origin, grounded and floating.
Scene RandomScene(int count, Rng& rng) {
  Scene scene;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d size(rng.Uniform(0.1, 0.8), rng.Uniform(0.1, 0.8),
                               rng.Uniform(0.1, 1.2));
    const double bottom = rng.Uniform01() < 0.5 ? 0.0 : rng.Uniform(0.2, 1.0);
    scene.boxes.push_back(MakeBox({rng.Uniform(-6, 6), rng.Uniform(-6, 6),
                                   bottom + 0.5 * size.z()},
                                  size, rng.Uniform(-3.2, 3.2)));
  }
  return scene;
}

WholeBodyState ZeroArmState(const RobotModel& model, double x, double y, double yaw) {
  WholeBodyState state;
  state.x_m = x;
  state.y_m = y;
  state.yaw_rad = yaw;
  state.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  return state;
}

// Every primitive against every box, no pruning: the reference for the checker's result.
struct NaiveClearance {
  double base_m = kInf;
  int base_box = -1;
  double spheres_m = kInf;
  int sphere = -1;
  int sphere_box = -1;
};

NaiveClearance Naive(const RobotModel& model, const KinematicsCache& cache, const Scene& scene) {
  NaiveClearance out;
  const VerticalCylinder base{cache.X_WB.translation().head<2>(), model.base_cylinder.radius_m,
                              0.0, model.base_cylinder.height_m};
  for (int b = 0; b < static_cast<int>(scene.boxes.size()); ++b) {
    const double d = SignedDistanceCylinderToBox(scene.boxes[b], base);
    if (d < out.base_m) out = {d, b, out.spheres_m, out.sphere, out.sphere_box};
    for (int s = 0; s < static_cast<int>(model.spheres.size()); ++s) {
      const double ds =
          SignedDistanceSphereToBox(scene.boxes[b], cache.p_WS[s], model.spheres[s].radius_m);
      if (ds < out.spheres_m) {
        out.spheres_m = ds;
        out.sphere = s;
        out.sphere_box = b;
      }
    }
  }
  return out;
}

class SceneClearanceTest : public ::testing::Test {
 protected:
  SceneClearanceTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(SceneClearanceTest, MatchesNaiveMinimumOverAllBoxes) {
  Rng rng(21);
  const Scene scene = RandomScene(150, rng);
  const SceneClearanceChecker checker(kinematics_, scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  int colliding = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    const SceneClearance clearance = checker.Compute(state, &workspace);
    const NaiveClearance naive = Naive(model_, workspace.cache, scene);
    EXPECT_EQ(clearance.base_m, naive.base_m);
    EXPECT_EQ(clearance.base_box, naive.base_box);
    EXPECT_EQ(clearance.spheres_m, naive.spheres_m);
    EXPECT_EQ(clearance.sphere, naive.sphere);
    EXPECT_EQ(clearance.sphere_box, naive.sphere_box);
    EXPECT_EQ(clearance.min_m, std::min({clearance.base_m, clearance.spheres_m,
                                         clearance.self_m, clearance.chassis_m}));
    colliding += clearance.obstacle_m() < 0.0;
  }
  EXPECT_GT(colliding, 10);  // the scene is dense enough to exercise penetration
}

// The broad phase (bucket grid) keeps the exact answer on a dense scene of many small boxes,
// and with a cutoff; the point query too.
TEST_F(SceneClearanceTest, MatchesNaiveMinimumOnADenseSceneOfSmallBoxes) {
  Rng rng(23);
  Scene scene;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d size(rng.Uniform(0.02, 0.1), rng.Uniform(0.02, 0.1),
                               rng.Uniform(0.02, 1.5));
    scene.boxes.push_back(MakeBox({rng.Uniform(-6, 6), rng.Uniform(-6, 6),
                                   rng.Uniform(0.0, 1.0) + 0.5 * size.z()},
                                  size, rng.Uniform(-3.2, 3.2)));
  }
  const SceneClearanceChecker checker(kinematics_, scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  for (int trial = 0; trial < 40; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    const SceneClearance clearance = checker.Compute(state, &workspace);
    const NaiveClearance naive = Naive(model_, workspace.cache, scene);
    EXPECT_EQ(clearance.base_m, naive.base_m);
    EXPECT_EQ(clearance.base_box, naive.base_box);
    EXPECT_EQ(clearance.spheres_m, naive.spheres_m);
    EXPECT_EQ(clearance.sphere_box, naive.sphere_box);
    // With a cutoff: the same where the true value is below it, else nothing.
    SceneClearance cut;
    checker.ComputeObstacleParts(workspace.cache, 0.05, &cut);
    EXPECT_EQ(cut.base_m, naive.base_m < 0.05 ? naive.base_m : kInf);
    EXPECT_EQ(cut.spheres_m, naive.spheres_m < 0.05 ? naive.spheres_m : kInf);

    const Eigen::Vector3d p(rng.Uniform(-7, 7), rng.Uniform(-7, 7), rng.Uniform(0, 2));
    double best = kInf;
    int best_box = -1;
    for (int b = 0; b < static_cast<int>(scene.boxes.size()); ++b) {
      const double d = SignedDistanceToBox(scene.boxes[b], p);
      if (d < best) {
        best = d;
        best_box = b;
      }
    }
    int box = -2;
    EXPECT_EQ(checker.PointClearance(p, kInf, &box), best);
    EXPECT_EQ(box, best_box);
  }
}

TEST_F(SceneClearanceTest, SelfPartsMatchSelfCollision) {
  Rng rng(22);
  const Scene scene;
  const SceneClearanceChecker checker(kinematics_, scene);
  const SelfCollision self(kinematics_);
  KinematicsCache cache = kinematics_.MakeCache();
  Eigen::VectorXd margins(self.num_spheres());
  for (int trial = 0; trial < 100; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    const SceneClearance clearance = checker.Compute(state);
    kinematics_.Update(state, &cache);
    EXPECT_EQ(clearance.self_m, self.MinDistance(cache));
    self.ChassisMargins(cache, margins);
    Eigen::Index argmin;
    EXPECT_EQ(clearance.chassis_m, margins.minCoeff(&argmin));
    EXPECT_EQ(clearance.chassis_sphere, argmin);
    ASSERT_GE(clearance.self_pair, 0);
    const auto [i, j] = model_.self_collision_pairs[clearance.self_pair];
    EXPECT_NEAR(clearance.self_m,
                (cache.p_WS[i] - cache.p_WS[j]).norm() - model_.spheres[i].radius_m -
                    model_.spheres[j].radius_m,
                1e-12);
    // An empty scene: no obstacle part.
    EXPECT_EQ(clearance.base_m, kInf);
    EXPECT_EQ(clearance.spheres_m, kInf);
    EXPECT_EQ(clearance.base_box, -1);
    EXPECT_EQ(clearance.sphere_box, -1);
  }
}

TEST_F(SceneClearanceTest, SphereTouchingABoxFace) {
  const WholeBodyState state = ZeroArmState(model_, 1.0, 2.0, 0.4);
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(state, &cache);
  const int tool = static_cast<int>(model_.spheres.size()) - 1;  // the top sphere
  const Eigen::Vector3d p = cache.p_WS[tool];
  const double r = model_.spheres[tool].radius_m;
  // A thin box above the tool sphere, its lower face `gap` above the sphere's top.
  for (const double gap : {0.01, 0.0, -0.01}) {
    Scene scene;
    scene.boxes.push_back(MakeBox({5.0, 5.0, 0.5}, {0.3, 0.3, 1.0}));  // far away
    scene.boxes.push_back(MakeBox(p + Eigen::Vector3d(0, 0, r + gap + 0.05), {0.2, 0.2, 0.1},
                                  0.3));
    const SceneClearanceChecker checker(kinematics_, scene);
    const SceneClearance clearance = checker.Compute(state);
    EXPECT_NEAR(clearance.spheres_m, gap, 1e-12);
    EXPECT_EQ(clearance.sphere, tool);
    EXPECT_EQ(clearance.sphere_box, 1);
    if (gap == 0.0) continue;  // touching: the sign of the rounding error decides
    EXPECT_EQ(clearance.IsCollisionFree(), gap > 0.0);
    SceneClearanceWorkspace workspace = checker.MakeWorkspace();
    EXPECT_EQ(checker.IsCollisionFree(state, 0.0, 0.0, &workspace), gap > 0.0);
    EXPECT_EQ(checker.IsCollisionFree(state, 0.005, 0.0, &workspace), gap > 0.005);
    EXPECT_FALSE(checker.IsCollisionFree(state, 0.02, 0.0, &workspace));
  }
}

// A large table top over the robot: the chassis passes under it, an arm stretched out
// horizontally stays below it, the raised arm (q = 0) goes through it.
TEST_F(SceneClearanceTest, BaseUnderTableTopClearsButRaisedArmDoesNot) {
  const double top_bottom = 0.70;
  Scene scene;
  scene.boxes.push_back(MakeBox({0.2, -0.1, top_bottom + 0.025}, {4.0, 4.0, 0.05}, 0.2));
  const SceneClearanceChecker checker(kinematics_, scene);

  WholeBodyState stretched = ZeroArmState(model_, 0.0, 0.0, 0.7);
  stretched.q_rad(1) = std::numbers::pi / 2;  // shoulder: arm horizontal
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(stretched, &cache);
  double expected_spheres = kInf;
  for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
    expected_spheres =
        std::min(expected_spheres, top_bottom - cache.p_WS[s].z() - model_.spheres[s].radius_m);
  }
  ASSERT_GT(expected_spheres, 0.0);
  const SceneClearance low = checker.Compute(stretched);
  EXPECT_NEAR(low.base_m, top_bottom - model_.base_cylinder.height_m, 1e-12);
  EXPECT_NEAR(low.spheres_m, expected_spheres, 1e-12);
  EXPECT_TRUE(low.IsCollisionFree());

  const WholeBodyState raised = ZeroArmState(model_, 0.0, 0.0, 0.7);
  const SceneClearance high = checker.Compute(raised);
  EXPECT_NEAR(high.base_m, top_bottom - model_.base_cylinder.height_m, 1e-12);
  EXPECT_LT(high.spheres_m, 0.0);
  EXPECT_FALSE(high.IsCollisionFree());
  EXPECT_EQ(high.sphere_box, 0);
}

TEST_F(SceneClearanceTest, CutoffSkipsOnlyFarBoxes) {
  Rng rng(23);
  const Scene scene = RandomScene(150, rng);
  const SceneClearanceChecker exact(kinematics_, scene);
  SceneClearanceOptions options;
  options.cutoff_m = 0.3;
  const SceneClearanceChecker cut(kinematics_, scene, options);
  int near = 0;
  int far = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    const SceneClearance a = exact.Compute(state);
    const SceneClearance b = cut.Compute(state);
    for (const auto& [exact_m, cut_m] : {std::pair{a.base_m, b.base_m},
                                         std::pair{a.spheres_m, b.spheres_m}}) {
      if (exact_m < options.cutoff_m) {
        EXPECT_EQ(cut_m, exact_m);
        ++near;
      } else {
        EXPECT_EQ(cut_m, kInf);
        ++far;
      }
    }
    EXPECT_EQ(a.self_m, b.self_m);
  }
  EXPECT_GT(near, 20);
  EXPECT_GT(far, 20);
}

TEST_F(SceneClearanceTest, FastFreeTestAgreesWithFullClearance) {
  Rng rng(24);
  const Scene scene = RandomScene(150, rng);
  const SceneClearanceChecker checker(kinematics_, scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  int free = 0;
  const int trials = 400;
  for (int trial = 0; trial < trials; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    const SceneClearance clearance = checker.Compute(state, &workspace);
    for (const double margin : {0.0, 0.05, 0.2}) {
      EXPECT_EQ(checker.IsCollisionFree(state, margin, 0.0, &workspace),
                clearance.IsCollisionFree(margin, 0.0));
    }
    free += clearance.IsCollisionFree();
  }
  EXPECT_GT(free, 10);
  EXPECT_LT(free, trials - 10);
}

TEST_F(SceneClearanceTest, ComputeWithWorkspaceDoesNotAllocate) {
  Rng rng(25);
  const Scene scene = RandomScene(100, rng);
  const SceneClearanceChecker checker(kinematics_, scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  const WholeBodyState state = testing::RandomState(model_, &rng);
  double sum = 0.0;
  {
    const testing::AllocationCounter allocations;
    sum += checker.Compute(state, &workspace).min_m;
    sum += checker.IsCollisionFree(state, 0.0, 0.0, &workspace);
    EXPECT_EQ(allocations.count(), 0);
  }
  EXPECT_TRUE(std::isfinite(sum));
}

TEST_F(SceneClearanceTest, BadStateThrows) {
  const Scene scene;
  const SceneClearanceChecker checker(kinematics_, scene);
  WholeBodyState state = ZeroArmState(model_, 0.0, 0.0, 0.0);
  state.q_rad(2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(checker.Compute(state), std::invalid_argument);
  state.q_rad.resize(3);
  EXPECT_THROW(checker.Compute(state), std::invalid_argument);
}

}  // namespace
}  // namespace topay
