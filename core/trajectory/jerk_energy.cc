#include "core/trajectory/jerk_energy.h"

#include <stdexcept>
#include <string>

#include "core/trajectory/quintic_basis.h"

namespace topay {
namespace {

void CheckSizes(const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                const Eigen::Ref<const Eigen::VectorXd>& durations_s,
                const Eigen::Ref<const Eigen::VectorXd>& weights, const char* caller) {
  if (coefficients.rows() != kQuinticCoefficients * durations_s.size() ||
      coefficients.cols() != weights.size()) {
    throw std::invalid_argument(std::string(caller) + ": coefficients must be 6M x D with M = " +
                                std::to_string(durations_s.size()) + " durations and D = " +
                                std::to_string(weights.size()) + " weights, got " +
                                std::to_string(coefficients.rows()) + " x " +
                                std::to_string(coefficients.cols()));
  }
}

}  // namespace

Eigen::VectorXd JerkWeightOptions::Weights(int num_joints) const {
  Eigen::VectorXd w(2 + num_joints);
  w(0) = arc_length;
  w(1) = yaw;
  w.tail(num_joints).setConstant(joint);
  return w;
}

double JerkEnergy(const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                  const Eigen::Ref<const Eigen::VectorXd>& durations_s,
                  const Eigen::Ref<const Eigen::VectorXd>& weights) {
  CheckSizes(coefficients, durations_s, weights, "JerkEnergy");
  double energy = 0.0;
  for (int j = 0; j < durations_s.size(); ++j) {
    const double T = durations_s(j);
    const double T2 = T * T, T3 = T2 * T, T4 = T3 * T, T5 = T4 * T;
    for (int d = 0; d < weights.size(); ++d) {
      const double a = coefficients(6 * j + 3, d);
      const double b = coefficients(6 * j + 4, d);
      const double e = coefficients(6 * j + 5, d);
      energy += weights(d) * (36.0 * a * a * T + 144.0 * a * b * T2 +
                              (192.0 * b * b + 240.0 * a * e) * T3 + 720.0 * b * e * T4 +
                              720.0 * e * e * T5);
    }
  }
  return energy;
}

void AddJerkEnergyGradient(const Eigen::Ref<const Eigen::MatrixXd>& coefficients,
                           const Eigen::Ref<const Eigen::VectorXd>& durations_s,
                           const Eigen::Ref<const Eigen::VectorXd>& weights,
                           Eigen::Ref<Eigen::MatrixXd> dE_dc, Eigen::Ref<Eigen::VectorXd> dE_dT) {
  CheckSizes(coefficients, durations_s, weights, "AddJerkEnergyGradient");
  if (dE_dc.rows() != coefficients.rows() || dE_dc.cols() != coefficients.cols() ||
      dE_dT.size() != durations_s.size()) {
    throw std::invalid_argument("AddJerkEnergyGradient: dE_dc must be 6M x D and dE_dT M");
  }
  for (int j = 0; j < durations_s.size(); ++j) {
    const double T = durations_s(j);
    const double T2 = T * T, T3 = T2 * T, T4 = T3 * T, T5 = T4 * T;
    for (int d = 0; d < weights.size(); ++d) {
      const double w = weights(d);
      const double a = coefficients(6 * j + 3, d);
      const double b = coefficients(6 * j + 4, d);
      const double e = coefficients(6 * j + 5, d);
      dE_dc(6 * j + 3, d) += w * (72.0 * a * T + 144.0 * b * T2 + 240.0 * e * T3);
      dE_dc(6 * j + 4, d) += w * (144.0 * a * T2 + 384.0 * b * T3 + 720.0 * e * T4);
      dE_dc(6 * j + 5, d) += w * (240.0 * a * T3 + 720.0 * b * T4 + 1440.0 * e * T5);
      const double jerk_at_end = 6.0 * a + 24.0 * b * T + 60.0 * e * T2;
      dE_dT(j) += w * jerk_at_end * jerk_at_end;
    }
  }
}

}  // namespace topay
