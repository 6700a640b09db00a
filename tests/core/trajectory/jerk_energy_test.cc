#include "core/trajectory/jerk_energy.h"

#include <stdexcept>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/trajectory/minco_s3.h"
#include "core/trajectory/quintic_basis.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

using testing::CentralDifference;
using testing::RelativeError;

// sum_j int_0^T_j j^T W j dt by composite Gauss-Legendre quadrature (3 nodes on each of
// `panels` sub-intervals per piece), evaluating the jerk through QuinticBasis.
double QuadratureEnergy(const Eigen::MatrixXd& c, const Eigen::VectorXd& T,
                        const Eigen::VectorXd& w, int panels) {
  const double nodes[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double node_weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double energy = 0.0;
  for (int j = 0; j < T.size(); ++j) {
    const double h = T(j) / panels;
    for (int p = 0; p < panels; ++p) {
      for (int n = 0; n < 3; ++n) {
        const double t = (p + 0.5) * h + 0.5 * h * nodes[n];
        const Eigen::VectorXd jerk = c.middleRows(6 * j, 6).transpose() * QuinticBasis(t, 3);
        energy += 0.5 * h * node_weights[n] * jerk.dot(w.asDiagonal() * jerk);
      }
    }
  }
  return energy;
}

TEST(JerkEnergyTest, MatchesQuadrature) {
  Rng rng(21);
  for (int trial = 0; trial < 5; ++trial) {
    const int D = 9, M = 1 + trial * 3;
    const Eigen::MatrixXd c = testing::RandomMatrix(6 * M, D, -1.0, 1.0, &rng);
    const Eigen::VectorXd T = testing::RandomMatrix(M, 1, 0.3, 3.0, &rng);
    const Eigen::VectorXd w = testing::RandomMatrix(D, 1, 0.1, 2.0, &rng);
    const double closed_form = JerkEnergy(c, T, w);
    const double quadrature = QuadratureEnergy(c, T, w, 16);
    EXPECT_GT(closed_form, 0.0);
    EXPECT_LT(std::abs(closed_form - quadrature), 1e-10 * closed_form) << "trial " << trial;
  }
}

TEST(JerkEnergyTest, GradientsMatchCentralDifferences) {
  Rng rng(22);
  const int D = 4, M = 3;
  Eigen::MatrixXd c = testing::RandomMatrix(6 * M, D, -1.0, 1.0, &rng);
  Eigen::VectorXd T = testing::RandomMatrix(M, 1, 0.5, 2.0, &rng);
  const Eigen::VectorXd w = testing::RandomMatrix(D, 1, 0.1, 2.0, &rng);
  Eigen::MatrixXd dE_dc = Eigen::MatrixXd::Zero(6 * M, D);
  Eigen::VectorXd dE_dT = Eigen::VectorXd::Zero(M);
  AddJerkEnergyGradient(c, T, w, dE_dc, dE_dT);
  const auto energy = [&] { return JerkEnergy(c, T, w); };
  // E is quadratic in c, so central differences have no truncation error there: a large step
  // keeps round-off (eps |E| / step) small. In T, E is a quintic: a small step.
  constexpr double kStepC = 1e-3, kStepT = 1e-6, kTol = 1e-7;
  for (int r = 0; r < 6 * M; ++r) {
    for (int d = 0; d < D; ++d) {
      EXPECT_LT(RelativeError(dE_dc(r, d), CentralDifference(&c(r, d), kStepC, energy)), kTol)
          << "dE/dc(" << r << ", " << d << ")";
    }
  }
  for (int j = 0; j < M; ++j) {
    EXPECT_LT(RelativeError(dE_dT(j), CentralDifference(&T(j), kStepT, energy)), kTol)
        << "dE/dT(" << j << ")";
  }
}

// MINCO's coefficients minimise the jerk energy among all piecewise quintics that pass the
// waypoints, meet the boundary states and are C^2 at the joints (the C^3, C^4 rows are the
// optimality conditions; Wang et al. 2022). So the energy gradient vanishes along every
// feasible direction (the null space N of those constraints), and a feasible perturbation
// raises the energy. Checks the energy gradient and MINCO together.
TEST(JerkEnergyTest, MincoIsStationaryOnItsConstraintSet) {
  Rng rng(23);
  const int D = 2, M = 4;
  const testing::MincoInputs in = testing::RandomMincoInputs(D, M, &rng);
  MincoS3 minco(D, M);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  const Eigen::VectorXd w = Eigen::VectorXd::Ones(D);
  // The conditions of MINCO without the C^3 and C^4 continuity rows (those are the optimality
  // conditions): head, tail, waypoints, C^0..C^2 at the joints. Any c' = c + N z with
  // A N = 0 is feasible.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6 + 4 * (M - 1), 6 * M);
  int row = 0;
  for (int k = 0; k < 3; ++k) A.block(row++, 0, 1, 6) = QuinticBasis(0.0, k).transpose();
  for (int i = 0; i + 1 < M; ++i) {
    A.block(row++, 6 * i, 1, 6) = QuinticBasis(in.durations(i), 0).transpose();
    for (int k = 0; k < 3; ++k, ++row) {
      A.block(row, 6 * i, 1, 6) = QuinticBasis(in.durations(i), k).transpose();
      A.block(row, 6 * (i + 1), 1, 6) = -QuinticBasis(0.0, k).transpose();
    }
  }
  for (int k = 0; k < 3; ++k) {
    A.block(row++, 6 * (M - 1), 1, 6) = QuinticBasis(in.durations(M - 1), k).transpose();
  }
  const Eigen::MatrixXd null_space = Eigen::FullPivLU<Eigen::MatrixXd>(A).kernel();
  ASSERT_GT(null_space.cols(), 0);
  Eigen::MatrixXd dE_dc = Eigen::MatrixXd::Zero(6 * M, D);
  Eigen::VectorXd dE_dT = Eigen::VectorXd::Zero(M);
  AddJerkEnergyGradient(minco.coefficients(), minco.durations(), w, dE_dc, dE_dT);
  const Eigen::MatrixXd projected = null_space.transpose() * dE_dc;
  EXPECT_LT(projected.norm(), 1e-8 * std::max(1.0, dE_dc.norm()));
  // And a random feasible perturbation raises the energy.
  const Eigen::MatrixXd perturbed =
      minco.coefficients() + 0.01 * null_space *
          testing::RandomMatrix(static_cast<int>(null_space.cols()), D, -1.0, 1.0, &rng);
  EXPECT_GT(JerkEnergy(perturbed, minco.durations(), w),
            JerkEnergy(minco.coefficients(), minco.durations(), w));
}

TEST(JerkEnergyTest, DefaultWeightsAreTheReferenceOnes) {
  const Eigen::VectorXd w = JerkWeightOptions().Weights(7);
  ASSERT_EQ(w.size(), 9);
  EXPECT_EQ(w(0), 1.0);   // arc length
  EXPECT_EQ(w(1), 0.33);  // yaw
  for (int k = 2; k < 9; ++k) EXPECT_EQ(w(k), 1.0);
}

TEST(JerkEnergyTest, InconsistentSizesThrow) {
  const Eigen::MatrixXd c = Eigen::MatrixXd::Zero(12, 3);
  const Eigen::VectorXd T = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(JerkEnergy(c, T, Eigen::VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(JerkEnergy(c, Eigen::VectorXd::Ones(3), Eigen::VectorXd::Ones(3)),
               std::invalid_argument);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(12, 2);
  Eigen::VectorXd gT = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(AddJerkEnergyGradient(c, T, Eigen::VectorXd::Ones(3), g, gT),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
