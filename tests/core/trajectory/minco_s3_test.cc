#include "core/trajectory/minco_s3.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/trajectory/jerk_energy.h"
#include "core/trajectory/quintic_basis.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

using testing::CentralDifference;
using testing::MincoInputs;
using testing::RandomMincoInputs;
using testing::RelativeError;

// The MINCO conditions written out independently of MincoS3's row order: head and tail
// position/velocity/acceleration, waypoints, continuity of derivatives 0..4 at every joint.
// Solved densely (full-pivoting LU).
Eigen::MatrixXd DenseMincoSolve(const MincoInputs& in) {
  const int D = static_cast<int>(in.head.rows());
  const int M = static_cast<int>(in.durations.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6 * M, 6 * M);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6 * M, D);
  int row = 0;
  for (int k = 0; k < 3; ++k, ++row) {
    A.block(row, 0, 1, 6) = QuinticBasis(0.0, k).transpose();
    b.row(row) = in.head.col(k).transpose();
  }
  for (int i = 0; i + 1 < M; ++i) {
    A.block(row, 6 * i, 1, 6) = QuinticBasis(in.durations(i), 0).transpose();
    b.row(row++) = in.waypoints.col(i).transpose();
    for (int k = 0; k <= 4; ++k, ++row) {
      A.block(row, 6 * i, 1, 6) = QuinticBasis(in.durations(i), k).transpose();
      A.block(row, 6 * (i + 1), 1, 6) = -QuinticBasis(0.0, k).transpose();
    }
  }
  for (int k = 0; k < 3; ++k, ++row) {
    A.block(row, 6 * (M - 1), 1, 6) = QuinticBasis(in.durations(M - 1), k).transpose();
    b.row(row) = in.tail.col(k).transpose();
  }
  return A.fullPivLu().solve(b);
}

Eigen::VectorXd Eval(const MincoS3& minco, int piece, double t, int order) {
  Eigen::VectorXd out(minco.num_dims());
  minco.EvaluatePiece(piece, t, order, out);
  return out;
}

TEST(MincoS3Test, CoefficientsMatchDenseSolve) {
  Rng rng(1);
  for (int M : {1, 2, 3, 5, 13, 40}) {
    for (int trial = 0; trial < 5; ++trial) {
      const MincoInputs in = RandomMincoInputs(4, M, &rng, 0.2, 3.0);
      MincoS3 minco(4, M);
      minco.Solve(in.head, in.tail, in.waypoints, in.durations);
      const Eigen::MatrixXd expected = DenseMincoSolve(in);
      EXPECT_LT((minco.coefficients() - expected).norm(), 1e-9 * std::max(1.0, expected.norm()))
          << "M = " << M << " trial " << trial;
    }
  }
}

// Elimination without pivoting stays accurate over the durations an optimizer visits
// (0.05 s .. 8 s pieces mixed in one trajectory): compared by the residual of the dense system.
TEST(MincoS3Test, AccurateForWidelySpreadDurations) {
  Rng rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int M = 8;
    const MincoInputs in = RandomMincoInputs(3, M, &rng, 0.05, 8.0);
    MincoS3 minco(3, M);
    minco.Solve(in.head, in.tail, in.waypoints, in.durations);
    const Eigen::MatrixXd expected = DenseMincoSolve(in);
    EXPECT_LT((minco.coefficients() - expected).norm(), 1e-7 * std::max(1.0, expected.norm()))
        << "trial " << trial << " durations " << in.durations.transpose();
    for (int i = 0; i + 1 < M; ++i) {
      EXPECT_LT((Eval(minco, i, in.durations(i), 0) - in.waypoints.col(i)).norm(), 1e-9);
    }
  }
}

