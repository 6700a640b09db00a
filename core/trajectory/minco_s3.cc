#include "core/trajectory/minco_s3.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

constexpr int kBlock = kQuinticCoefficients;  // 6 rows (and coefficients) per piece
constexpr int kBandwidth = 6;                  // sub- and super-diagonals of M(T)

// Derivative order evaluated by each of the 6 rows of an interior joint's block, in the row
// order of the class comment: jerk, snap, waypoint, position, velocity, acceleration.
constexpr int kJointRowOrders[kBlock] = {3, 4, 0, 0, 1, 2};
// The tail's 3 rows: position, velocity, acceleration.
constexpr int kTailRowOrders[3] = {0, 1, 2};

void CheckShape(const Eigen::Ref<const Eigen::MatrixXd>& m, int rows, int cols,
                const char* name) {
  if (m.rows() != rows || m.cols() != cols) {
    throw std::invalid_argument(std::string("MincoS3::Solve: ") + name + " must be " +
                                std::to_string(rows) + " x " + std::to_string(cols) + ", got " +
                                std::to_string(m.rows()) + " x " + std::to_string(m.cols()));
  }
  for (int c = 0; c < m.cols(); ++c) {
    for (int r = 0; r < m.rows(); ++r) {
      if (!std::isfinite(m(r, c))) {
        throw std::invalid_argument(std::string("MincoS3::Solve: ") + name + "(" +
                                    std::to_string(r) + ", " + std::to_string(c) +
                                    ") is not finite");
      }
    }
  }
}

}  // namespace

void MincoGradient::Resize(int num_dims, int num_pieces) {
  head.setZero(num_dims, 3);
  tail.setZero(num_dims, 3);
  waypoints.setZero(num_dims, num_pieces - 1);
  durations.setZero(num_pieces);
}

MincoS3::MincoS3(int num_dims, int num_pieces)
    : num_dims_(num_dims), num_pieces_(num_pieces) {
  if (num_dims < 1 || num_pieces < 1) {
    throw std::invalid_argument("MincoS3: need at least 1 dimension and 1 piece, got " +
                                std::to_string(num_dims) + " dimensions, " +
                                std::to_string(num_pieces) + " pieces");
  }
  durations_s_.setZero(num_pieces);
  system_.Resize(kBlock * num_pieces, kBandwidth, kBandwidth);
  coefficients_.setZero(kBlock * num_pieces, num_dims);
  solution_.setZero(kBlock * num_pieces, num_dims);
  adjoint_.setZero(kBlock * num_pieces, num_dims);
  derivative_.setZero(num_dims);
}

void MincoS3::CheckInputs(const Eigen::Ref<const Eigen::MatrixXd>& head,
                          const Eigen::Ref<const Eigen::MatrixXd>& tail,
                          const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
                          const Eigen::Ref<const Eigen::VectorXd>& durations_s) const {
  CheckShape(head, num_dims_, 3, "head");
  CheckShape(tail, num_dims_, 3, "tail");
  CheckShape(waypoints, num_dims_, num_pieces_ - 1, "waypoints");
  if (durations_s.size() != num_pieces_) {
    throw std::invalid_argument("MincoS3::Solve: durations must have " +
                                std::to_string(num_pieces_) + " entries, got " +
                                std::to_string(durations_s.size()));
  }
  for (int j = 0; j < num_pieces_; ++j) {
    if (!(std::isfinite(durations_s(j)) && durations_s(j) > 0.0)) {
      throw std::invalid_argument("MincoS3::Solve: durations(" + std::to_string(j) + ") = " +
                                  std::to_string(durations_s(j)) +
                                  " is not a positive finite number");
    }
  }
}

void MincoS3::Solve(const Eigen::Ref<const Eigen::MatrixXd>& head,
                    const Eigen::Ref<const Eigen::MatrixXd>& tail,
                    const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
                    const Eigen::Ref<const Eigen::VectorXd>& durations_s) {
  solved_ = false;
  CheckInputs(head, tail, waypoints, durations_s);
  durations_s_ = durations_s;
  total_duration_s_ = durations_s_.sum();
  BuildSystem();
  system_.Factorize();
  BuildRightHandSide(head, tail, waypoints);
  system_.Solve(solution_);
  coefficients_ = solution_;
  solved_ = true;
}

