#include "core/trajectory/arc_yaw_position_integrator.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/trajectory/minco_s3.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

using testing::CentralDifference;
using testing::MincoInputs;
using testing::RandomMincoInputs;
using testing::RelativeError;

ArcYawPositionIntegrator::Options Panels(int k) {
  ArcYawPositionIntegrator::Options options;
  options.panels_per_piece = k;
  return options;
}

// s(t) = v t and yaw(t) = yaw0 + omega t as a MINCO trajectory (a linear function satisfies
// every MINCO condition with zero jerk, so it is the solution).
MincoS3 ConstantCurvature(double v, double yaw0, double omega, const Eigen::VectorXd& T) {
  const int M = static_cast<int>(T.size());
  MincoInputs in;
  in.head.resize(2, 3);
  in.head << 0.0, v, 0.0, yaw0, omega, 0.0;
  const double total = T.sum();
  in.tail.resize(2, 3);
  in.tail << v * total, v, 0.0, yaw0 + omega * total, omega, 0.0;
  in.waypoints.resize(2, M - 1);
  double t = 0.0;
  for (int i = 0; i + 1 < M; ++i) {
    t += T(i);
    in.waypoints.col(i) << v * t, yaw0 + omega * t;
  }
  MincoS3 minco(2, M);
  minco.Solve(in.head, in.tail, in.waypoints, T);
  return minco;
}

TEST(ArcYawPositionIntegratorTest, ConstantCurvatureArcFollowsTheCircle) {
  Rng rng(31);
  const double v = 0.8, yaw0 = 0.7, omega = 0.9;
  const Eigen::Vector2d p0(1.5, -2.0);
  const Eigen::VectorXd T = testing::RandomMatrix(5, 1, 0.5, 2.5, &rng);
  const MincoS3 minco = ConstantCurvature(v, yaw0, omega, T);
  ArcYawPositionIntegrator integrator(5, Panels(12));
  integrator.Integrate(p0, minco.coefficients(), minco.durations());
  const auto circle = [&](double t) {
    // x = x0 + v/omega (sin(yaw0 + omega t) - sin yaw0), y = y0 - v/omega (cos(...) - cos yaw0).
    return Eigen::Vector2d(p0.x() + v / omega * (std::sin(yaw0 + omega * t) - std::sin(yaw0)),
                           p0.y() - v / omega * (std::cos(yaw0 + omega * t) - std::cos(yaw0)));
  };
  // Composite Simpson bound: t / 2880 h^4 max|f''''|, |f''''| <= v omega^4 per component.
  const double h_max = T.maxCoeff() / 12.0;
  const double f4 = v * std::pow(omega, 4);
  for (int g = 0; g < integrator.num_samples(); ++g) {
    const double t = integrator.SampleTime(g);
    const double bound = t / 2880.0 * std::pow(h_max, 4) * f4 + 1e-13;
    const Eigen::Vector2d error = integrator.positions().col(g) - circle(t);
    EXPECT_LE(error.cwiseAbs().maxCoeff(), bound) << "sample " << g;
  }
  // Not a degenerate test: the base goes around the circle (diameter 2 v / omega).
  EXPECT_GT((integrator.positions().colwise() - p0).colwise().norm().maxCoeff(), 1.5);
  // Between samples: one more panel of width delta <= h adds delta^5 / 2880 |f''''|.
  for (int trial = 0; trial < 50; ++trial) {
    const int piece = static_cast<int>(rng.UniformInt(0, 4));
    const double tau = rng.Uniform(0.0, T(piece));
    const double t = T.head(piece).sum() + tau;
    const double bound = (t * std::pow(h_max, 4) + std::pow(h_max, 5)) / 2880.0 * f4 + 1e-13;
    EXPECT_LE((integrator.Interpolate(piece, tau) - circle(t)).cwiseAbs().maxCoeff(), bound)
        << "t = " << t;
  }
}

TEST(ArcYawPositionIntegratorTest, StraightLineAtConstantYaw) {
  Rng rng(32);
  MincoInputs in = RandomMincoInputs(2, 4, &rng);
  const double yaw = -2.3;
  in.head.row(1) << yaw, 0.0, 0.0;
  in.tail.row(1) << yaw, 0.0, 0.0;
  in.waypoints.row(1).setConstant(yaw);
  MincoS3 minco(2, 4);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  const Eigen::Vector2d p0(-1.0, 3.0);
  ArcYawPositionIntegrator integrator(4, Panels(12));
  integrator.Integrate(p0, minco.coefficients(), minco.durations());
  const Eigen::Vector2d direction(std::cos(yaw), std::sin(yaw));
  // f = s' (cos, sin) with |s'''''| = |120 c_5| per piece: the Simpson bound along the line.
  double s5_max = 0.0;
  for (int j = 0; j < 4; ++j) s5_max = std::max(s5_max, 120.0 * std::abs(minco.coefficients()(6 * j + 5, 0)));
  const double h_max = in.durations.maxCoeff() / 12.0;
  Eigen::VectorXd s(1);
  for (int g = 0; g < integrator.num_samples(); ++g) {
    const Eigen::Vector2d d = integrator.positions().col(g) - p0;
    // On the line exactly (every increment is a multiple of the direction).
    EXPECT_LT(std::abs(d.x() * direction.y() - d.y() * direction.x()), 1e-12) << "sample " << g;
    double tau = 0.0;
    const int piece = minco.LocatePiece(integrator.SampleTime(g), &tau);
    Eigen::VectorXd value(2);
    minco.EvaluatePiece(piece, tau, 0, value);
    const double travelled = value(0) - in.head(0, 0);
    const double bound = integrator.SampleTime(g) / 2880.0 * std::pow(h_max, 4) * s5_max + 1e-12;
    EXPECT_LE(std::abs(d.dot(direction) - travelled), bound) << "sample " << g;
  }
}

