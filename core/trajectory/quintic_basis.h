#pragma once

#include <Eigen/Core>

namespace topay {

/// Number of coefficients of a quintic piece: gamma(t) = [1, t, t^2, t^3, t^4, t^5]^T
/// (paper Sec. III-B, the natural basis).
inline constexpr int kQuinticCoefficients = 6;

/// beta^(order)(t) = d^order gamma(t) / dt^order: entry i is i! / (i - order)! * t^(i - order)
/// for i >= order, 0 otherwise. A piece's derivative is then p^(order)(t) = c^T beta^(order)(t)
/// with c its 6 x D coefficient block. order in [0, 5]; larger orders give zero.
inline Eigen::Matrix<double, kQuinticCoefficients, 1> QuinticBasis(double t, int order) {
  // kFalling[order][i] = i! / (i - order)!  (0 for i < order).
  static constexpr double kFalling[kQuinticCoefficients][kQuinticCoefficients] = {
      {1, 1, 1, 1, 1, 1},      {0, 1, 2, 3, 4, 5},       {0, 0, 2, 6, 12, 20},
      {0, 0, 0, 6, 24, 60},    {0, 0, 0, 0, 24, 120},    {0, 0, 0, 0, 0, 120}};
  Eigen::Matrix<double, kQuinticCoefficients, 1> beta;
  beta.setZero();
  if (order < 0 || order >= kQuinticCoefficients) return beta;
  double power = 1.0;  // t^(i - order)
  for (int i = order; i < kQuinticCoefficients; ++i) {
    beta(i) = kFalling[order][i] * power;
    power *= t;
  }
  return beta;
}

}  // namespace topay
