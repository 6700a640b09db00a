#include "core/trajectory/arc_yaw_trajectory.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/trajectory/jerk_energy.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

using testing::CentralDifference;
using testing::MincoInputs;
using testing::RandomMincoInputs;
using testing::RelativeError;

ArcYawTrajectory::Options Panels(int k) {
  ArcYawTrajectory::Options options;
  options.integrator.panels_per_piece = k;
  return options;
}

class ArcYawTrajectoryTest : public ::testing::Test {
 protected:
  static constexpr int kJoints = 7;
  static constexpr int kPieces = 4;

  ArcYawTrajectoryTest() : rng_(41), trajectory_(kJoints, kPieces, Panels(12)) {
    in_ = RandomMincoInputs(kJoints + 2, kPieces, &rng_);
    in_.head(0, 0) = 0.0;  // s(0) = 0 (paper's convention)
    trajectory_.Update(p0_, in_.head, in_.tail, in_.waypoints, in_.durations);
  }

  Rng rng_;
  Eigen::Vector2d p0_{2.0, -1.0};
  MincoInputs in_;
  ArcYawTrajectory trajectory_;
};

// max over the trajectory of |f''''| per component, f = v (cos yaw, sin yaw), by fourth
// central differences of the exactly evaluated f on a 10 ms grid.
Eigen::Vector2d MaxFourthDerivativeOfIntegrand(const ArcYawTrajectory& trajectory) {
  TrajectorySample point = trajectory.MakePoint();
  const auto f = [&](double t) {
    trajectory.Evaluate(t, &point);
    return Eigen::Vector2d(point.v_mps * std::cos(point.state.yaw_rad),
                           point.v_mps * std::sin(point.state.yaw_rad));
  };
  constexpr double kH = 0.01;
  Eigen::Vector2d max = Eigen::Vector2d::Zero();
  for (double t = 2 * kH; t <= trajectory.duration_s() - 2 * kH; t += kH) {
    const Eigen::Vector2d d4 =
        (f(t + 2 * kH) - 4 * f(t + kH) + 6 * f(t) - 4 * f(t - kH) + f(t - 2 * kH)) /
        std::pow(kH, 4);
    max = max.cwiseMax(d4.cwiseAbs());
  }
  return max;
}

// Every rate equals the time derivative of the quantity below it (central differences in t),
// and x, y follow x' = v cos(yaw), y' = v sin(yaw) up to the Simpson panel's error.
TEST_F(ArcYawTrajectoryTest, RatesAreDerivativesOfTheirQuantities) {
  constexpr double kStep = 1e-5;
  TrajectorySample at = trajectory_.MakePoint(), plus = trajectory_.MakePoint(),
              minus = trajectory_.MakePoint();
  // Between samples x(t) = x_l + delta/6 (f(a) + 4 f(a + delta/2) + f(a + delta)), whose
  // error -(delta/2)^5/90 f''''(xi) has the derivative 5 delta^4 / 2880 f'''': with
  // delta <= h, |x' - v cos yaw| <= h^4 / 576 max|f''''| (doubled for the estimate of f'''').
  const double h_max = in_.durations.maxCoeff() / 12.0;
  const Eigen::Vector2d xy_tolerance =
      2.0 * std::pow(h_max, 4) / 576.0 * MaxFourthDerivativeOfIntegrand(trajectory_) +
      Eigen::Vector2d::Constant(1e-7);
  RecordProperty("xy_rate_tolerance", std::to_string(xy_tolerance.maxCoeff()));
  for (int trial = 0; trial < 40; ++trial) {
    const double t = rng_.Uniform(kStep, trajectory_.duration_s() - kStep);
    trajectory_.Evaluate(t, &at);
    trajectory_.Evaluate(t + kStep, &plus);
    trajectory_.Evaluate(t - kStep, &minus);
    const auto rate = [&](double p, double m) { return (p - m) / (2.0 * kStep); };
    EXPECT_NEAR(at.v_mps, rate(plus.s_m, minus.s_m), 1e-6);
    EXPECT_NEAR(at.omega_radps, rate(plus.state.yaw_rad, minus.state.yaw_rad), 1e-6);
    EXPECT_NEAR(at.a_mps2, rate(plus.v_mps, minus.v_mps), 1e-6);
    EXPECT_NEAR(at.beta_radps2, rate(plus.omega_radps, minus.omega_radps), 1e-6);
    EXPECT_NEAR(at.jerk(0), rate(plus.a_mps2, minus.a_mps2), 1e-5);
    EXPECT_NEAR(at.jerk(1), rate(plus.beta_radps2, minus.beta_radps2), 1e-5);
    for (int k = 0; k < kJoints; ++k) {
      EXPECT_NEAR(at.qd_radps(k), rate(plus.state.q_rad(k), minus.state.q_rad(k)), 1e-6);
      EXPECT_NEAR(at.qdd_radps2(k), rate(plus.qd_radps(k), minus.qd_radps(k)), 1e-6);
      EXPECT_NEAR(at.jerk(2 + k), rate(plus.qdd_radps2(k), minus.qdd_radps2(k)), 1e-5);
    }
    EXPECT_NEAR(at.v_mps * std::cos(at.state.yaw_rad), rate(plus.state.x_m, minus.state.x_m),
                xy_tolerance.x());
    EXPECT_NEAR(at.v_mps * std::sin(at.state.yaw_rad), rate(plus.state.y_m, minus.state.y_m),
                xy_tolerance.y());
  }
}