TEST(MincoS3Test, ContinuousUpToSnapThroughWaypointsAndBoundaryStates) {
  Rng rng(2);
  const int D = 9, M = 10;
  const MincoInputs in = RandomMincoInputs(D, M, &rng);
  MincoS3 minco(D, M);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  constexpr double kTol = 1e-9;
  for (int i = 0; i + 1 < M; ++i) {
    for (int k = 0; k <= 4; ++k) {
      const Eigen::VectorXd left = Eval(minco, i, in.durations(i), k);
      const Eigen::VectorXd right = Eval(minco, i + 1, 0.0, k);
      EXPECT_LT((left - right).norm(), kTol * std::max(1.0, left.norm()))
          << "joint " << i << " derivative " << k;
    }
    EXPECT_LT((Eval(minco, i, in.durations(i), 0) - in.waypoints.col(i)).norm(), kTol);
    // Jerk energy optimality makes the 5th derivative jump (it is not a C^5 spline).
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT((Eval(minco, 0, 0.0, k) - in.head.col(k)).norm(), kTol) << "head " << k;
    EXPECT_LT((Eval(minco, M - 1, in.durations(M - 1), k) - in.tail.col(k)).norm(), kTol)
        << "tail " << k;
  }
  EXPECT_NEAR(minco.total_duration(), in.durations.sum(), 1e-12);
}

TEST(MincoS3Test, LocatePieceSplitsGlobalTime) {
  Rng rng(3);
  const MincoInputs in = RandomMincoInputs(2, 4, &rng);
  MincoS3 minco(2, 4);
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  double local = -1.0;
  EXPECT_EQ(minco.LocatePiece(-1.0, &local), 0);
  EXPECT_EQ(local, 0.0);
  const double t = in.durations(0) + in.durations(1) + 0.25 * in.durations(2);
  EXPECT_EQ(minco.LocatePiece(t, &local), 2);
  EXPECT_NEAR(local, 0.25 * in.durations(2), 1e-12);
  EXPECT_EQ(minco.LocatePiece(1e9, &local), 3);
  EXPECT_NEAR(local, in.durations(3), 1e-12);
}

// A smooth random cost of (c, T): weighted positions and velocities at random fractions of
// random pieces (the times move with T), the square of another such sum, and the jerk energy.
struct RandomCost {
  struct Term {
    int piece;
    double fraction;
    int order;
    Eigen::VectorXd linear_weight;
    Eigen::VectorXd square_weight;
  };
  std::vector<Term> terms;
  Eigen::VectorXd energy_weights;

  RandomCost(int D, int M, Rng* rng) {
    for (int i = 0; i < 12; ++i) {
      terms.push_back({static_cast<int>(rng->UniformInt(0, M - 1)), rng->Uniform01(),
                       static_cast<int>(rng->UniformInt(0, 1)),
                       testing::RandomMatrix(D, 1, -1.0, 1.0, rng),
                       testing::RandomMatrix(D, 1, -0.3, 0.3, rng)});
    }
    energy_weights = testing::RandomMatrix(D, 1, 0.2, 1.0, rng);
  }

  double Value(const MincoS3& minco) const {
    double linear = 0.0, square = 0.0;
    for (const Term& term : terms) {
      const Eigen::VectorXd p = Eval(minco, term.piece,
                                     term.fraction * minco.durations()(term.piece), term.order);
      linear += term.linear_weight.dot(p);
      square += term.square_weight.dot(p);
    }
    return linear + 0.5 * square * square +
           JerkEnergy(minco.coefficients(), minco.durations(), energy_weights);
  }

  // Partial derivatives with c and T as independent variables.
  void Partials(const MincoS3& minco, Eigen::MatrixXd* dJ_dc, Eigen::VectorXd* dJ_dT) const {
    dJ_dc->setZero(minco.coefficients().rows(), minco.num_dims());
    dJ_dT->setZero(minco.num_pieces());
    double square = 0.0;
    for (const Term& term : terms) {
      square += term.square_weight.dot(
          Eval(minco, term.piece, term.fraction * minco.durations()(term.piece), term.order));
    }
    for (const Term& term : terms) {
      const double t = term.fraction * minco.durations()(term.piece);
      const Eigen::VectorXd weight = term.linear_weight + square * term.square_weight;
      dJ_dc->middleRows(6 * term.piece, 6) += QuinticBasis(t, term.order) * weight.transpose();
      (*dJ_dT)(term.piece) +=
          term.fraction * weight.dot(Eval(minco, term.piece, t, term.order + 1));
    }
    AddJerkEnergyGradient(minco.coefficients(), minco.durations(), energy_weights, *dJ_dc,
                          *dJ_dT);
  }
};

