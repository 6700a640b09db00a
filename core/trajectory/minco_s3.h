#pragma once

#include <Eigen/Core>

#include "core/trajectory/banded_lu.h"

namespace topay {

/// Gradient of a cost J with respect to MINCO's free parameters (see MincoS3::PropagateGradient).
struct MincoGradient {
  Eigen::MatrixXd head;       ///< dJ/d head state, D x 3 (position, velocity, acceleration).
  Eigen::MatrixXd tail;       ///< dJ/d tail state, D x 3; column 0 is dJ/d of the free end
                              ///< values (s_f, yaw_f, q_f in the arc length-yaw trajectory).
  Eigen::MatrixXd waypoints;  ///< dJ/dP, D x (M - 1).
  Eigen::VectorXd durations;  ///< Total dJ/dT, M (through c(T) and J's own dependence on T).

  /// Sizes every member for D dimensions and M pieces (allocates).
  void Resize(int num_dims, int num_pieces);
};

/// MINCO for s = 3 (minimum jerk; Wang et al. 2022, T-RO, "Geometrically constrained
/// trajectory optimization for multicopters"; TopAY paper Sec. III-B/C, eqs. (3)-(5), (8) and the boundary conditions (15)-(20)):
/// M quintic pieces in D dimensions, piece j being p_j(t) = c_j^T gamma(t), t in [0, T_j],
/// with c_j the 6 x D block of rows 6j..6j+5 of c (6M x D; row 6j + k holds the coefficient
/// of t^k).
///
/// The coefficients are the unique solution of M(T) c = b(P, head, tail) (Wang et al.: the
/// optimality conditions of the minimum-jerk problem with fixed waypoints and durations are
/// quintic pieces, C^4 at the joints), rows in this order:
///   rows 0..2:          p_0(0), p_0'(0), p_0''(0)                 = head (D x 3)
///   rows 6i+3..6i+8, for each joint i = 0..M-2 between pieces i and i+1:
///     p_i'''(T_i) - p_{i+1}'''(0) = 0,  p_i''''(T_i) - p_{i+1}''''(0) = 0,
///     p_i(T_i) = P_i,  p_i(T_i) - p_{i+1}(0) = 0,
///     p_i'(T_i) - p_{i+1}'(0) = 0,      p_i''(T_i) - p_{i+1}''(0) = 0
///   rows 6M-3..6M-1:    p_{M-1}(T), p_{M-1}'(T), p_{M-1}''(T)     = tail (D x 3)
/// i.e. derivatives 0..4 continuous at the joints and the waypoints passed. This ordering (the
/// one of Wang et al.) makes M(T) a band matrix with 6 sub- and 6 super-diagonals
/// factorised by LU without pivoting (BandedLu, as Wang et al. do; the tests compare it with a
/// full-pivoting dense solve for pieces of 0.05 s to 8 s), so solving costs O(M).
///
/// Adjoint (Wang et al., gradient propagation through M(T) c = b): for a cost J(c, T), with
/// G = M(T)^{-T} dJ/dc,
///   dJ/db = G,  so dJ/dP_i = G_{6i+5}, dJ/dhead_k = G_k, dJ/dtail_k = G_{6M-3+k};
///   dJ/dT_i = partial dJ/dT_i - tr(G^T (dM/dT_i) c)
///           = partial dJ/dT_i - sum_r G_r . p_i^(k_r + 1)(T_i),
/// r over the rows that evaluate piece i at T_i, k_r the derivative order of row r.
///
/// Construction sizes every workspace; Solve, the evaluations and PropagateGradient do not
/// allocate.
class MincoS3 {
 public:
  MincoS3(int num_dims, int num_pieces);

  int num_dims() const { return num_dims_; }
  int num_pieces() const { return num_pieces_; }

  /// Builds M(T), factorises it and solves for c. head, tail: D x 3 [position, velocity,
  /// acceleration]; waypoints: D x (M - 1); durations_s: M, every entry finite and > 0.
  /// Throws std::invalid_argument naming the argument and entry for a wrong size, a non-finite
  /// value or a non-positive duration; std::runtime_error if the system is numerically
  /// singular (durations spanning too many orders of magnitude).
  void Solve(const Eigen::Ref<const Eigen::MatrixXd>& head,
             const Eigen::Ref<const Eigen::MatrixXd>& tail,
             const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
             const Eigen::Ref<const Eigen::VectorXd>& durations_s);

  bool solved() const { return solved_; }
  /// c, 6M x D (see the class comment).
  const Eigen::MatrixXd& coefficients() const { return coefficients_; }
  const Eigen::VectorXd& durations() const { return durations_s_; }
  double total_duration() const { return total_duration_s_; }

  /// Index of the piece containing global time t_s (clamped to [0, total]) and the local time
  /// in it (written to *local_t_s).
  int LocatePiece(double t_s, double* local_t_s) const;

  /// p_piece^(order)(local_t_s) (D values) into `out`.
  void EvaluatePiece(int piece, double local_t_s, int order,
                     Eigen::Ref<Eigen::VectorXd> out) const;

  /// The adjoint solve (see the class comment). dJ_dc: 6M x D, the partial derivative of J
  /// with respect to c; dJ_dT_partial: M, J's explicit dependence on T (c held fixed).
  /// Overwrites every member of *gradient (which must be sized: MincoGradient::Resize).
  /// Requires Solve().
  void PropagateGradient(const Eigen::Ref<const Eigen::MatrixXd>& dJ_dc,
                         const Eigen::Ref<const Eigen::VectorXd>& dJ_dT_partial,
                         MincoGradient* gradient);

 private:
  void CheckInputs(const Eigen::Ref<const Eigen::MatrixXd>& head,
                   const Eigen::Ref<const Eigen::MatrixXd>& tail,
                   const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
                   const Eigen::Ref<const Eigen::VectorXd>& durations_s) const;
  void BuildSystem();
  void BuildRightHandSide(const Eigen::Ref<const Eigen::MatrixXd>& head,
                          const Eigen::Ref<const Eigen::MatrixXd>& tail,
                          const Eigen::Ref<const Eigen::MatrixXd>& waypoints);
  /// Adds -G_r . p_i^(k + 1)(T_i) over the rows r = first_row.. with derivative orders
  /// orders[0..count) to *dJ_dT_i.
  void AddDurationAdjoint(int piece, int first_row, const int* orders, int count,
                          double* dJ_dT_i) const;

  int num_dims_;
  int num_pieces_;
  bool solved_ = false;
  double total_duration_s_ = 0.0;
  Eigen::VectorXd durations_s_;
  BandedLu system_;
  RowMajorMatrixXd solution_;     // b, then c after the solve
  Eigen::MatrixXd coefficients_;  // c (copy of solution_ in the public layout)
  RowMajorMatrixXd adjoint_;      // G = M^{-T} dJ/dc
  Eigen::VectorXd derivative_;    // D values, scratch for AddDurationAdjoint
};

}  // namespace topay