TEST_F(ArcYawTrajectoryTest, BoundaryStatesSamplesAndContinuity) {
  TrajectorySample point = trajectory_.MakePoint();
  trajectory_.Evaluate(0.0, &point);
  EXPECT_EQ(point.state.x_m, p0_.x());
  EXPECT_EQ(point.state.y_m, p0_.y());
  EXPECT_NEAR(point.state.yaw_rad, in_.head(1, 0), 1e-12);
  EXPECT_NEAR(point.v_mps, in_.head(0, 1), 1e-12);
  EXPECT_NEAR(point.beta_radps2, in_.head(1, 2), 1e-12);
  EXPECT_LT((point.state.q_rad - in_.head.col(0).tail(kJoints)).norm(), 1e-12);
  trajectory_.Evaluate(trajectory_.duration_s(), &point);
  EXPECT_NEAR(point.s_m, in_.tail(0, 0), 1e-9);
  EXPECT_NEAR(point.omega_radps, in_.tail(1, 1), 1e-9);
  EXPECT_LT((point.qdd_radps2 - in_.tail.col(2).tail(kJoints)).norm(), 1e-9);
  // At every sample time the pose is the sample.
  const auto& positions = trajectory_.positions();
  for (int g = 0; g < positions.num_samples(); ++g) {
    trajectory_.Evaluate(positions.SampleTime(g), &point);
    EXPECT_LT((Eigen::Vector2d(point.state.x_m, point.state.y_m) - positions.positions().col(g))
                  .norm(),
              1e-12)
        << "sample " << g;
  }
  // Across the first joint.
  TrajectorySample after = trajectory_.MakePoint();
  trajectory_.Evaluate(in_.durations(0) - 1e-9, &point);
  trajectory_.Evaluate(in_.durations(0) + 1e-9, &after);
  EXPECT_NEAR(point.state.x_m, after.state.x_m, 1e-8);
  EXPECT_NEAR(point.state.y_m, after.state.y_m, 1e-8);
  EXPECT_NEAR(point.jerk(3), after.jerk(3), 1e-6);
}

TEST_F(ArcYawTrajectoryTest, EndEffectorPoseGoesThroughKinematics) {
  const RobotModel model = testing::LoadTopayModel();
  ASSERT_EQ(model.num_joints(), kJoints);
  const Kinematics kinematics(model);
  KinematicsCache cache = kinematics.MakeCache();
  TrajectorySample point = trajectory_.MakePoint();
  for (double fraction : {0.0, 0.3, 0.77, 1.0}) {
    const double t = fraction * trajectory_.duration_s();
    const Eigen::Isometry3d X_WE = trajectory_.EndEffectorPose(t, kinematics, &cache, &point);
    EXPECT_TRUE(X_WE.isApprox(kinematics.EndEffectorPose(point.state), 1e-12));
    EXPECT_NEAR(cache.X_WB.translation().x(), point.state.x_m, 1e-12);
    EXPECT_NEAR(cache.X_WB.translation().y(), point.state.y_m, 1e-12);
  }
}