TEST(MincoS3Test, GradientsMatchCentralDifferences) {
  Rng rng(4);
  constexpr double kStep = 1e-6;
  constexpr double kTol = 1e-6;  // relative to max(1, |finite difference|)
  for (int trial = 0; trial < 3; ++trial) {
    const int D = 3, M = 4 + trial;
    MincoInputs in = RandomMincoInputs(D, M, &rng);
    const RandomCost cost(D, M, &rng);
    MincoS3 minco(D, M);
    minco.Solve(in.head, in.tail, in.waypoints, in.durations);
    Eigen::MatrixXd dJ_dc;
    Eigen::VectorXd dJ_dT;
    cost.Partials(minco, &dJ_dc, &dJ_dT);
    MincoGradient gradient;
    gradient.Resize(D, M);
    minco.PropagateGradient(dJ_dc, dJ_dT, &gradient);

    MincoS3 probe(D, M);
    const auto value = [&] {
      probe.Solve(in.head, in.tail, in.waypoints, in.durations);
      return cost.Value(probe);
    };
    ExpectMincoGradientMatchesFiniteDifferences(gradient, &in, value, kStep, kTol);
  }
}

TEST(MincoS3Test, SolveAndGradientDoNotAllocate) {
  Rng rng(5);
  const int D = 9, M = 10;
  const MincoInputs in = RandomMincoInputs(D, M, &rng);
  MincoS3 minco(D, M);
  Eigen::MatrixXd dJ_dc = testing::RandomMatrix(6 * M, D, -1.0, 1.0, &rng);
  Eigen::VectorXd dJ_dT = testing::RandomMatrix(M, 1, -1.0, 1.0, &rng);
  MincoGradient gradient;
  gradient.Resize(D, M);
  const Eigen::VectorXd weights = JerkWeightOptions().Weights(D - 2);
  testing::AllocationCounter counter;
  minco.Solve(in.head, in.tail, in.waypoints, in.durations);
  AddJerkEnergyGradient(minco.coefficients(), minco.durations(), weights, dJ_dc, dJ_dT);
  minco.PropagateGradient(dJ_dc, dJ_dT, &gradient);
  EXPECT_EQ(counter.count(), 0);
}

void ExpectInvalid(const std::function<void()>& call, const std::string& fragment) {
  try {
    call();
    FAIL() << "expected std::invalid_argument mentioning '" << fragment << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(MincoS3Test, BadInputIsRejectedWithItsName) {
  Rng rng(6);
  const MincoInputs good = RandomMincoInputs(3, 4, &rng);
  MincoS3 minco(3, 4);
  MincoInputs in = good;
  in.durations(2) = 0.0;
  ExpectInvalid([&] { minco.Solve(in.head, in.tail, in.waypoints, in.durations); },
                "durations(2)");
  in = good;
  in.durations(1) = std::nan("");
  ExpectInvalid([&] { minco.Solve(in.head, in.tail, in.waypoints, in.durations); },
                "durations(1)");
  in = good;
  in.waypoints(1, 2) = std::numeric_limits<double>::infinity();
  ExpectInvalid([&] { minco.Solve(in.head, in.tail, in.waypoints, in.durations); },
                "waypoints(1, 2)");
  in = good;
  in.tail.resize(3, 2);
  ExpectInvalid([&] { minco.Solve(in.head, in.tail, in.waypoints, in.durations); }, "tail");
  ExpectInvalid([] { MincoS3(0, 3); }, "dimension");
  MincoS3 fresh(3, 4);
  MincoGradient gradient;
  gradient.Resize(3, 4);
  EXPECT_THROW(fresh.PropagateGradient(Eigen::MatrixXd::Zero(24, 3), Eigen::VectorXd::Zero(4),
                                       &gradient),
               std::logic_error);
  minco.Solve(good.head, good.tail, good.waypoints, good.durations);
  ExpectInvalid([&] {
    minco.PropagateGradient(Eigen::MatrixXd::Zero(24, 2), Eigen::VectorXd::Zero(4), &gradient);
  }, "dJ_dc");
}

}  // namespace
}  // namespace topay