TEST(ArcYawPositionIntegratorTest, SpinInPlaceKeepsThePosition) {
  Rng rng(33);
  MincoInputs in = RandomMincoInputs(2, 5, &rng);
  in.head.row(0).setZero();
  in.tail.row(0).setZero();
  in.waypoints.row(0).setZero();
  MincoS3 minco(2, 5);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  const Eigen::Vector2d p0(4.0, 0.5);
  ArcYawPositionIntegrator integrator(5, Panels(12));
  integrator.Integrate(p0, minco.coefficients(), minco.durations());
  EXPECT_GT(minco.coefficients().col(1).cwiseAbs().maxCoeff(), 0.1);  // the yaw does move
  for (int g = 0; g < integrator.num_samples(); ++g) {
    EXPECT_LT((integrator.positions().col(g) - p0).norm(), 1e-14) << "sample " << g;
  }
  EXPECT_LT((integrator.Interpolate(2, 0.37 * in.durations(2)) - p0).norm(), 1e-14);
}

TEST(ArcYawPositionIntegratorTest, SimpsonConvergesWithOrderFour) {
  Rng rng(34);
  MincoInputs in = RandomMincoInputs(2, 3, &rng, 1.0, 2.0);
  MincoS3 minco(2, 3);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  const auto end_position = [&](int k) {
    ArcYawPositionIntegrator integrator(3, Panels(k));
    integrator.Integrate(Eigen::Vector2d::Zero(), minco.coefficients(), minco.durations());
    return Eigen::Vector2d(integrator.positions().col(integrator.num_samples() - 1));
  };
  const Eigen::Vector2d reference = end_position(2048);
  double previous_error = (end_position(4) - reference).norm();
  for (int k : {8, 16, 32, 64}) {
    const double error = (end_position(k) - reference).norm();
    const double order = std::log2(previous_error / error);
    EXPECT_GT(order, 3.7) << "K = " << k << " error " << error;
    EXPECT_LT(order, 4.3) << "K = " << k << " error " << error;
    previous_error = error;
  }
}

// C(p) = sum_g a_g . p_g + 1/2 (sum_g b_g . p_g)^2 over the samples.
struct SampleCost {
  Eigen::Matrix2Xd a, b;
  double Value(const Eigen::Matrix2Xd& p) const {
    const double square = (b.array() * p.array()).sum();
    return (a.array() * p.array()).sum() + 0.5 * square * square;
  }
  Eigen::Matrix2Xd Gradient(const Eigen::Matrix2Xd& p) const {
    return a + (b.array() * p.array()).sum() * b;
  }
};

TEST(ArcYawPositionIntegratorTest, GradientsMatchCentralDifferences) {
  Rng rng(35);
  const int M = 3, K = 5, D = 3;
  const MincoInputs in = RandomMincoInputs(D, M, &rng);
  MincoS3 minco(D, M);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  Eigen::MatrixXd c = minco.coefficients();
  Eigen::VectorXd T = in.durations;
  Eigen::Vector2d p0(0.3, -0.4);
  ArcYawPositionIntegrator integrator(M, Panels(K));
  const SampleCost cost{testing::RandomMatrix(2, M * K + 1, -1.0, 1.0, &rng),
                        testing::RandomMatrix(2, M * K + 1, -0.2, 0.2, &rng)};
  integrator.Integrate(p0, c, T);
  Eigen::MatrixXd dC_dc = Eigen::MatrixXd::Zero(6 * M, D);
  Eigen::VectorXd dC_dT = Eigen::VectorXd::Zero(M);
  const Eigen::Vector2d dC_dp0 =
      integrator.AddGradient(cost.Gradient(integrator.positions()), dC_dc, dC_dT);
  ArcYawPositionIntegrator probe(M, Panels(K));
  const auto value = [&] {
    probe.Integrate(p0, c, T);
    return cost.Value(probe.positions());
  };
  constexpr double kStep = 1e-6, kTol = 1e-7;
  for (int r = 0; r < 6 * M; ++r) {
    for (int d = 0; d < D; ++d) {
      EXPECT_LT(RelativeError(dC_dc(r, d), CentralDifference(&c(r, d), kStep, value)), kTol)
          << "dC/dc(" << r << ", " << d << ")";
    }
  }
  for (int j = 0; j < M; ++j) {
    EXPECT_LT(RelativeError(dC_dT(j), CentralDifference(&T(j), kStep, value)), kTol)
        << "dC/dT(" << j << ")";
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(RelativeError(dC_dp0(i), CentralDifference(&p0(i), kStep, value)), kTol)
        << "dC/dp0(" << i << ")";
  }
  EXPECT_EQ(dC_dc.col(2).norm(), 0.0);  // the joints do not move the base
}

TEST(ArcYawPositionIntegratorTest, BadInputThrows) {
  EXPECT_THROW(ArcYawPositionIntegrator(0, Panels(12)), std::invalid_argument);
  EXPECT_THROW(ArcYawPositionIntegrator(3, Panels(0)), std::invalid_argument);
  ArcYawPositionIntegrator integrator(2, Panels(4));
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(12, 2);
  Eigen::VectorXd T = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(integrator.Integrate(Eigen::Vector2d::Zero(), Eigen::MatrixXd::Zero(6, 2), T),
               std::invalid_argument);
  T(1) = -1.0;
  EXPECT_THROW(integrator.Integrate(Eigen::Vector2d::Zero(), c, T), std::invalid_argument);
  T(1) = 1.0;
  c(3, 1) = std::nan("");
  EXPECT_THROW(integrator.Integrate(Eigen::Vector2d::Zero(), c, T), std::invalid_argument);
}

}  // namespace
}  // namespace topay
