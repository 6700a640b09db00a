#include "core/trajectory/banded_lu.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void BandedLu::Resize(int n, int lower, int upper) {
  if (n < 1 || lower < 0 || upper < 0) {
    throw std::invalid_argument("BandedLu::Resize: need n >= 1 and bandwidths >= 0, got n = " +
                                std::to_string(n) + ", lower = " + std::to_string(lower) +
                                ", upper = " + std::to_string(upper));
  }
  n_ = n;
  lower_ = lower;
  upper_ = upper;
  width_ = lower + upper + 1;
  data_.assign(static_cast<std::size_t>(n) * width_, 0.0);
  factorized_ = false;
}

void BandedLu::SetZero() {
  std::fill(data_.begin(), data_.end(), 0.0);
  factorized_ = false;
}

double& BandedLu::operator()(int row, int col) {
  assert(row >= 0 && row < n_ && col >= 0 && col < n_);
  assert(col - row >= -lower_ && col - row <= upper_);
  return data_[Index(row, col)];
}

double BandedLu::operator()(int row, int col) const {
  assert(row >= 0 && row < n_ && col >= 0 && col < n_);
  assert(col - row >= -lower_ && col - row <= upper_);
  return data_[Index(row, col)];
}

// Golub & Van Loan, Alg. 4.3.1: for each column k, scale the sub-diagonal part of column k by
// the pivot (the multipliers l_ik) and update the trailing band
// A(i, j) -= l_ik * A(k, j), i in (k, k + lower], j in (k, k + upper].
void BandedLu::Factorize() {
  for (int k = 0; k < n_; ++k) {
    const double pivot = data_[Index(k, k)];
    if (!(std::isfinite(pivot) && pivot != 0.0)) {
      throw std::runtime_error("BandedLu::Factorize: pivot of row " + std::to_string(k) +
                               " is " + std::to_string(pivot) +
                               " (singular without pivoting)");
    }
    const int last_row = std::min(k + lower_, n_ - 1);
    const int last_col = std::min(k + upper_, n_ - 1);
    for (int i = k + 1; i <= last_row; ++i) data_[Index(i, k)] /= pivot;
    for (int j = k + 1; j <= last_col; ++j) {
      const double a_kj = data_[Index(k, j)];
      if (a_kj == 0.0) continue;
      for (int i = k + 1; i <= last_row; ++i) data_[Index(i, j)] -= data_[Index(i, k)] * a_kj;
    }
  }
  factorized_ = true;
}

namespace {

// x_i -= a x_k over the `width` values of two rows.
inline void SubtractScaledRow(double a, const double* x_k, double* x_i, Eigen::Index width) {
  for (Eigen::Index d = 0; d < width; ++d) x_i[d] -= a * x_k[d];
}

inline void ScaleRow(double a, double* x_i, Eigen::Index width) {
  for (Eigen::Index d = 0; d < width; ++d) x_i[d] *= a;
}

}  // namespace

// Both solves work on whole rows of the right-hand sides (row-oriented substitution): the
// updates of the D columns are independent, so they pipeline instead of forming one long
// dependency chain per column.
void BandedLu::Solve(Eigen::Ref<RowMajorMatrixXd> rhs) const {
  if (!factorized_ || rhs.rows() != n_) {
    throw std::invalid_argument("BandedLu::Solve: needs Factorize() and " + std::to_string(n_) +
                                " rows, got " + std::to_string(rhs.rows()));
  }
  const Eigen::Index width = rhs.cols();
  const auto row = [&](int i) { return rhs.row(i).data(); };
  // L y = b (unit lower triangular, forward substitution).
  for (int i = 0; i < n_; ++i) {
    for (int k = std::max(0, i - lower_); k < i; ++k) {
      SubtractScaledRow(data_[Index(i, k)], row(k), row(i), width);
    }
  }
  // U x = y (back substitution).
  for (int i = n_ - 1; i >= 0; --i) {
    const int last_col = std::min(i + upper_, n_ - 1);
    for (int j = i + 1; j <= last_col; ++j) {
      SubtractScaledRow(data_[Index(i, j)], row(j), row(i), width);
    }
    ScaleRow(1.0 / data_[Index(i, i)], row(i), width);
  }
}

void BandedLu::SolveTransposed(Eigen::Ref<RowMajorMatrixXd> rhs) const {
  if (!factorized_ || rhs.rows() != n_) {
    throw std::invalid_argument("BandedLu::SolveTransposed: needs Factorize() and " +
                                std::to_string(n_) + " rows, got " +
                                std::to_string(rhs.rows()));
  }
  const Eigen::Index width = rhs.cols();
  const auto row = [&](int i) { return rhs.row(i).data(); };
  // A^T = U^T L^T. U^T z = b: lower triangular, column-oriented forward substitution.
  for (int i = 0; i < n_; ++i) {
    ScaleRow(1.0 / data_[Index(i, i)], row(i), width);
    const int last_col = std::min(i + upper_, n_ - 1);
    for (int j = i + 1; j <= last_col; ++j) {
      SubtractScaledRow(data_[Index(i, j)], row(i), row(j), width);
    }
  }
  // L^T x = z: unit upper triangular, column-oriented back substitution.
  for (int i = n_ - 1; i >= 0; --i) {
    for (int k = std::max(0, i - lower_); k < i; ++k) {
      SubtractScaledRow(data_[Index(i, k)], row(i), row(k), width);
    }
  }
}

}  // namespace topay
