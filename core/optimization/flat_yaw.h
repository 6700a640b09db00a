#pragma once

#include <cmath>

#include <Eigen/Core>

namespace topay {

/// The base's heading and rates from the flat outputs' derivatives (REMANI-style flatness
/// baseline; REMANI's flatness, paper Sec. III-B), forward driving only
/// (eta = +1):
///   yaw   = atan2(dy, dx),                           v = |u|,   u = (dx, dy) = p',
///   a     = (u . w) / v,                             w = p'',
///   omega = (u x w) / v^2,                           z = p''',
///   beta  = (u x z) / v^2 - 2 (u x w)(u . w) / v^4,  with u x w = u1 w2 - u2 w1.
/// Undefined at v = 0 (the caller handles rest points; see FlatnessObjective).
struct FlatYaw {
  double yaw_rad = 0.0;
  double v_mps = 0.0;
  double a_mps2 = 0.0;
  double omega_radps = 0.0;
  double beta_radps2 = 0.0;
};

/// The quantities above; u must be non-zero.
inline FlatYaw ComputeFlatYaw(const Eigen::Vector2d& u, const Eigen::Vector2d& w,
                              const Eigen::Vector2d& z) {
  FlatYaw out;
  const double s = u.squaredNorm();
  const double v = std::sqrt(s);
  const double uxw = u.x() * w.y() - u.y() * w.x();
  const double uxz = u.x() * z.y() - u.y() * z.x();
  const double udw = u.dot(w);
  out.yaw_rad = std::atan2(u.y(), u.x());
  out.v_mps = v;
  out.a_mps2 = udw / v;
  out.omega_radps = uxw / s;
  out.beta_radps2 = uxz / s - 2.0 * uxw * udw / (s * s);
  return out;
}

/// Chain rule of ComputeFlatYaw: given g = dC/d(yaw, v, a, omega, beta), adds dC/du, dC/dw
/// and dC/dz to the outputs. u must be non-zero.
inline void AddFlatYawGradient(const Eigen::Vector2d& u, const Eigen::Vector2d& w,
                               const Eigen::Vector2d& z, const FlatYaw& g,
                               Eigen::Vector2d* dC_du, Eigen::Vector2d* dC_dw,
                               Eigen::Vector2d* dC_dz) {
  const double s = u.squaredNorm();
  const double v = std::sqrt(s);
  const double uxw = u.x() * w.y() - u.y() * w.x();
  const double uxz = u.x() * z.y() - u.y() * z.x();
  const double udw = u.dot(w);
  const Eigen::Vector2d perp_u(-u.y(), u.x());  // d(u x w)/dw, d(u x z)/dz
  const Eigen::Vector2d dcross_w_du(w.y(), -w.x());  // d(u x w)/du
  const Eigen::Vector2d dcross_z_du(z.y(), -z.x());
  // yaw: d atan2(u2, u1)/du = (-u2, u1) / s.
  *dC_du += g.yaw_rad * perp_u / s;
  // v = |u|.
  *dC_du += g.v_mps * u / v;
  // a = (u . w) / v.
  *dC_du += g.a_mps2 * (w / v - udw * u / (s * v));
  *dC_dw += g.a_mps2 * u / v;
  // omega = (u x w) / s.
  *dC_du += g.omega_radps * (dcross_w_du / s - 2.0 * uxw * u / (s * s));
  *dC_dw += g.omega_radps * perp_u / s;
  // beta = (u x z) / s - 2 (u x w)(u . w) / s^2.
  const double s2 = s * s;
  *dC_dz += g.beta_radps2 * perp_u / s;
  *dC_dw += g.beta_radps2 * (-2.0 * (perp_u * udw + uxw * u) / s2);
  *dC_du += g.beta_radps2 * (dcross_z_du / s - 2.0 * uxz * u / s2 -
                             2.0 * (dcross_w_du * udw + uxw * w) / s2 +
                             8.0 * uxw * udw * u / (s2 * s));
}

}  // namespace topay
