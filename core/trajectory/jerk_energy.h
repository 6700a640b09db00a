#pragma once

#include <Eigen/Core>

namespace topay {

/// Diagonal jerk weights W of the arc length-yaw trajectory (dimension order s, yaw, q1..qN).
/// Defaults: the reference implementation's (the authors' code).
struct JerkWeightOptions {
  double arc_length = 1.0;  ///< Weight of s''' (m/s^3)^2.
  double yaw = 0.33;        ///< Weight of yaw''' (rad/s^3)^2.
  double joint = 1.0;       ///< Weight of every q_k''' (rad/s^3)^2.

  /// diag(W) for N joints: [arc_length, yaw, joint x N].
  Eigen::VectorXd Weights(int num_joints) const;
};

/// The jerk energy of piecewise quintic coefficients c (6M x D, MincoS3's layout) with
/// durations T (M) and diagonal weights w (D), TopAY paper eq. (6) (first term):
///   E = sum_j int_0^{T_j} j_j(t)^T W j_j(t) dt,  j_j(t) = p_j'''(t).
/// In closed form per dimension with (a, b, e) = (c_3, c_4, c_5), j(t) = 6a + 24bt + 60et^2:
///   int_0^T j^2 dt = 36a^2 T + 144ab T^2 + (192b^2 + 240ae) T^3 + 720be T^4 + 720e^2 T^5.
/// Throws std::invalid_argument on inconsistent sizes.
double JerkEnergy(const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                  const Eigen::Ref<const Eigen::VectorXd>& durations_s,
                  const Eigen::Ref<const Eigen::VectorXd>& weights);

/// Adds dE/dc (6M x D) and the partial dE/dT (M) to the given arrays:
///   dE/da = w (72aT + 144bT^2 + 240eT^3),
///   dE/db = w (144aT^2 + 384bT^3 + 720eT^4),
///   dE/de = w (240aT^3 + 720bT^4 + 1440eT^5),
///   dE/dT = sum_d w_d j_d(T)^2   (the integrand at the end of the piece).
/// Allocation-free. Throws std::invalid_argument on inconsistent sizes.
void AddJerkEnergyGradient(const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                           const Eigen::Ref<const Eigen::VectorXd>& durations_s,
                           const Eigen::Ref<const Eigen::VectorXd>& weights,
                           Eigen::Ref<Eigen::MatrixXd> dE_dc, Eigen::Ref<Eigen::VectorXd> dE_dT);

}  // namespace topay
