#include "core/control/protective_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/option_checks.h"

namespace topay {
namespace {
constexpr const char* kProtectiveFieldOptions = "ProtectiveFieldOptions";  // the owner in error messages
}  // namespace

void ProtectiveFieldOptions::Check() const {
  CheckOptionNonNegative(kProtectiveFieldOptions, "reaction_s", reaction_s);
  CheckOptionNonNegative(kProtectiveFieldOptions, "lookahead_m", lookahead_m);
  if (!std::isfinite(radial_margin_m) || radial_margin_m > 0.5) {
    FailOption(kProtectiveFieldOptions, "radial_margin_m", radial_margin_m, "finite and <= 0.5");
  }
  if (!std::isfinite(z_min_m)) FailOption(kProtectiveFieldOptions, "z_min_m", z_min_m, "finite");
  if (!std::isfinite(z_max_m) || z_max_m <= z_min_m) {
    FailOption(kProtectiveFieldOptions, "z_max_m", z_max_m, "finite and > z_min_m");
  }
  if (min_points < 1) FailOption(kProtectiveFieldOptions, "min_points", min_points, ">= 1");
  CheckOptionPositive(kProtectiveFieldOptions, "max_scan_age_s", max_scan_age_s);
  CheckOptionPositive(kProtectiveFieldOptions, "step_m", step_m);
  CheckOptionNonNegative(kProtectiveFieldOptions, "self_margin_m", self_margin_m);
}

ProtectiveField::ProtectiveField(const ProtectiveFieldOptions& options, const BaseCylinder& base,
                                 const BaseLimits& limits)
    : options_(options), field_radius_m_(base.radius_m + options.radial_margin_m), limits_(limits) {
  options_.Check();
  if (!(field_radius_m_ > 0.0)) {
    throw std::invalid_argument("ProtectiveField: radial_margin_m " + std::to_string(options.radial_margin_m) +
                                " leaves no field around a base of radius " + std::to_string(base.radius_m));
  }
  if (!(limits.v_max_mps > 0.0) || !(limits.a_max_mps2 > 0.0)) {
    throw std::invalid_argument("ProtectiveField: the base's v_max and a_max must be > 0");
  }
}

double ProtectiveField::LengthM(double speed_mps) const {
  const double v = std::min(std::abs(speed_mps), limits_.v_max_mps);
  // Reaction at the current speed, then braking at a_max: s = v t_r + v^2 / (2 a_max).
  return v * options_.reaction_s + v * v / (2.0 * limits_.a_max_mps2) + options_.lookahead_m;
}

double ProtectiveField::ReachM() const {
  return LengthM(limits_.v_max_mps) + limits_.v_max_mps * options_.max_scan_age_s + field_radius_m_;
}

void ProtectiveField::SetScan(std::span<const Eigen::Vector3f> p_WP, double scan_time_s,
                              const Eigen::Vector2d& p_WB) {
  p_W_.clear();
  const float reach_squared = static_cast<float>(ReachM() * ReachM());
  const Eigen::Vector2f p_WB_xy = p_WB.cast<float>();
  const float z_min = static_cast<float>(options_.z_min_m), z_max = static_cast<float>(options_.z_max_m);
  for (const Eigen::Vector3f& p : p_WP) {
    if (!p.allFinite() || p.z() < z_min || p.z() > z_max) continue;
    if ((p.head<2>() - p_WB_xy).squaredNorm() > reach_squared) continue;
    p_W_.push_back(p);
  }
  scan_time_s_ = scan_time_s;
  has_scan_ = true;
}

void ProtectiveField::ClearScan() {
  p_W_.clear();
  has_scan_ = false;
}

ProtectiveFieldCheck ProtectiveField::Check(std::span<const Eigen::Vector2d> path_W, double now_s) const {
  ProtectiveFieldCheck check;
  // A scan dated in the future by more than the age limit is no more trusted than an old one.
  check.scan_fresh = has_scan_ && std::abs(now_s - scan_time_s_) <= options_.max_scan_age_s;
  if (!check.scan_fresh || path_W.empty()) return check;
  // The path's bounding box grown by the field's radius: points outside it are outside every pose.
  Eigen::Vector2d lo = path_W[0], hi = path_W[0];
  for (const Eigen::Vector2d& p : path_W) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (std::size_t k = 1; k < path_W.size(); ++k) check.path_length_m += (path_W[k] - path_W[k - 1]).norm();
  const Eigen::Vector2f lo_f = (lo.array() - field_radius_m_).cast<float>();
  const Eigen::Vector2f hi_f = (hi.array() + field_radius_m_).cast<float>();
  const double radius_squared = field_radius_m_ * field_radius_m_;
  std::size_t first_pose = path_W.size();
  for (const Eigen::Vector3f& p : p_W_) {
    if ((p.head<2>().array() < lo_f.array()).any() || (p.head<2>().array() > hi_f.array()).any()) continue;
    const Eigen::Vector2d p_xy = p.head<2>().cast<double>();
    for (std::size_t k = 0; k < path_W.size(); ++k) {
      if ((p_xy - path_W[k]).squaredNorm() > radius_squared) continue;
      ++check.num_inside;
      if (k < first_pose) {
        first_pose = k;
        check.p_W_first = p;
      }
      break;
    }
  }
  for (std::size_t k = 1; k <= first_pose && k < path_W.size(); ++k) {
    check.distance_ahead_m += (path_W[k] - path_W[k - 1]).norm();
  }
  check.entered = check.num_inside >= options_.min_points;
  return check;
}

void BasePathAhead(const TrackerReference& reference, double now_s, double length_m, double step_s,
                   double max_horizon_s, std::vector<Eigen::Vector2d>* path, TrajectorySample* sample) {
  path->clear();
  if (!reference.sampler || !(step_s > 0.0)) return;
  const double t_end = reference.start_time_s + reference.duration_s;
  const double t_last = std::min(t_end, now_s + std::max(0.0, max_horizon_s));
  double covered_m = 0.0;
  const double t0 = std::clamp(now_s, reference.start_time_s, t_end);
  for (int k = 0;; ++k) {
    const double t = std::min(t0 + k * step_s, t_last);  // by index: no drift from summing steps
    reference.sampler(t - reference.start_time_s, sample);
    const Eigen::Vector2d p(sample->state.x_m, sample->state.y_m);
    if (!path->empty()) covered_m += (p - path->back()).norm();
    path->push_back(p);
    if (covered_m >= length_m || t >= t_last) return;
  }
}

}  // namespace topay
