#include "core/optimization/field_feasibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/optimization/endpoint_relief.h"
#include "core/planning/base_band.h"

namespace topay {
namespace {

std::string Describe(const char* what, int index, double amount, const char* unit, double t_s) {
  char buffer[160];
  if (index >= 0) {
    std::snprintf(buffer, sizeof(buffer), "%s %d off by %.4f %s at t = %.3f s", what, index,
                  amount, unit, t_s);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%s off by %.4f %s at t = %.3f s", what, amount, unit,
                  t_s);
  }
  return buffer;
}

class Checker {
 public:
  explicit Checker(FieldFeasibilityReport* report) : report_(report) {}

  // Records a requirement value >= 0 (else violated) for the minimum `*minimum`.
  void Clearance(double value, double* minimum, const char* what, int index, double t) {
    *minimum = std::min(*minimum, value);
    if (value < 0.0) Violation(Describe(what, index, -value, "m", t));
  }
  void Rate(double ratio, const std::string& name, double tolerance, double t) {
    if (ratio > report_->max_rate_ratio) {
      report_->max_rate_ratio = ratio;
      report_->worst_rate = name;
    }
    if (ratio > 1.0 + tolerance) {
      Violation(Describe((name + " / limit").c_str(), -1, ratio - 1.0, "(ratio above 1)", t));
    }
  }
  void Violation(const std::string& text) {
    if (report_->feasible) report_->first_violation = text;
    report_->feasible = false;
  }

 private:
  FieldFeasibilityReport* report_;
};

/// The margins the fields' inexactness asks for (m).
struct FieldMargins {
  double base_m = 0.0;
  double arm_m = 0.0;
};

/// Rates (eqs. (9)-(12)) and joint positions of one sample.
void CheckRatesAndJoints(const TrajectorySample& point, const RobotModel& model,
                         const BaseLimits& limits, const FieldFeasibilityOptions& options,
                         Checker* check, FieldFeasibilityReport* report) {
  const JointLimits& joints = model.joint_limits;
  const double t = point.t_s;
  const double w = point.omega_radps / limits.omega_max_radps;
  const double v = point.v_mps / limits.v_max_mps;
  check->Rate(std::max(std::abs(w + v), std::abs(w - v)), "v-omega", options.rate_tolerance, t);
  check->Rate(std::abs(point.a_mps2) / limits.a_max_mps2, "a", options.rate_tolerance, t);
  check->Rate(std::abs(point.beta_radps2) / limits.beta_max_radps2, "beta",
              options.rate_tolerance, t);
  for (int k = 0; k < model.num_joints(); ++k) {
    const std::string joint = std::to_string(k + 1);
    check->Rate(std::abs(point.qd_radps(k)) / joints.qd_max_radps(k), "qd" + joint,
                options.rate_tolerance, t);
    check->Rate(std::abs(point.qdd_radps2(k)) / joints.qdd_max_radps2(k), "qdd" + joint,
                options.rate_tolerance, t);
    const double excess = std::max(point.state.q_rad(k) - joints.q_max_rad(k),
                                   joints.q_min_rad(k) - point.state.q_rad(k));
    report->max_joint_excess_rad = std::max(report->max_joint_excess_rad, excess);
    if (excess > options.joint_position_tolerance_rad) {
      check->Violation(Describe("joint", k + 1, excess, "rad beyond its limit", t));
    }
  }
}

/// The endpoint relief at a sample (none: relief null).
struct SampleRelief {
  const EndpointRelief* relief = nullptr;
  EndpointRelief::Weights weights;

