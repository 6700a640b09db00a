#pragma once

#include <vector>

#include <Eigen/Core>

namespace topay {

/// Row-major dense matrix: the right-hand sides of BandedLu, one row per unknown, so each
/// elimination step updates a contiguous row of independent values.
using RowMajorMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// A square band matrix A (n x n; entries A(i, j) with -lower <= j - i <= upper may be
/// non-zero) and its LU factorisation in place, without pivoting.
///
/// Without row exchanges Gaussian elimination creates no fill-in outside the band (Golub & Van
/// Loan, Matrix Computations, 4th ed., Thm. 4.3.1 and Alg. 4.3.1 "band Gaussian elimination"),
/// so factorising costs O(n lower upper) and each solve O(n (lower + upper)) per right-hand
/// side. The caller is responsible for a matrix whose leading principal minors are non-zero
/// (MINCO orders its rows so; Wang et al. 2022, T-RO).
///
/// Storage is row-wise, (lower + upper + 1) doubles per row. Resize allocates; everything else
/// is allocation-free.
class BandedLu {
 public:
  BandedLu() = default;
  BandedLu(int n, int lower, int upper) { Resize(n, lower, upper); }

  /// Sizes the storage and zeroes every entry.
  void Resize(int n, int lower, int upper);
  /// Zeroes every entry (keeps the size).
  void SetZero();

  int size() const { return n_; }
  int lower() const { return lower_; }
  int upper() const { return upper_; }

  /// Entry A(row, col); (row, col) must lie in the band (checked in debug builds).
  double& operator()(int row, int col);
  double operator()(int row, int col) const;

  /// Replaces A by its factors L (unit lower, below the diagonal) and U (on and above).
  /// Throws std::runtime_error naming the row if a pivot is zero or not finite.
  void Factorize();

  /// Solves A X = B in place for every column of `rhs` (n rows). Requires Factorize().
  void Solve(Eigen::Ref<RowMajorMatrixXd> rhs) const;
  /// Solves A^T X = B in place (the adjoint solve). Requires Factorize().
  void SolveTransposed(Eigen::Ref<RowMajorMatrixXd> rhs) const;

 private:
  int Index(int row, int col) const { return row * width_ + (col - row + lower_); }

  int n_ = 0;
  int lower_ = 0;
  int upper_ = 0;
  int width_ = 1;
  bool factorized_ = false;
  std::vector<double> data_;
};

}  // namespace topay