TEST_F(ArcYawTrajectoryTest, EvaluateAndEndEffectorPoseDoNotAllocate) {
  const RobotModel model = testing::LoadTopayModel();
  const Kinematics kinematics(model);
  KinematicsCache cache = kinematics.MakeCache();
  TrajectorySample point = trajectory_.MakePoint();
  testing::AllocationCounter counter;
  double sum = 0.0;
  for (int i = 0; i <= 20; ++i) {
    sum += trajectory_.EndEffectorPose(i * 0.05 * trajectory_.duration_s(), kinematics, &cache,
                                       &point)
               .translation()
               .z();
  }
  EXPECT_EQ(counter.count(), 0);
  EXPECT_TRUE(std::isfinite(sum));
}

// Gradient of a cost on every x, y sample plus the jerk energy, through the Simpson chain and
// MINCO, with respect to the waypoints P, the durations T, the head and tail states (tail
// column 0: the free end values s_f, yaw_f, q_f) and p0.
TEST_F(ArcYawTrajectoryTest, SampleGradientsThroughMincoMatchCentralDifferences) {
  const int D = kJoints + 2;
  const int S = trajectory_.positions().num_samples();
  const Eigen::Matrix2Xd a = testing::RandomMatrix(2, S, -1.0, 1.0, &rng_);
  const Eigen::Matrix2Xd b = testing::RandomMatrix(2, S, -0.2, 0.2, &rng_);
  const Eigen::VectorXd w = JerkWeightOptions().Weights(kJoints);
  const auto cost = [&](const ArcYawTrajectory& traj) {
    const Eigen::Matrix2Xd& p = traj.positions().positions();
    const double square = (b.array() * p.array()).sum();
    return (a.array() * p.array()).sum() + 0.5 * square * square +
           JerkEnergy(traj.minco().coefficients(), traj.minco().durations(), w);
  };
  const Eigen::Matrix2Xd& p = trajectory_.positions().positions();
  const Eigen::Matrix2Xd dC_dp = a + (b.array() * p.array()).sum() * b;
  Eigen::MatrixXd dC_dc = Eigen::MatrixXd::Zero(6 * kPieces, D);
  Eigen::VectorXd dC_dT = Eigen::VectorXd::Zero(kPieces);
  AddJerkEnergyGradient(trajectory_.minco().coefficients(), trajectory_.minco().durations(), w,
                        dC_dc, dC_dT);
  MincoGradient gradient;
  gradient.Resize(D, kPieces);
  const Eigen::Vector2d dC_dp0 = trajectory_.PropagateGradient(dC_dp, dC_dc, dC_dT, &gradient);

  ArcYawTrajectory probe(kJoints, kPieces, Panels(12));
  const auto value = [&] {
    probe.Update(p0_, in_.head, in_.tail, in_.waypoints, in_.durations);
    return cost(probe);
  };
  constexpr double kStep = 1e-6, kTol = 1e-6;
  ExpectMincoGradientMatchesFiniteDifferences(gradient, &in_, value, kStep, kTol);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(RelativeError(dC_dp0(i), CentralDifference(&p0_(i), kStep, value)), kTol);
  }
}

TEST_F(ArcYawTrajectoryTest, BadUseThrows) {
  TrajectorySample point = trajectory_.MakePoint();
  EXPECT_THROW(trajectory_.Evaluate(std::nan(""), &point), std::invalid_argument);
  TrajectorySample unsized;
  EXPECT_THROW(trajectory_.Evaluate(0.5, &unsized), std::invalid_argument);
  ArcYawTrajectory fresh(kJoints, kPieces, Panels(12));
  EXPECT_THROW(fresh.Evaluate(0.5, &point), std::invalid_argument);
  MincoInputs bad = in_;
  bad.durations(1) = -0.5;
  EXPECT_THROW(fresh.Update(p0_, bad.head, bad.tail, bad.waypoints, bad.durations),
               std::invalid_argument);
  EXPECT_THROW(ArcYawTrajectory(kJoints, 0, Panels(12)), std::invalid_argument);
}

}  // namespace
}  // namespace topay