  double base_m() const { return relief ? relief->base_m(weights) : 0.0; }
  double base_primary_m() const { return relief ? relief->base_primary_m(weights) : 0.0; }
  double sphere_m(int s) const { return relief ? relief->sphere_m(s, weights) : 0.0; }
};

/// The relief at global time t: its piece-index fraction (piece j, local tau: (j + tau / T_j)
/// / M), as the optimizer's samples have it.
SampleRelief ReliefAt(const EndpointRelief* relief, const ArcYawTrajectory& trajectory,
                      double t) {
  SampleRelief out;
  if (relief == nullptr) return out;
  const MincoS3& minco = trajectory.minco();
  double local_s = 0.0;
  const int piece = minco.LocatePiece(t, &local_s);
  const double fraction = local_s / minco.durations()(piece);
  out.relief = relief;
  out.weights = relief->WeightsAt(PieceFraction(piece, fraction, minco.num_pieces()));
  return out;
}

/// Clearances (eqs. (13)-(14)) of one sample: base on the 2D field, arm spheres on the 3D
/// field (each requirement less its endpoint relief), chassis and self-collision pairs;
/// `cache` is updated for the sample's state.
void CheckClearances(const TrajectorySample& point, const KinematicsCache& cache,
                     const RobotModel& model, const SignedDistanceField2& base_field,
                     const SignedDistanceField3& arm_field,
                     const std::vector<int>& arm_field_spheres, const FieldMargins& margins,
                     const SampleRelief& relief, const FieldFeasibilityOptions& options,
                     Checker* check, FieldFeasibilityReport* report) {
  const double t = point.t_s;
  const double base = base_field.Distance(Eigen::Vector2d(point.state.x_m, point.state.y_m)) -
                      model.base_cylinder.radius_m - margins.base_m + relief.base_m();
  check->Clearance(base, &report->min_base_clearance_m, "base clearance", -1, t);
  const SignedDistanceField2* primary = base_field.primary_band();
  if (relief.base_m() > 0.0 && primary != nullptr) {  // as SamplePenalties::EvaluateBase
    const double base_primary =
        primary->Distance(Eigen::Vector2d(point.state.x_m, point.state.y_m)) -
        model.base_cylinder.radius_m - margins.base_m + relief.base_primary_m();
    check->Clearance(base_primary, &report->min_base_clearance_m,
                     "base clearance (primary band)", -1, t);
  }
  for (const int s : arm_field_spheres) {
    const double arm = arm_field.Distance(cache.p_WS[s]) - model.spheres[s].radius_m -
                       margins.arm_m + relief.sphere_m(s);
    check->Clearance(arm, &report->min_arm_clearance_m, "arm sphere clearance, sphere", s, t);
  }
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int s = 0; s < num_spheres; ++s) {
    const double chassis = cache.p_WS[s].z() - model.spheres[s].radius_m -
                           model.base_cylinder.height_m - options.chassis_margin_m;
    check->Clearance(chassis, &report->min_chassis_clearance_m, "chassis clearance, sphere", s,
                     t);
  }
  for (std::size_t k = 0; k < model.self_collision_pairs.size(); ++k) {
    const auto [a, b] = model.self_collision_pairs[k];
    const double self = (cache.p_WS[a] - cache.p_WS[b]).norm() - model.spheres[a].radius_m -
                        model.spheres[b].radius_m - options.self_margin_m;
    check->Clearance(self, &report->min_self_clearance_m, "self-collision pair",
                     static_cast<int>(k), t);
  }
}

}  // namespace

std::string DescribeViolations(const FieldFeasibilityReport& report,
                               const FieldFeasibilityOptions& options) {
  std::string out;
  const auto add = [&](const char* format, double value, const std::string& name = "") {
    char buffer[128];
    std::snprintf(buffer, sizeof(buffer), format, name.c_str(), value);
    out += (out.empty() ? "" : "; ") + std::string(buffer);
  };
  if (report.min_arm_clearance_m < 0.0) {
    add("arm clearance%s short by %.4f m", -report.min_arm_clearance_m);
  }
  if (report.min_base_clearance_m < 0.0) {
    add("base clearance%s short by %.4f m", -report.min_base_clearance_m);
  }
  if (report.min_self_clearance_m < 0.0) {
    add("self clearance%s short by %.4f m", -report.min_self_clearance_m);
  }
  if (report.min_chassis_clearance_m < 0.0) {
    add("chassis clearance%s short by %.4f m", -report.min_chassis_clearance_m);
  }
  if (report.max_rate_ratio > 1.0 + options.rate_tolerance) {
    add("%s at %.3f x its limit", report.max_rate_ratio, report.worst_rate);
  }
  if (report.max_joint_excess_rad > options.joint_position_tolerance_rad) {
    add("a joint%s %.4f rad beyond its limit", report.max_joint_excess_rad);
  }
  if (out.empty() && !report.feasible) out = report.first_violation;
  return out;
}

FieldFeasibilityReport CheckFeasibilityOnFields(const ArcYawTrajectory& trajectory,
                                                const Kinematics& kinematics,
                                                const SignedDistanceField2& base_field,
                                                const SignedDistanceField3& arm_field,
                                                const BaseLimits& limits,
                                                const FieldFeasibilityOptions& options,
                                                const EndpointRelief* relief) {
  if (!(options.sample_period_s > 0.0 && options.rate_tolerance >= 0.0 &&
        options.joint_position_tolerance_rad >= 0.0)) {
    throw std::invalid_argument(
        "CheckFeasibilityOnFields: sample_period_s must be > 0 and tolerances >= 0");
  }
  const FieldMargins margins{
      options.base_field_margin_m.value_or(base_field.exactness_margin_m()),
      options.arm_field_margin_m.value_or(arm_field.exactness_margin_m())};
  FieldFeasibilityReport report;
  Checker check(&report);
  TrajectorySample point = trajectory.MakePoint();
  KinematicsCache cache = kinematics.MakeCache();
  const double duration = trajectory.duration_s();
  const int steps = static_cast<int>(std::ceil(duration / options.sample_period_s));
  // The rigid spheres the base field covers pass with the base's check below.
  const std::vector<int> arm_field_spheres = SpheresToCheckOnArmField(kinematics, base_field);
  if (relief != nullptr && relief->empty()) relief = nullptr;
  for (int i = 0; i <= steps; ++i) {
    const double t = std::min(i * options.sample_period_s, duration);
    trajectory.Evaluate(t, &point);
    ++report.num_samples;
    CheckRatesAndJoints(point, kinematics.model(), limits, options, &check, &report);
    kinematics.Update(point.state, &cache);
    CheckClearances(point, cache, kinematics.model(), base_field, arm_field, arm_field_spheres,
                    margins, ReliefAt(relief, trajectory, t), options, &check, &report);
  }
  return report;
}

}  // namespace topay
