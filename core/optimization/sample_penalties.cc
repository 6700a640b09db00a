#include "core/optimization/sample_penalties.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/optimization/endpoint_relief.h"
#include "core/optimization/smooth_penalty.h"
#include "core/planning/base_band.h"
#include "core/robot/fixed_height_links.h"

namespace topay {
namespace {

void CheckPositive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("SamplePenalties: ") + name + " = " +
                                std::to_string(value) + " must be finite and > 0");
  }
}

void CheckNonNegative(double value, const char* name) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw std::invalid_argument(std::string("SamplePenalties: ") + name + " = " +
                                std::to_string(value) + " must be finite and >= 0");
  }
}

void CheckFinite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("SamplePenalties: ") + name + " is not finite");
  }
}

bool NeedsKinematics(const PenaltyMask& enabled) {
  return enabled[static_cast<int>(PenaltyTerm::kArmObstacle)] ||
         enabled[static_cast<int>(PenaltyTerm::kSelfCollision)] ||
         enabled[static_cast<int>(PenaltyTerm::kChassis)];
}

/// The base limits and the options SamplePenalties takes (throws naming the first bad one).

/// Joint limits sized for n joints, finite positions with min < max, positive rates.
void CheckJointLimits(const JointLimits& joints, int n) {
  if (joints.q_min_rad.size() != n || joints.q_max_rad.size() != n ||
      joints.qd_max_radps.size() != n || joints.qdd_max_radps2.size() != n) {
    throw std::invalid_argument("SamplePenalties: joint limits are not sized for " +
                                std::to_string(n) + " joints");
  }
  for (int k = 0; k < n; ++k) {
    if (!(std::isfinite(joints.q_min_rad(k)) && std::isfinite(joints.q_max_rad(k)) &&
          joints.q_min_rad(k) < joints.q_max_rad(k))) {
      throw std::invalid_argument("SamplePenalties: position limits of joint " +
                                  std::to_string(k + 1) + " are not finite with min < max");
    }
    CheckPositive(joints.qd_max_radps(k), "joint_limits.qd_max_radps");
    CheckPositive(joints.qdd_max_radps2(k), "joint_limits.qdd_max_radps2");
  }
}

/// Every base limit times `fraction`.
BaseLimits ScaledBaseLimits(BaseLimits limits, double fraction) {
  limits.v_max_mps *= fraction;
  limits.a_max_mps2 *= fraction;
  limits.omega_max_radps *= fraction;
  limits.beta_max_radps2 *= fraction;
  return limits;
}

}  // namespace

void CheckSamplePenaltyOptions(const SamplePenaltyOptions& o) {
  CheckPositive(o.smoothing_mu, "smoothing_mu");
  const std::pair<const char*, double> weights[] = {
      {"velocity_omega_weight", o.velocity_omega_weight},
      {"acceleration_weight", o.acceleration_weight},
      {"yaw_acceleration_weight", o.yaw_acceleration_weight},
      {"joint_position_weight", o.joint_position_weight},
      {"joint_velocity_weight", o.joint_velocity_weight},
      {"joint_acceleration_weight", o.joint_acceleration_weight},
      {"base_obstacle_weight", o.base_obstacle_weight},
      {"arm_obstacle_weight", o.arm_obstacle_weight},
      {"self_collision_weight", o.self_collision_weight},
      {"chassis_weight", o.chassis_weight}};
  for (const auto& [name, weight] : weights) CheckNonNegative(weight, name);
  CheckPositive(o.base_radius_factor, "base_radius_factor");
  if (!(o.rate_limit_fraction > 0.0 && o.rate_limit_fraction <= 1.0)) {
    throw std::invalid_argument("SamplePenalties: rate_limit_fraction = " +
                                std::to_string(o.rate_limit_fraction) + " must be in (0, 1]");
  }
  CheckPositive(o.sphere_radius_factor, "sphere_radius_factor");
  CheckFinite(o.self_margin_m, "self_margin_m");
  CheckFinite(o.chassis_margin_m, "chassis_margin_m");
  CheckNonNegative(o.joint_position_margin_rad, "joint_position_margin_rad");
  if (o.base_field_margin_m) CheckNonNegative(*o.base_field_margin_m, "base_field_margin_m");
  if (o.arm_field_margin_m) CheckNonNegative(*o.arm_field_margin_m, "arm_field_margin_m");
}

