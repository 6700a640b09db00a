#include "core/trajectory/arc_yaw_position_integrator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

constexpr int kBlock = kQuinticCoefficients;

/// Values of s', s'', yaw, yaw' of one piece at tau (Horner).
struct ArcYawRates {
  double s_dot = 0.0;
  double s_ddot = 0.0;
  double yaw = 0.0;
  double yaw_dot = 0.0;
};

ArcYawRates EvaluateRates(const Eigen::Matrix<double, Eigen::Dynamic, 2>& c, int piece,
                          double tau) {
  const int row = kBlock * piece;
  ArcYawRates r;
  for (int k = kBlock - 1; k >= 0; --k) {
    const double s_k = c(row + k, 0);
    const double yaw_k = c(row + k, 1);
    r.yaw = r.yaw * tau + yaw_k;
    if (k >= 1) {
      r.s_dot = r.s_dot * tau + k * s_k;
      r.yaw_dot = r.yaw_dot * tau + k * yaw_k;
    }
    if (k >= 2) r.s_ddot = r.s_ddot * tau + k * (k - 1) * s_k;
  }
  return r;
}

}  // namespace

ArcYawPositionIntegrator::ArcYawPositionIntegrator(int num_pieces, const Options& options)
    : num_pieces_(num_pieces), panels_(options.panels_per_piece) {
  if (num_pieces < 1 || panels_ < 1) {
    throw std::invalid_argument("ArcYawPositionIntegrator: need >= 1 piece and >= 1 panel, got " +
                                std::to_string(num_pieces) + " pieces, " +
                                std::to_string(panels_) + " panels");
  }
  s_yaw_coefficients_.setZero(kBlock * num_pieces, 2);
  durations_s_.setZero(num_pieces);
  piece_start_s_.setZero(num_pieces);
  positions_.setZero(2, num_samples());
  increments_.setZero(2, num_samples() - 1);
  suffix_.setZero(2, num_samples());
  point_cache_.setZero(3, num_pieces * (2 * panels_ + 1));
}

Eigen::Vector2d ArcYawPositionIntegrator::Integrand(int piece, double tau) const {
  const ArcYawRates r = EvaluateRates(s_yaw_coefficients_, piece, tau);
  return r.s_dot * Eigen::Vector2d(std::cos(r.yaw), std::sin(r.yaw));
}

void ArcYawPositionIntegrator::Integrate(const Eigen::Vector2d& p0_W,
                                         const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                                         const Eigen::Ref<const Eigen::VectorXd>& durations_s) {
  if (coefficients.rows() != kBlock * num_pieces_ || coefficients.cols() < 2 ||
      durations_s.size() != num_pieces_) {
    throw std::invalid_argument("ArcYawPositionIntegrator::Integrate: coefficients must be " +
                                std::to_string(kBlock * num_pieces_) +
                                " x D (D >= 2) and durations " + std::to_string(num_pieces_) +
                                " long");
  }
  if (!p0_W.allFinite() || !coefficients.leftCols<2>().allFinite()) {
    throw std::invalid_argument(
        "ArcYawPositionIntegrator::Integrate: p0 or the s/yaw coefficients are not finite");
  }
  for (int j = 0; j < num_pieces_; ++j) {
    if (!(std::isfinite(durations_s(j)) && durations_s(j) > 0.0)) {
      throw std::invalid_argument("ArcYawPositionIntegrator::Integrate: durations(" +
                                  std::to_string(j) + ") = " + std::to_string(durations_s(j)) +
                                  " is not a positive finite number");
    }
  }
  s_yaw_coefficients_ = coefficients.leftCols<2>();
  durations_s_ = durations_s;
  positions_.col(0) = p0_W;
  const int points = 2 * panels_ + 1;
  double start_s = 0.0;
  for (int j = 0; j < num_pieces_; ++j) {
    piece_start_s_(j) = start_s;
    start_s += durations_s_(j);
    const double h = durations_s_(j) / panels_;
    // The integrand at the 2K + 1 panel end and mid points tau_m = m h / 2 (cached for
    // AddGradient: s', cos yaw, sin yaw).
    for (int m = 0; m < points; ++m) {
      const ArcYawRates r = EvaluateRates(s_yaw_coefficients_, j, 0.5 * m * h);
      point_cache_.col(j * points + m) << r.s_dot, std::cos(r.yaw), std::sin(r.yaw);
    }
    const auto f = [&](int m) {
      const auto cached = point_cache_.col(j * points + m);
      return Eigen::Vector2d(cached(0) * cached(1), cached(0) * cached(2));
    };
    for (int l = 1; l <= panels_; ++l) {
      const int g = j * panels_ + l;
      // Simpson's rule on [t_{l-1}, t_l]: h / 6 (f0 + 4 f_1/2 + f1).
      increments_.col(g - 1) = h / 6.0 * (f(2 * l - 2) + 4.0 * f(2 * l - 1) + f(2 * l));
      positions_.col(g) = positions_.col(g - 1) + increments_.col(g - 1);
    }
  }
}

