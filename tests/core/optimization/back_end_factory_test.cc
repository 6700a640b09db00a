#include "core/optimization/back_end_factory.h"

#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeWorld;

TEST(BackEndFactoryTest, BuildsTheBackEndTheParameterisationNames) {
  const auto world = MakeWorld({});
  TrajectoryOptimizerOptions options;
  std::unique_ptr<TrajectoryBackEnd> back_end =
      MakeTrajectoryBackEnd(*world->kinematics, world->base_field(), world->arm_field(), options);
  ASSERT_NE(dynamic_cast<const TrajectoryOptimizer*>(back_end.get()), nullptr);
  EXPECT_EQ(back_end->parameterisation(), TrajectoryParameterisation::kArcLengthYaw);
  options.parameterisation = TrajectoryParameterisation::kFlatness;
  back_end =
      MakeTrajectoryBackEnd(*world->kinematics, world->base_field(), world->arm_field(), options);
  const auto* flatness = dynamic_cast<const FlatnessOptimizer*>(back_end.get());
  ASSERT_NE(flatness, nullptr);
  EXPECT_EQ(back_end->parameterisation(), TrajectoryParameterisation::kFlatness);
  EXPECT_EQ(flatness->options().time_limit_s, options.time_limit_s);
}

TEST(BackEndFactoryTest, FlatnessTakesTheSharedOptionsAndKeepsItsOwnSampling) {
  TrajectoryOptimizerOptions o;
  o.time_limit_s = 1.25;
  o.alm.rho_initial = 123.0;
  o.alm.max_outer_iterations = 3;
  o.ee_position_tolerance_m = 0.02;
  o.lbfgs.memory = 17;
  o.warm_start.min_pieces = 4;
  o.objective.time_weight = 7.0;
  o.objective.jerk_weights.joint = 0.5;
  o.objective.penalties.chassis_weight = 42.0;
  o.objective.panels_per_piece = 9;
  o.feasibility.sample_period_s = 0.02;
  const FlatnessOptimizerOptions f = FlatnessOptionsFrom(o);
  EXPECT_EQ(f.time_limit_s, 1.25);
  EXPECT_EQ(f.alm.rho_initial, 123.0);
  EXPECT_EQ(f.alm.max_outer_iterations, 3);
  EXPECT_EQ(f.ee_position_tolerance_m, 0.02);
  EXPECT_EQ(f.lbfgs.memory, 17);
  EXPECT_EQ(f.warm_start.min_pieces, 4);
  EXPECT_EQ(f.objective.time_weight, 7.0);
  EXPECT_EQ(f.objective.jerk_weights.joint, 0.5);
  EXPECT_EQ(f.objective.penalties.chassis_weight, 42.0);
  EXPECT_EQ(f.check_period_s, 0.02);
  EXPECT_EQ(f.objective.panels_per_piece, FlatnessObjectiveOptions().panels_per_piece);
}

TEST(BackEndFactoryTest, BadOptionsThrowForEitherBackEnd) {
  const auto world = MakeWorld({});
  for (const auto p : {TrajectoryParameterisation::kArcLengthYaw,
                       TrajectoryParameterisation::kFlatness}) {
    TrajectoryOptimizerOptions options;
    options.parameterisation = p;
    options.alm.rho_growth = 0.5;
    EXPECT_THROW(MakeTrajectoryBackEnd(*world->kinematics, world->base_field(),
                                       world->arm_field(), options),
                 std::invalid_argument);
  }
  // TrajectoryOptimizer itself is the arc length-yaw back end only.
  TrajectoryOptimizerOptions flat;
  flat.parameterisation = TrajectoryParameterisation::kFlatness;
  EXPECT_THROW(TrajectoryOptimizer(*world->kinematics, world->base_field(), world->arm_field(),
                                   flat),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
