// The odometry motion model: exact arcs (a full circle returns to the start; splitting an
// increment changes nothing), F and G against central finite differences (on arcs and on the
// straight line, where s1 and c1 are series), and Q growing with the motion.

#include "core/estimation/se2_motion.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/angles.h"

namespace topay {
namespace {

constexpr double kStep = 1e-6;

Eigen::Vector3d Difference(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {a.x() - b.x(), a.y() - b.y(), WrapAngle(a.z() - b.z())};
}

// Central differences of MoveAlongArc w.r.t. the state.
Eigen::Matrix3d NumericF(const Eigen::Vector3d& X, const OdometryIncrement& u) {
  Eigen::Matrix3d F;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d plus = X, minus = X;
    plus[j] += kStep;
    minus[j] -= kStep;
    F.col(j) = Difference(MoveAlongArc(plus, u), MoveAlongArc(minus, u)) / (2 * kStep);
  }
  return F;
}

// Central differences w.r.t. d = v dt and dpsi = omega dt (dt fixed).
Eigen::Matrix<double, 3, 2> NumericG(const Eigen::Vector3d& X, const OdometryIncrement& u) {
  Eigen::Matrix<double, 3, 2> G;
  for (int j = 0; j < 2; ++j) {
    OdometryIncrement plus = u, minus = u;
    double& p = j == 0 ? plus.v_mps : plus.omega_radps;
    double& m = j == 0 ? minus.v_mps : minus.omega_radps;
    p += kStep / u.dt_s;
    m -= kStep / u.dt_s;
    G.col(j) = Difference(MoveAlongArc(X, plus), MoveAlongArc(X, minus)) / (2 * kStep);
  }
  return G;
}

struct Case {
  Eigen::Vector3d X;
  OdometryIncrement u;
};

std::vector<Case> Cases() {
  return {{{1.0, -2.0, 0.3}, {0.8, 0.5, 0.1}},      // an arc
          {{0.0, 0.0, 3.0}, {-0.5, -1.2, 0.5}},     // reverse, turning right, yaw near pi
          {{2.0, 1.0, -1.0}, {0.6, 0.0, 0.2}},      // straight (series branch)
          {{2.0, 1.0, -1.0}, {0.6, 0.04, 0.2}},     // dpsi = 0.008: series branch, curved
          {{2.0, 1.0, 2.0}, {0.0, 0.9, 0.3}},       // turning on the spot
          {{-3.0, 4.0, 1.0}, {1.0, 2.5, 1.0}}};     // a long arc (2.5 rad)
}

TEST(EstimatorMotion, JacobiansMatchFiniteDifferences) {
  for (const Case& c : Cases()) {
    const Eigen::Matrix3d F = MotionJacobianState(c.X, c.u);
    const Eigen::Matrix<double, 3, 2> G = MotionJacobianIncrement(c.X, c.u);
    EXPECT_LT((F - NumericF(c.X, c.u)).cwiseAbs().maxCoeff(), 1e-7) << F << "\n" << NumericF(c.X, c.u);
    EXPECT_LT((G - NumericG(c.X, c.u)).cwiseAbs().maxCoeff(), 1e-7) << G << "\n" << NumericG(c.X, c.u);
  }
}

TEST(EstimatorMotion, ArcsAreExact) {
  // A full circle of radius v / omega in 100 steps returns to the start.
  const double v = 0.5, omega = 0.4, T = 2 * std::numbers::pi / omega;
  Eigen::Vector3d X(1.0, 2.0, 0.7);
  for (int k = 0; k < 100; ++k) X = MoveAlongArc(X, {v, omega, T / 100});
  EXPECT_LT(Difference(X, Eigen::Vector3d(1.0, 2.0, 0.7)).norm(), 1e-12);
  // Quarter circle from the origin heading +x, turning left: ends at (r, r) heading +y.
  const double r = v / omega;
  const Eigen::Vector3d quarter = MoveAlongArc(Eigen::Vector3d::Zero(), {v, omega, T / 4});
  EXPECT_NEAR(quarter.x(), r, 1e-12);
  EXPECT_NEAR(quarter.y(), r, 1e-12);
  EXPECT_NEAR(quarter.z(), std::numbers::pi / 2, 1e-12);
  // One step of 0.3 s equals three of 0.1 s (also on the series branch).
  for (const double w : {0.7, 0.01}) {
    Eigen::Vector3d split(0.2, 0.1, -0.4);
    for (int k = 0; k < 3; ++k) split = MoveAlongArc(split, {0.9, w, 0.1});
    EXPECT_LT(Difference(split, MoveAlongArc(Eigen::Vector3d(0.2, 0.1, -0.4), {0.9, w, 0.3})).norm(), 1e-12);
  }
}

TEST(EstimatorMotion, NoiseGrowsWithTheMotion) {
  EstimatorOptions o;
  o.diffusion_xy_m2_per_s = 0.0;
  o.diffusion_yaw_rad2_per_s = 0.0;
  const Eigen::Vector3d X(0.0, 0.0, 0.0);
  EXPECT_EQ(MotionNoise(X, {0.0, 0.0, 0.1}, o).norm(), 0.0);  // at rest: nothing
  // Straight along x: var(x) = translation_var * d; yaw: rotation_var_per_m * d.
  const Eigen::Matrix3d Q = MotionNoise(X, {1.0, 0.0, 0.5}, o);
  EXPECT_NEAR(Q(0, 0), o.translation_var_m2_per_m * 0.5, 1e-15);
  EXPECT_NEAR(Q(2, 2), o.rotation_var_rad2_per_m * 0.5, 1e-15);
  // Twice the distance, twice the variance (rate-independent).
  EXPECT_NEAR(MotionNoise(X, {1.0, 0.0, 1.0}, o)(0, 0), 2 * Q(0, 0), 1e-15);
  // Turning on the spot: yaw only.
  const Eigen::Matrix3d turn = MotionNoise(X, {0.0, 1.0, 0.5}, o);
  EXPECT_NEAR(turn(2, 2), o.rotation_var_rad2_per_rad * 0.5, 1e-15);
  EXPECT_NEAR(turn(0, 0), 0.0, 1e-15);
  // The diffusion at rest.
  const EstimatorOptions d;
  const Eigen::Matrix3d rest = MotionNoise(X, {0.0, 0.0, 2.0}, d);
  EXPECT_NEAR(rest(0, 0), 2 * d.diffusion_xy_m2_per_s, 1e-15);
  EXPECT_NEAR(rest(2, 2), 2 * d.diffusion_yaw_rad2_per_s, 1e-15);
}

TEST(EstimatorMotion, PredictionPropagatesTheCovariance) {
  const EstimatorOptions o;
  Eigen::Vector3d X(0.0, 0.0, 0.0);
  Eigen::Matrix3d P = Eigen::Vector3d(0.0, 0.0, 0.01).asDiagonal();  // yaw uncertain only
  const OdometryIncrement u{1.0, 0.0, 2.0};
  const Eigen::Matrix3d F = MotionJacobianState(X, u);
  const Eigen::Matrix3d expected = F * P * F.transpose() + MotionNoise(X, u, o);
  PredictPose(u, o, &X, &P);
  EXPECT_NEAR(X.x(), 2.0, 1e-12);
  EXPECT_LT((P - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(P(1, 1), 4.0 * 0.01 + MotionNoise(Eigen::Vector3d::Zero(), u, o)(1, 1), 1e-12);  // lateral from yaw
}

}  // namespace
}  // namespace topay