std::string_view ToString(PenaltyTerm term) {
  switch (term) {
    case PenaltyTerm::kVelocityOmega: return "velocity-omega";
    case PenaltyTerm::kAcceleration: return "acceleration";
    case PenaltyTerm::kYawAcceleration: return "yaw acceleration";
    case PenaltyTerm::kJointPosition: return "joint position";
    case PenaltyTerm::kJointVelocity: return "joint velocity";
    case PenaltyTerm::kJointAcceleration: return "joint acceleration";
    case PenaltyTerm::kBaseObstacle: return "base obstacle";
    case PenaltyTerm::kArmObstacle: return "arm obstacle";
    case PenaltyTerm::kSelfCollision: return "self collision";
    case PenaltyTerm::kChassis: return "arm above chassis";
  }
  return "unknown";
}

double SamplePenaltyOptions::Weight(PenaltyTerm term) const {
  switch (term) {
    case PenaltyTerm::kVelocityOmega: return velocity_omega_weight;
    case PenaltyTerm::kAcceleration: return acceleration_weight;
    case PenaltyTerm::kYawAcceleration: return yaw_acceleration_weight;
    case PenaltyTerm::kJointPosition: return joint_position_weight;
    case PenaltyTerm::kJointVelocity: return joint_velocity_weight;
    case PenaltyTerm::kJointAcceleration: return joint_acceleration_weight;
    case PenaltyTerm::kBaseObstacle: return base_obstacle_weight;
    case PenaltyTerm::kArmObstacle: return arm_obstacle_weight;
    case PenaltyTerm::kSelfCollision: return self_collision_weight;
    case PenaltyTerm::kChassis: return chassis_weight;
  }
  return 0.0;
}

void SampleQuantities::SetZero() {
  x_m = y_m = yaw_rad = v_mps = a_mps2 = omega_radps = beta_radps2 = 0.0;
  q_rad.setZero();
  qd_radps.setZero();
  qdd_radps2.setZero();
}

