#include "core/trajectory/banded_lu.h"

#include <stdexcept>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/trajectory/random_minco_inputs.h"

namespace topay {
namespace {

// A random band matrix, diagonally dominant so elimination without pivoting is well defined,
// as a BandedLu and as a dense matrix.
void RandomBand(int n, int lower, int upper, Rng* rng, BandedLu* band, Eigen::MatrixXd* dense) {
  band->Resize(n, lower, upper);
  dense->setZero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - lower); j <= std::min(n - 1, i + upper); ++j) {
      const double value = (i == j) ? rng->Uniform(5.0, 10.0) * (rng->Uniform01() < 0.5 ? -1 : 1)
                                    : rng->Uniform(-1.0, 1.0);
      (*band)(i, j) = value;
      (*dense)(i, j) = value;
    }
  }
}

TEST(BandedLuTest, SolveMatchesDenseSolveForSeveralBands) {
  Rng rng(11);
  for (const auto& [n, lower, upper] : {std::tuple{1, 0, 0}, std::tuple{7, 2, 3},
                                        std::tuple{30, 6, 6}, std::tuple{25, 0, 4},
                                        std::tuple{25, 5, 0}, std::tuple{8, 10, 10}}) {
    BandedLu band;
    Eigen::MatrixXd dense;
    RandomBand(n, lower, upper, &rng, &band, &dense);
    const Eigen::MatrixXd rhs = testing::RandomMatrix(n, 3, -1.0, 1.0, &rng);
    band.Factorize();
    RowMajorMatrixXd x = rhs;
    band.Solve(x);
    const Eigen::MatrixXd expected = dense.fullPivLu().solve(rhs);
    EXPECT_LT((x - expected).norm(), 1e-12 * std::max(1.0, expected.norm()))
        << "n " << n << " lower " << lower << " upper " << upper;
    RowMajorMatrixXd y = rhs;
    band.SolveTransposed(y);
    const Eigen::MatrixXd expected_t = dense.transpose().fullPivLu().solve(rhs);
    EXPECT_LT((y - expected_t).norm(), 1e-12 * std::max(1.0, expected_t.norm()))
        << "n " << n << " lower " << lower << " upper " << upper;
  }
}

TEST(BandedLuTest, ZeroPivotIsReportedWithItsRow) {
  BandedLu band(3, 1, 1);
  band(0, 0) = 1.0;
  band(1, 1) = 0.0;
  band(2, 2) = 1.0;
  try {
    band.Factorize();
    FAIL() << "expected a singular-pivot error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("row 1"), std::string::npos) << e.what();
  }
}

TEST(BandedLuTest, BadUseThrows) {
  EXPECT_THROW(BandedLu(0, 1, 1), std::invalid_argument);
  EXPECT_THROW(BandedLu(3, -1, 1), std::invalid_argument);
  BandedLu band(3, 1, 1);
  RowMajorMatrixXd rhs = RowMajorMatrixXd::Ones(3, 1);
  EXPECT_THROW(band.Solve(rhs), std::invalid_argument);  // not factorised
  band(0, 0) = band(1, 1) = band(2, 2) = 1.0;
  band.Factorize();
  RowMajorMatrixXd wrong = RowMajorMatrixXd::Ones(4, 1);
  EXPECT_THROW(band.Solve(wrong), std::invalid_argument);
  EXPECT_THROW(band.SolveTransposed(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace topay
