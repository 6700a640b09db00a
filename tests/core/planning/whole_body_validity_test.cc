#include "core/planning/whole_body_validity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/common/random.h"
#include "core/geometry/oriented_box.h"
#include "tests/common/make_box.h"
#include "tests/core/planning/rrt_test_world.h"

namespace topay {
namespace {

using testing::RrtTestWorld;

/// A 6 x 6 m room cluttered with rotated grounded boxes, floating cubes and a table top.
Scene ClutteredScene(std::uint64_t seed) {
  Scene scene;
  scene.bounds_W_m =
      Eigen::AlignedBox3d(Eigen::Vector3d(-3.0, -3.0, 0.0), Eigen::Vector3d(3.0, 3.0, 1.6));
  scene.kind = "validity test clutter";
  Rng rng(seed);
  for (int i = 0; i < 14; ++i) {  // grounded boxes
    const Eigen::Vector3d size(rng.Uniform(0.2, 0.8), rng.Uniform(0.2, 0.8), rng.Uniform(0.4, 1.5));
    scene.boxes.push_back(
        MakeBox(Eigen::Vector3d(rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5), 0.5 * size.z()),
                size, rng.Uniform(-3.14, 3.14)));
  }
  for (int i = 0; i < 14; ++i) {  // floating cubes
    const double side = rng.Uniform(0.3, 0.6);
    const double bottom = rng.Uniform(0.4, 0.8);
    scene.boxes.push_back(MakeBox(
        Eigen::Vector3d(rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5), bottom + 0.5 * side),
        Eigen::Vector3d(side, side, side), rng.Uniform(-3.14, 3.14)));
  }
  scene.boxes.push_back(MakeBox({0.5, -0.5, 0.725}, {1.0, 0.8, 0.05}, 0.3));  // a table top
  return scene;
}

TEST(WholeBodyValidityTest, DefaultMarginsFollowTheFieldResolution) {
  const RrtTestWorld world(ClutteredScene(1));
  const WholeBodyValidity validity(world.kinematics, world.fields.base_field_2d,
                                   world.fields.field_3d);
  EXPECT_DOUBLE_EQ(validity.base_margin_m(),
                   std::sqrt(2.0) * world.fields.base_field_2d.geometry().resolution_m);
  EXPECT_DOUBLE_EQ(validity.arm_margin_m(),
                   std::sqrt(3.0) * world.fields.field_3d.geometry().resolution_m);
  WholeBodyValidityOptions options;
  options.arm_margin_m = 0.05;
  EXPECT_DOUBLE_EQ(WholeBodyValidity(world.kinematics, world.fields.base_field_2d,
                                     world.fields.field_3d, options)
                       .arm_margin_m(),
                   0.05);
}

// The margin's promise on single points: field(p) >= r + margin => exact distance >= r.
// Points are drawn near the boxes' surfaces, where the field's errors matter.
TEST(WholeBodyValidityTest, FieldClearPointsAreExactlyClear) {
  const RrtTestWorld world(ClutteredScene(2));
  const WholeBodyValidity validity(world.kinematics, world.fields.base_field_2d,
                                   world.fields.field_3d);
  Rng rng(7);
  int field_clear = 0, field_blocked = 0;
  double smallest_slack = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 200000; ++i) {
    // Points at least half a cell inside the field's volume (see whole_body_validity.cc).
    const Eigen::Vector3d p(rng.Uniform(-2.9, 2.9), rng.Uniform(-2.9, 2.9),
                            rng.Uniform(0.05, 1.55));
    const double r = rng.Uniform(0.0, 0.1);
    double exact = std::numeric_limits<double>::infinity();
    for (const OrientedBox& box : world.scene.boxes)
      exact = std::min(exact, SignedDistanceToBox(box, p));
    if (world.fields.field_3d.Distance(p) >= r + validity.arm_margin_m()) {
      ++field_clear;
      smallest_slack = std::min(smallest_slack, exact - r);
      ASSERT_GE(exact, r) << "point " << p.transpose();
    } else {
      ++field_blocked;
    }
  }
  EXPECT_GT(field_clear, 10000);
  EXPECT_GT(field_blocked, 10000);
  // The margin is not absurdly loose: some field-clear points come within 15 cm of a surface.
  EXPECT_LT(smallest_slack, 0.15);
}

TEST(WholeBodyValidityTest, FieldValidStatesAreExactlyCollisionFree) {
  const RrtTestWorld world(ClutteredScene(3));
  const WholeBodyValidity validity(world.kinematics, world.fields.base_field_2d,
                                   world.fields.field_3d);
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  SceneClearanceWorkspace exact_workspace = world.exact.MakeWorkspace();
  Rng rng(11);
  int valid = 0, exactly_free_but_rejected = 0;
  for (int i = 0; i < 20000; ++i) {
    WholeBodyState state = testing::RandomState(world.model, &rng);
    state.x_m = rng.Uniform(-2.5, 2.5);
    state.y_m = rng.Uniform(-2.5, 2.5);
    const bool exactly_free = world.exact.IsCollisionFree(state, 0.0, 0.0, &exact_workspace);
    if (validity.IsValid(state, &workspace)) {
      ++valid;
      ASSERT_TRUE(exactly_free) << "state " << state.ToVector().transpose();
    } else if (exactly_free) {
      ++exactly_free_but_rejected;
    }
  }
  EXPECT_GT(valid, 500);
  EXPECT_GT(exactly_free_but_rejected, 0);  // the margin costs something, as it must
}