// Fills M(T) row by row in the order documented in the header.
void MincoS3::BuildSystem() {
  system_.SetZero();
  // Head: p_0(0) = c_00, p_0'(0) = c_01, p_0''(0) = 2 c_02.
  system_(0, 0) = 1.0;
  system_(1, 1) = 1.0;
  system_(2, 2) = 2.0;
  for (int i = 0; i + 1 < num_pieces_; ++i) {
    const int row0 = kBlock * i + 3;
    const int col_i = kBlock * i;
    const int col_next = kBlock * (i + 1);
    for (int r = 0; r < kBlock; ++r) {
      const int order = kJointRowOrders[r];
      const auto beta = QuinticBasis(durations_s_(i), order);
      for (int k = order; k < kBlock; ++k) system_(row0 + r, col_i + k) = beta(k);
      // -p_{i+1}^(order)(0) = -order! c_{i+1, order}; the waypoint row (r = 2) has none.
      if (r != 2) system_(row0 + r, col_next + order) = -QuinticBasis(0.0, order)(order);
    }
  }
  const int last = num_pieces_ - 1;
  for (int r = 0; r < 3; ++r) {
    const auto beta = QuinticBasis(durations_s_(last), kTailRowOrders[r]);
    for (int k = kTailRowOrders[r]; k < kBlock; ++k) {
      system_(kBlock * num_pieces_ - 3 + r, kBlock * last + k) = beta(k);
    }
  }
}

void MincoS3::BuildRightHandSide(const Eigen::Ref<const Eigen::MatrixXd>& head,
                                 const Eigen::Ref<const Eigen::MatrixXd>& tail,
                                 const Eigen::Ref<const Eigen::MatrixXd>& waypoints) {
  solution_.setZero();
  solution_.topRows<3>() = head.transpose();
  for (int i = 0; i + 1 < num_pieces_; ++i) {
    solution_.row(kBlock * i + 5) = waypoints.col(i).transpose();
  }
  solution_.bottomRows<3>() = tail.transpose();
}

int MincoS3::LocatePiece(double t_s, double* local_t_s) const {
  double t = std::clamp(t_s, 0.0, total_duration_s_);
  int piece = 0;
  while (piece + 1 < num_pieces_ && t > durations_s_(piece)) {
    t -= durations_s_(piece);
    ++piece;
  }
  *local_t_s = std::min(t, durations_s_(piece));
  return piece;
}

void MincoS3::EvaluatePiece(int piece, double local_t_s, int order,
                            Eigen::Ref<Eigen::VectorXd> out) const {
  const auto beta = QuinticBasis(local_t_s, order);
  out.noalias() = coefficients_.middleRows<kBlock>(kBlock * piece).transpose() * beta;
}

void MincoS3::AddDurationAdjoint(int piece, int first_row, const int* orders, int count,
                                 double* dJ_dT_i) const {
  const auto block = coefficients_.middleRows<kBlock>(kBlock * piece);
  for (int r = 0; r < count; ++r) {
    // d/dT_i of row r's entries applied to c: p_i^(k_r + 1)(T_i).
    const auto beta = QuinticBasis(durations_s_(piece), orders[r] + 1);
    double dot = 0.0;
    for (int d = 0; d < num_dims_; ++d) {
      dot += adjoint_(first_row + r, d) * block.col(d).dot(beta);
    }
    *dJ_dT_i -= dot;
  }
}

void MincoS3::PropagateGradient(const Eigen::Ref<const Eigen::MatrixXd>& dJ_dc,
                                const Eigen::Ref<const Eigen::VectorXd>& dJ_dT_partial,
                                MincoGradient* gradient) {
  if (!solved_) throw std::logic_error("MincoS3::PropagateGradient: call Solve() first");
  if (dJ_dc.rows() != coefficients_.rows() || dJ_dc.cols() != num_dims_ ||
      dJ_dT_partial.size() != num_pieces_ || gradient->head.rows() != num_dims_ ||
      gradient->head.cols() != 3 || gradient->tail.rows() != num_dims_ ||
      gradient->tail.cols() != 3 || gradient->waypoints.rows() != num_dims_ ||
      gradient->waypoints.cols() != num_pieces_ - 1 ||
      gradient->durations.size() != num_pieces_) {
    throw std::invalid_argument(
        "MincoS3::PropagateGradient: dJ_dc must be 6M x D, dJ_dT_partial M and the gradient "
        "sized by MincoGradient::Resize(D, M)");
  }
  adjoint_ = dJ_dc;
  system_.SolveTransposed(adjoint_);  // G = M^{-T} dJ/dc = dJ/db
  gradient->head = adjoint_.topRows<3>().transpose();
  gradient->tail = adjoint_.bottomRows<3>().transpose();
  for (int i = 0; i + 1 < num_pieces_; ++i) {
    gradient->waypoints.col(i) = adjoint_.row(kBlock * i + 5).transpose();
  }
  gradient->durations = dJ_dT_partial;
  for (int i = 0; i + 1 < num_pieces_; ++i) {
    AddDurationAdjoint(i, kBlock * i + 3, kJointRowOrders, kBlock, &gradient->durations(i));
  }
  AddDurationAdjoint(num_pieces_ - 1, kBlock * num_pieces_ - 3, kTailRowOrders, 3,
                     &gradient->durations(num_pieces_ - 1));
}

}  // namespace topay