SamplePenalties::SamplePenalties(const Kinematics& kinematics,
                                 const SignedDistanceField2& base_field,
                                 const SignedDistanceField3& arm_field,
                                 const BaseLimits& base_limits,
                                 const SamplePenaltyOptions& options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      limits_(base_limits),
      options_(options) {
  CheckPositive(limits_.v_max_mps, "base_limits.v_max_mps");
  CheckPositive(limits_.a_max_mps2, "base_limits.a_max_mps2");
  CheckPositive(limits_.omega_max_radps, "base_limits.omega_max_radps");
  CheckPositive(limits_.beta_max_radps2, "base_limits.beta_max_radps2");
  CheckSamplePenaltyOptions(options_);
  const RobotModel& model = kinematics.model();
  const int n = model.num_joints();
  const JointLimits& joints = model.joint_limits;
  CheckJointLimits(joints, n);
  const double base_margin = options_.base_field_margin_m.value_or(
      base_field.exactness_margin_m());
  const double arm_margin =
      options_.arm_field_margin_m.value_or(arm_field.exactness_margin_m());
  CheckNonNegative(base_margin, "base_field_margin_m");
  CheckNonNegative(arm_margin, "arm_field_margin_m");
  base_threshold_m_ = options_.base_radius_factor * model.base_cylinder.radius_m + base_margin;
  arm_field_spheres_ = SpheresToCheckOnArmField(kinematics, base_field);
  const std::vector<bool> fixed_height = FixedHeightLinks(model);
  for (int s = 0; s < static_cast<int>(model.spheres.size()); ++s) {
    if (!fixed_height[static_cast<std::size_t>(model.spheres[s].link)]) chassis_spheres_.push_back(s);
  }
  sphere_thresholds_m_.resize(static_cast<int>(model.spheres.size()));
  for (int s = 0; s < sphere_thresholds_m_.size(); ++s) {
    sphere_thresholds_m_(s) =
        options_.sphere_radius_factor * model.spheres[s].radius_m + arm_margin;
  }
  const double fraction = options_.rate_limit_fraction;
  limits_ = ScaledBaseLimits(limits_, fraction);
  qd_max_radps_ = fraction * joints.qd_max_radps;
  qdd_max_radps2_ = fraction * joints.qdd_max_radps2;
  joint_middle_rad_ = 0.5 * (joints.q_min_rad + joints.q_max_rad);
  joint_half_range_rad_ =
      0.5 * (joints.q_max_rad - joints.q_min_rad).array() - options_.joint_position_margin_rad;
  if (n > 0) {
    CheckPositive(joint_half_range_rad_.minCoeff(),
                  "the smallest joint half range minus joint_position_margin_rad");
  }
  state_.q_rad.setZero(n);
  cache_ = kinematics.MakeCache();
  gradient_z_.setZero(kinematics.num_states());
}

SampleQuantities SamplePenalties::MakeQuantities() const {
  SampleQuantities quantities;
  quantities.q_rad.setZero(num_joints());
  quantities.qd_radps.setZero(num_joints());
  quantities.qdd_radps2.setZero(num_joints());
  return quantities;
}

double SamplePenalties::Add(PenaltyTerm term, double constraint, double* total,
                            PenaltyValues* costs) const {
  if (constraint <= 0.0) return 0.0;
  const SmoothPenaltyValue l = SmoothPenalty(constraint, options_.smoothing_mu);
  const double weight = weight_scales_[static_cast<int>(term)] * options_.Weight(term);
  *total += weight * l.value;
  if (costs) (*costs)[static_cast<int>(term)] += weight * l.value;
  return weight * l.derivative;
}

double SamplePenalties::Evaluate(const SampleQuantities& sample, double u,
                                 SampleQuantities* gradient, PenaltyValues* costs) {
  return EvaluateWith(sample, relief_, u, gradient, costs);
}

double SamplePenalties::Evaluate(const SampleQuantities& sample, SampleQuantities* gradient,
                                 PenaltyValues* costs) {
  return EvaluateWith(sample, nullptr, 0.0, gradient, costs);
}

double SamplePenalties::EvaluateWith(const SampleQuantities& sample,
                                     const EndpointRelief* relief, double u,
                                     SampleQuantities* gradient, PenaltyValues* costs) {
  if (gradient) gradient->SetZero();
  double total = 0.0;
  EvaluateBase(sample, relief, u, gradient, &total, costs);
  EvaluateJoints(sample, gradient, &total, costs);
  EvaluateGeometry(sample, relief, u, gradient, &total, costs);
  return total;
}

void SamplePenalties::EvaluateBase(const SampleQuantities& sample, const EndpointRelief* relief,
                                   double u, SampleQuantities* gradient, double* total,
                                   PenaltyValues* costs) {
  const double rate_scale = tightening_.rate_scale;
  const double v_max = rate_scale * limits_.v_max_mps;
  const double w_max = rate_scale * limits_.omega_max_radps;
  if (enabled(PenaltyTerm::kVelocityOmega)) {
    // Eq. (9), squared: (v_max omega +- omega_max v)^2 - (v_max omega_max)^2 <= 0.
    for (const double sign : {1.0, -1.0}) {
      const double u = v_max * sample.omega_radps + sign * w_max * sample.v_mps;
      const double slope =
          Add(PenaltyTerm::kVelocityOmega, u * u - v_max * v_max * w_max * w_max, total, costs);
      if (gradient && slope != 0.0) {
        gradient->omega_radps += slope * 2.0 * u * v_max;
        gradient->v_mps += slope * 2.0 * u * sign * w_max;
      }
    }
  }
  if (enabled(PenaltyTerm::kAcceleration)) {
    // Eq. (10): a^2 - a_max^2 <= 0.
    const double a = sample.a_mps2, a_max = rate_scale * limits_.a_max_mps2;
    const double slope = Add(PenaltyTerm::kAcceleration, a * a - a_max * a_max, total, costs);
    if (gradient) gradient->a_mps2 += slope * 2.0 * a;
  }
  if (enabled(PenaltyTerm::kYawAcceleration)) {
    // Eq. (10): beta^2 - beta_max^2 <= 0.
    const double b = sample.beta_radps2, b_max = rate_scale * limits_.beta_max_radps2;
    const double slope = Add(PenaltyTerm::kYawAcceleration, b * b - b_max * b_max, total, costs);
    if (gradient) gradient->beta_radps2 += slope * 2.0 * b;
  }
  if (enabled(PenaltyTerm::kBaseObstacle)) {
    // Eq. (13), base cylinder on the 2D field: threshold - SDF(x, y) <= 0, the threshold
    // tightened and relieved near an endpoint (a constant at this u).
    Eigen::Vector2d field_gradient;
    const double distance = base_field_.DistanceAndGradient(
        Eigen::Vector2d(sample.x_m, sample.y_m), &field_gradient);
    const double relief_m = relief ? relief->base_m(u) : 0.0;
    const double slope =
        Add(PenaltyTerm::kBaseObstacle,
            base_threshold_m_ + tightening_.base_m - relief_m - distance, total, costs);
    if (gradient && slope != 0.0) {
      gradient->x_m -= slope * field_gradient.x();
      gradient->y_m -= slope * field_gradient.y();
    }
    const SignedDistanceField2* primary = base_field_.primary_band();
    if (relief_m > 0.0 && primary != nullptr) {
      // Relieved near an endpoint, the lowered band (parts above the chassis) may come as
      // close as the endpoint does; the primary band (what the base cylinder itself touches)
      // keeps its threshold less the endpoint's own deficit on it (usually none).
      const double primary_distance = primary->DistanceAndGradient(
          Eigen::Vector2d(sample.x_m, sample.y_m), &field_gradient);
      const double primary_slope =
          Add(PenaltyTerm::kBaseObstacle,
              base_threshold_m_ + tightening_.base_m - relief->base_primary_m(u) -
                  primary_distance,
              total, costs);
      if (gradient && primary_slope != 0.0) {
        gradient->x_m -= primary_slope * field_gradient.x();
        gradient->y_m -= primary_slope * field_gradient.y();
      }
    }
  }
}

void SamplePenalties::EvaluateJoints(const SampleQuantities& sample, SampleQuantities* gradient,
                                     double* total, PenaltyValues* costs) {
  const bool position = enabled(PenaltyTerm::kJointPosition);
  const bool velocity = enabled(PenaltyTerm::kJointVelocity);
  const bool acceleration = enabled(PenaltyTerm::kJointAcceleration);
  const double rate_scale = tightening_.rate_scale;
  for (int k = 0; k < num_joints(); ++k) {
    if (position) {
      // Eq. (11), q o q <= q_max2 for a range centred on m_k (h: half range - margin):
      // (q - m)^2 - h^2 <= 0.
      const double e = sample.q_rad(k) - joint_middle_rad_(k);
      const double h = std::max(joint_half_range_rad_(k) - tightening_.joint_rad, 1e-3);
      const double slope = Add(PenaltyTerm::kJointPosition, e * e - h * h, total, costs);
      if (gradient) gradient->q_rad(k) += slope * 2.0 * e;
    }
    if (velocity) {
      // Eq. (11): q'^2 - q'_max^2 <= 0.
      const double qd = sample.qd_radps(k), qd_max = rate_scale * qd_max_radps_(k);
      const double slope =
          Add(PenaltyTerm::kJointVelocity, qd * qd - qd_max * qd_max, total, costs);
      if (gradient) gradient->qd_radps(k) += slope * 2.0 * qd;
    }
    if (acceleration) {
      // Eq. (12): q''^2 - q''_max^2 <= 0.
      const double qdd = sample.qdd_radps2(k), qdd_max = rate_scale * qdd_max_radps2_(k);
      const double slope =
          Add(PenaltyTerm::kJointAcceleration, qdd * qdd - qdd_max * qdd_max, total, costs);
      if (gradient) gradient->qdd_radps2(k) += slope * 2.0 * qdd;
    }
  }
}

void SamplePenalties::EvaluateGeometry(const SampleQuantities& sample,
                                       const EndpointRelief* relief, double u,
                                       SampleQuantities* gradient, double* total,
                                       PenaltyValues* costs) {
  if (!NeedsKinematics(options_.enabled)) return;
  state_.x_m = sample.x_m;
  state_.y_m = sample.y_m;
  state_.yaw_rad = sample.yaw_rad;
  state_.q_rad = sample.q_rad;
  kinematics_.Update(state_, &cache_);
  gradient_z_.setZero();
  bool any_active = false;
  const bool with_gradient = gradient != nullptr;
  if (enabled(PenaltyTerm::kArmObstacle)) {
    any_active = AddArmObstacle(relief, u, with_gradient, total, costs) || any_active;
  }
  if (enabled(PenaltyTerm::kSelfCollision)) {
    any_active = AddSelfCollision(with_gradient, total, costs) || any_active;
  }
  if (enabled(PenaltyTerm::kChassis)) {
    any_active = AddChassis(with_gradient, total, costs) || any_active;
  }
  if (gradient && any_active) {
    gradient->x_m += gradient_z_(0);
    gradient->y_m += gradient_z_(1);
    gradient->yaw_rad += gradient_z_(2);
    gradient->q_rad += gradient_z_.tail(num_joints());
  }
}

// Eq. (13), arm spheres on the 3D field: threshold_s - SDF(p_WS) <= 0, the threshold
// tightened and relieved near an endpoint (a constant at this u).
bool SamplePenalties::AddArmObstacle(const EndpointRelief* relief, double u, bool with_gradient,
                                     double* total, PenaltyValues* costs) {
  const RobotModel& model = kinematics_.model();
  const EndpointRelief::Weights weights =
      relief ? relief->WeightsAt(u) : EndpointRelief::Weights();
  bool any_active = false;
  for (const int s : arm_field_spheres_) {
    Eigen::Vector3d field_gradient;
    const double distance = arm_field_.DistanceAndGradient(cache_.p_WS[s], &field_gradient);
    const double relief_m = relief ? relief->sphere_m(s, weights) : 0.0;
    const double slope =
        Add(PenaltyTerm::kArmObstacle,
            sphere_thresholds_m_(s) + tightening_.arm_m - relief_m - distance, total, costs);
    if (with_gradient && slope != 0.0) {
      kinematics_.AddPointJacobianTransposeTimes(cache_, model.spheres[s].link, cache_.p_WS[s],
                                                 -slope * field_gradient, gradient_z_);
      any_active = true;
    }
  }
  return any_active;
}

// Eq. (14): margin - (|p_i - p_j| - r_i - r_j) <= 0 for every checked pair.
bool SamplePenalties::AddSelfCollision(bool with_gradient, double* total, PenaltyValues* costs) {
  const RobotModel& model = kinematics_.model();
  bool any_active = false;
  for (const auto& [i, j] : model.self_collision_pairs) {
    const Eigen::Vector3d r_W = cache_.p_WS[i] - cache_.p_WS[j];
    const double norm = r_W.norm();
    const double distance = norm - model.spheres[i].radius_m - model.spheres[j].radius_m;
    const double slope =
        Add(PenaltyTerm::kSelfCollision, options_.self_margin_m - distance, total, costs);
    if (with_gradient && slope != 0.0 && norm > 0.0) {
      const Eigen::Vector3d f_W = -slope / norm * r_W;  // d(-distance)/dp_i = -n
      kinematics_.AddPointJacobianTransposeTimes(cache_, model.spheres[i].link, cache_.p_WS[i],
                                                 f_W, gradient_z_);
      kinematics_.AddPointJacobianTransposeTimes(cache_, model.spheres[j].link, cache_.p_WS[j],
                                                 -f_W, gradient_z_);
      any_active = true;
    }
  }
  return any_active;
}

// Arm above the chassis (the authors' code): margin - (z_s - r_s - top) <= 0.
bool SamplePenalties::AddChassis(bool with_gradient, double* total, PenaltyValues* costs) {
  const RobotModel& model = kinematics_.model();
  const double top = model.base_cylinder.height_m;
  bool any_active = false;
  for (const int s : chassis_spheres_) {
    const double clearance = cache_.p_WS[s].z() - model.spheres[s].radius_m - top;
    const double slope =
        Add(PenaltyTerm::kChassis, options_.chassis_margin_m - clearance, total, costs);
    if (with_gradient && slope != 0.0) {
      kinematics_.AddPointJacobianTransposeTimes(cache_, model.spheres[s].link, cache_.p_WS[s],
                                                 Eigen::Vector3d(0.0, 0.0, -slope), gradient_z_);
      any_active = true;
    }
  }
  return any_active;
}

}  // namespace topay