TEST(WholeBodyValidityTest, ReportsEachKindOfFailure) {
  Scene scene = ClutteredScene(4);
  scene.boxes.clear();
  scene.boxes.push_back(MakeBox({2.0, 0.0, 0.5}, {0.4, 0.4, 1.0}));  // a pillar
  scene.boxes.push_back(MakeBox({0.0, 2.0, 1.0}, {0.6, 0.6, 0.2}));  // a floating slab
  const RrtTestWorld world(scene);
  const WholeBodyValidity validity(world.kinematics, world.fields.base_field_2d,
                                   world.fields.field_3d);
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(world.model.num_joints());
  EXPECT_EQ(validity.Check(state, &workspace), ValidityFailure::kNone);

  WholeBodyState bad = state;
  bad.q_rad(1) = world.model.joint_limits.q_max_rad(1) + 0.01;
  EXPECT_EQ(validity.Check(bad, &workspace), ValidityFailure::kJointLimit);
  bad = state;
  bad.x_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validity.Check(bad, &workspace), ValidityFailure::kMalformed);
  bad = state;
  bad.q_rad.resize(3);
  EXPECT_EQ(validity.Check(bad, &workspace), ValidityFailure::kMalformed);
  bad = state;
  bad.x_m = 1.5;  // the base cylinder overlaps the pillar by 0.1 m
  EXPECT_EQ(validity.Check(bad, &workspace), ValidityFailure::kBaseCollision);
  bad = state;
  bad.y_m = 2.0;  // upright arm through the floating slab; the base passes under it
  EXPECT_TRUE(validity.IsBaseValid(Eigen::Vector2d(0.0, 2.0)));
  EXPECT_EQ(validity.Check(bad, &workspace), ValidityFailure::kArmCollision);

  // A self-collision or chassis failure, found by search and confirmed exactly.
  Rng rng(5);
  SceneClearanceWorkspace exact_workspace = world.exact.MakeWorkspace();
  int self_failures = 0;
  for (int i = 0; i < 2000 && self_failures == 0; ++i) {
    WholeBodyState folded = testing::RandomState(world.model, &rng);
    folded.x_m = folded.y_m = 0.0;
    const SceneClearance exact = world.exact.Compute(folded, &exact_workspace);
    if (exact.obstacle_m() > 0.5 && (exact.self_m <= 0.0 || exact.chassis_m <= 0.0)) {
      const ValidityFailure failure = validity.Check(folded, &workspace);
      EXPECT_TRUE(failure == ValidityFailure::kSelfCollision ||
                  failure == ValidityFailure::kChassis)
          << ToString(failure);
      ++self_failures;
    }
  }
  EXPECT_EQ(self_failures, 1);
}

TEST(WholeBodyValidityTest, EdgeCheckFindsACollisionBetweenFreeEnds) {
  Scene scene = ClutteredScene(5);
  scene.boxes.clear();
  scene.boxes.push_back(MakeBox({0.0, 0.0, 1.3}, {0.3, 0.3, 0.3}));  // over the base
  const RrtTestWorld world(scene);
  const WholeBodyValidity validity(world.kinematics, world.fields.base_field_2d,
                                   world.fields.field_3d);
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  // The arm swings from leaning one way to leaning the other way (joint 2), passing upright
  // through the box above the base.
  WholeBodyState a;
  a.q_rad = Eigen::VectorXd::Zero(world.model.num_joints());
  a.q_rad(1) = 1.4;
  WholeBodyState b = a;
  b.q_rad(1) = -1.4;
  WholeBodyState upright = a;
  upright.q_rad(1) = 0.0;
  ASSERT_TRUE(validity.IsValid(a, &workspace));
  ASSERT_TRUE(validity.IsValid(b, &workspace));
  ASSERT_FALSE(validity.IsValid(upright, &workspace));
  EXPECT_EQ(validity.CheckEdge(a, b, &workspace), ValidityFailure::kArmCollision);
  EXPECT_EQ(validity.CheckEdge(a, a, &workspace), ValidityFailure::kNone);
}

TEST(WholeBodyValidityTest, EdgeInterpolationRespectsTheSteps) {
  WholeBodyState a;
  a.q_rad = Eigen::VectorXd::Zero(7);
  WholeBodyState b = a;
  b.x_m = 0.095;  // 9.5 steps of 1 cm
  EXPECT_EQ(WholeBodyValidity::EdgeInterpolationSteps(a, b, 0.01, 0.01), 10);
  b.q_rad(3) = -0.2;  // 20 steps of 0.01 rad
  EXPECT_EQ(WholeBodyValidity::EdgeInterpolationSteps(a, b, 0.01, 0.01), 20);
  b.yaw_rad = 0.3;
  EXPECT_EQ(WholeBodyValidity::EdgeInterpolationSteps(a, b, 0.01, 0.01), 30);
  EXPECT_EQ(WholeBodyValidity::EdgeInterpolationSteps(a, a, 0.01, 0.01), 1);
  WholeBodyState mid;
  mid.q_rad.resize(7);
  WholeBodyValidity::Interpolate(a, b, 0.25, &mid);
  EXPECT_DOUBLE_EQ(mid.x_m, 0.25 * 0.095);
  EXPECT_DOUBLE_EQ(mid.yaw_rad, 0.075);
  EXPECT_DOUBLE_EQ(mid.q_rad(3), -0.05);
}

TEST(WholeBodyValidityTest, BadOptionsThrow) {
  const RrtTestWorld world(ClutteredScene(6));
  WholeBodyValidityOptions options;
  options.arm_margin_m = -0.1;
  EXPECT_THROW(WholeBodyValidity(world.kinematics, world.fields.base_field_2d,
                                 world.fields.field_3d, options),
               std::invalid_argument);
  options = {};
  options.max_edge_step_rad = 0.0;
  EXPECT_THROW(WholeBodyValidity(world.kinematics, world.fields.base_field_2d,
                                 world.fields.field_3d, options),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
