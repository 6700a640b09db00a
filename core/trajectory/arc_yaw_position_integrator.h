#pragma once

#include <Eigen/Core>

namespace topay {

/// The base position p_WB = (x, y) of an arc length-yaw trajectory, TopAY paper eqs. (1)-(2):
///   x(t) = x0 + int_0^t s'(tau) cos(yaw(tau)) dtau,  y(t) = y0 + int_0^t s'(tau) sin(yaw(tau)) dtau,
/// integrated by the composite Simpson rule.
///
/// Discretisation: piece j (duration T_j) is split into K panels of width h_j = T_j / K. The
/// K + 1 panel end points t_jl = l h_j (l = 0..K) are the samples; sample g = jK + l of
/// M K + 1 in all (the last sample of a piece is the first of the next, stored once). Simpson
/// also evaluates each panel's mid-point, so f = s' (cos yaw, sin yaw) is evaluated at
/// 2K + 1 points per piece:
///   p_{g} = p_{g-1} + I_g,  I_g = h_j / 6 (f(t_{j,l-1}) + 4 f(t_{j,l-1} + h_j / 2) + f(t_jl)).
/// Accuracy: |error of sample g| <= t_g / 2880 h^4 max |f''''| (composite Simpson); between
/// samples (Interpolate) one more Simpson panel of width delta <= h from the previous sample
/// adds at most delta^5 / 2880 max |f''''|, so positions off the samples are as accurate as
/// the samples, and Interpolate reproduces the samples exactly at their times.
///
/// Gradients by reverse accumulation: with lambda_g = sum_{g' >= g} dC/dp_{g'} (suffix sums,
/// O(samples)), dC/dI_g = lambda_g, and each panel's I_g depends only on its own piece's
/// coefficients and duration, so the gradient of a cost on all samples costs O(samples).
///
/// Coefficients use MincoS3's layout (6M x D); only columns 0 (s) and 1 (yaw) are read.
/// Construction allocates; Integrate, Interpolate and AddGradient do not.
class ArcYawPositionIntegrator {
 public:
  struct Options {
    /// K, Simpson panels per piece (authors' code: 12).
    int panels_per_piece = 12;
  };

  ArcYawPositionIntegrator(int num_pieces, const Options& options);

  int num_pieces() const { return num_pieces_; }
  int panels_per_piece() const { return panels_; }
  /// M K + 1.
  int num_samples() const { return num_pieces_ * panels_ + 1; }

  /// Integrates from p0_W = (x0, y0). Keeps copies of the s and yaw coefficients and the
  /// durations for Interpolate and AddGradient. Throws std::invalid_argument for wrong sizes,
  /// non-finite values or non-positive durations.
  void Integrate(const Eigen::Vector2d& p0_W, const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                 const Eigen::Ref<const Eigen::VectorXd>& durations_s);

  /// p_W of every sample, 2 x (M K + 1).
  const Eigen::Matrix2Xd& positions() const { return positions_; }
  /// Time of sample g from the start of the trajectory, s.
  double SampleTime(int sample) const;

  /// p_W at local time local_t_s of `piece`: the previous sample plus one Simpson panel.
  Eigen::Vector2d Interpolate(int piece, double local_t_s) const;

  /// Reverse accumulation of a cost C on the samples: given dC_dp (2 x (M K + 1), dC/dx_g and
  /// dC/dy_g), adds dC/dc to dC_dc (6M x D, columns 0 and 1 only) and the partial dC/dT (c
  /// held fixed; the samples move with T) to dC_dT (M); returns dC/dp0.
  Eigen::Vector2d AddGradient(const Eigen::Ref<const Eigen::Matrix2Xd>& dC_dp,
                              Eigen::Ref<Eigen::MatrixXd> dC_dc,
                              Eigen::Ref<Eigen::VectorXd> dC_dT);

 private:
  /// f = s'(tau) (cos yaw(tau), sin yaw(tau)) for piece j.
  Eigen::Vector2d Integrand(int piece, double tau) const;
  void AddPieceGradient(int piece, Eigen::Ref<Eigen::MatrixXd> dC_dc, double* dC_dT) const;

  int num_pieces_;
  int panels_;
  Eigen::Matrix<double, Eigen::Dynamic, 2> s_yaw_coefficients_;  // 6M x 2
  Eigen::VectorXd durations_s_;
  Eigen::VectorXd piece_start_s_;  // start time of every piece
  Eigen::Matrix2Xd positions_;     // samples
  Eigen::Matrix2Xd increments_;    // I_g, g = 1..MK stored at g - 1
  Eigen::Matrix2Xd suffix_;        // lambda_g
  Eigen::Matrix3Xd point_cache_;   // s', cos yaw, sin yaw at the 2K + 1 points of each piece
};

}  // namespace topay
