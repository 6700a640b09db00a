#pragma once

namespace topay {

/// Value and first derivative of SmoothPenalty.
struct SmoothPenaltyValue {
  double value = 0.0;
  double derivative = 0.0;
};

/// The C2 smoothing L of max{0, x} that turns an inequality constraint C <= 0 into a penalty
/// (TopAY paper eq. (23); the authors' code's piecewise form, reference mu = 1e-3):
///   L(x) = 0                              x <= 0,
///   L(x) = x^3 / mu^2 - x^4 / (2 mu^3)    0 < x < mu,
///   L(x) = x - mu / 2                     x >= mu.
/// L'(x) = 3 x^2 / mu^2 - 2 x^3 / mu^3 on (0, mu): value, slope and curvature match at both
/// joints (L(mu) = mu / 2, L'(mu) = 1, L''(0) = L''(mu) = 0), so L is C2. mu must be > 0.
inline SmoothPenaltyValue SmoothPenalty(double x, double mu) {
  SmoothPenaltyValue out;
  if (x <= 0.0) return out;  // a NaN x falls through to the polynomial and stays NaN
  if (x >= mu) {
    out.value = x - 0.5 * mu;
    out.derivative = 1.0;
    return out;
  }
  const double r = x / mu;
  // x^3/mu^2 - x^4/(2 mu^3) = mu r^3 (1 - r / 2);  derivative 3 r^2 - 2 r^3.
  out.value = mu * r * r * r * (1.0 - 0.5 * r);
  out.derivative = r * r * (3.0 - 2.0 * r);
  return out;
}

}  // namespace topay