double ArcYawPositionIntegrator::SampleTime(int sample) const {
  const int piece = std::min(sample / panels_, num_pieces_ - 1);
  const int panel = sample - piece * panels_;
  return piece_start_s_(piece) + panel * durations_s_(piece) / panels_;
}

Eigen::Vector2d ArcYawPositionIntegrator::Interpolate(int piece, double local_t_s) const {
  const double h = durations_s_(piece) / panels_;
  const double tau = std::clamp(local_t_s, 0.0, durations_s_(piece));
  const int panel = std::min(static_cast<int>(tau / h), panels_ - 1);
  const double a = panel * h;
  const double delta = tau - a;
  // One Simpson panel of width delta from the sample at a (exact sample for delta = 0).
  return positions_.col(piece * panels_ + panel) +
         delta / 6.0 *
             (Integrand(piece, a) + 4.0 * Integrand(piece, a + 0.5 * delta) +
              Integrand(piece, tau));
}

Eigen::Vector2d ArcYawPositionIntegrator::AddGradient(
    const Eigen::Ref<const Eigen::Matrix2Xd>& dC_dp, Eigen::Ref<Eigen::MatrixXd> dC_dc,
    Eigen::Ref<Eigen::VectorXd> dC_dT) {
  if (dC_dp.cols() != num_samples() || dC_dc.rows() != kBlock * num_pieces_ ||
      dC_dc.cols() < 2 || dC_dT.size() != num_pieces_) {
    throw std::invalid_argument(
        "ArcYawPositionIntegrator::AddGradient: dC_dp must be 2 x (MK + 1), dC_dc 6M x D, "
        "dC_dT M");
  }
  // lambda_g = sum_{g' >= g} dC/dp_g' (reverse accumulation through p_g = p_{g-1} + I_g).
  suffix_.col(num_samples() - 1) = dC_dp.col(num_samples() - 1);
  for (int g = num_samples() - 2; g >= 0; --g) suffix_.col(g) = suffix_.col(g + 1) + dC_dp.col(g);
  for (int j = 0; j < num_pieces_; ++j) AddPieceGradient(j, dC_dc, &dC_dT(j));
  return suffix_.col(0);
}

// Panel l of piece j (sample g = jK + l) has dC/dI_g = lambda_g = mu_l. With
// I_g = h/6 sum_m w_m f(tau_m), tau_m = alpha_m T, h = T / K, Simpson weights w = (1, 4, 1):
//   dC/dc  = sum over points of omega . df/dc,   omega = h/6 w_m mu_l (summed over the panels
//            sharing an end point),
//   dC/dT  = sum_l mu_l . I_g / T + sum over points alpha_m omega . f'(tau_m),
// where, with g_s = omega . (cos, sin) and g_yaw = s' omega . (-sin, cos):
//   d(omega . f)/dc_{s,k} = k tau^(k-1) g_s,  d(omega . f)/dc_{yaw,k} = tau^k g_yaw,
//   omega . f' = s'' g_s + yaw' g_yaw.
void ArcYawPositionIntegrator::AddPieceGradient(int piece, Eigen::Ref<Eigen::MatrixXd> dC_dc,
                                                double* dC_dT) const {
  const double T = durations_s_(piece);
  const double h = T / panels_;
  const int first = piece * panels_;  // sample index of the piece's start
  const int row = kBlock * piece;
  double dT = 0.0;
  for (int l = 1; l <= panels_; ++l) {
    dT += suffix_.col(first + l).dot(increments_.col(first + l - 1)) / T;
  }
  for (int m = 0; m <= 2 * panels_; ++m) {
    Eigen::Vector2d mu = Eigen::Vector2d::Zero();
    if (m % 2 == 1) {
      mu = 4.0 * suffix_.col(first + (m + 1) / 2);
    } else {
      if (m > 0) mu += suffix_.col(first + m / 2);
      if (m < 2 * panels_) mu += suffix_.col(first + m / 2 + 1);
    }
    const Eigen::Vector2d omega = h / 6.0 * mu;
    const double tau = 0.5 * m * h;
    const ArcYawRates r = EvaluateRates(s_yaw_coefficients_, piece, tau);
    const auto cached = point_cache_.col(piece * (2 * panels_ + 1) + m);  // s', cos, sin
    const double cos_yaw = cached(1), sin_yaw = cached(2);
    const double g_s = omega.x() * cos_yaw + omega.y() * sin_yaw;
    const double g_yaw = cached(0) * (-omega.x() * sin_yaw + omega.y() * cos_yaw);
    double tau_power = 1.0;  // tau^k
    for (int k = 0; k < kBlock; ++k) {
      if (k + 1 < kBlock) dC_dc(row + k + 1, 0) += (k + 1) * tau_power * g_s;
      dC_dc(row + k, 1) += tau_power * g_yaw;
      tau_power *= tau;
    }
    const double alpha = 0.5 * m / panels_;
    dT += alpha * (r.s_ddot * g_s + r.yaw_dot * g_yaw);
  }
  *dC_dT += dT;
}

}  // namespace topay
