#include "core/planning/lead_in.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "core/robot/unicycle_motion.h"

namespace topay {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("MakeLeadIn: " + message);
}

void CheckInputs(const MovingState& start, const BaseLimits& base, const JointLimits& joints) {
  const int n = start.state.num_joints();
  Require(start.state.IsFinite(), "the start state is not finite");
  Require(start.rates.IsFinite() && start.rates.HasJointCount(n),
          "the start rates are not finite or not sized for " + std::to_string(n) + " joints");
  Require(std::isfinite(base.a_max_mps2) && base.a_max_mps2 > 0.0, "a_max must be > 0");
  Require(joints.q_min_rad.size() == n && joints.q_max_rad.size() == n &&
              joints.qdd_max_radps2.size() == n && (joints.qdd_max_radps2.array() > 0.0).all(),
          "joint limits must be sized for " + std::to_string(n) + " joints, qdd_max > 0");
}

}  // namespace

void CheckLeadInOptions(const LeadInOptions& o) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("LeadInOptions: ") + what);
  };
  require(std::isfinite(o.min_speed_mps) && o.min_speed_mps >= 0.0,
          "min_speed_mps must be finite and >= 0");
  require(std::isfinite(o.extra_distance_m) && o.extra_distance_m >= 0.0,
          "extra_distance_m must be finite and >= 0");
  require(std::isfinite(o.step_m) && o.step_m > 0.0, "step_m must be finite and > 0");
}

LeadIn MakeLeadIn(const MovingState& start, const BaseLimits& base_limits,
                  const JointLimits& joint_limits, const LeadInOptions& options) {
  CheckLeadInOptions(options);
  CheckInputs(start, base_limits, joint_limits);
  LeadIn lead_in;
  lead_in.states.push_back(start.state);
  lead_in.times_s.push_back(0.0);
  const double v = start.rates.v_mps, speed = std::abs(v);
  if (speed < options.min_speed_mps) return lead_in;
  const double a_max = base_limits.a_max_mps2;
  // Braking distance at a_max from |v|, plus room: v^2 / (2 a_max) + extra.
  lead_in.distance_m = 0.5 * speed * speed / a_max + options.extra_distance_m;
  const double direction = v > 0.0 ? 1.0 : -1.0;
  const double kappa = start.rates.omega_radps / v;  // dyaw/ds of the current arc
  const int n = start.state.num_joints();
  // Joint braking positions q + qd |qd| / (2 qdd_max), inside the limits.
  const Eigen::VectorXd qd = start.rates.JointVelocities(n);
  const Eigen::VectorXd q_stop =
      (start.state.q_rad.array() +
       qd.array() * qd.array().abs() / (2.0 * joint_limits.qdd_max_radps2.array()))
          .max(joint_limits.q_min_rad.array())
          .min(joint_limits.q_max_rad.array())
          .matrix();
  const int steps = std::max(1, static_cast<int>(std::ceil(lead_in.distance_m / options.step_m)));
  const double step = lead_in.distance_m / steps;
  const double braking_m = 0.5 * speed * speed / a_max;
  WholeBodyState state = start.state;
  for (int k = 1; k <= steps; ++k) {
    // One step of arc length along the unicycle (eqs. (1)-(2)) at unit speed in v's
    // direction and yaw rate kappa per metre: yaw changes by kappa x signed arc length.
    AdvanceUnicycle(direction, direction * kappa, step, &state);
    const double sigma = k * step;
    state.q_rad = start.state.q_rad + (sigma / lead_in.distance_m) * (q_stop - start.state.q_rad);
    lead_in.states.push_back(state);
    // Braking at a_max: sigma = |v| t - a t^2 / 2; the extra beyond the stop as if at |v|
    // (the times only label the path's states, increasing).
    const double t =
        sigma <= braking_m
            ? (speed - std::sqrt(std::max(speed * speed - 2.0 * a_max * sigma, 0.0))) / a_max
            : speed / a_max + (sigma - braking_m) / speed;
    lead_in.times_s.push_back(t);
  }
  return lead_in;
}

std::string CheckLeadIn(const LeadIn& lead_in, const WholeBodyValidity& validity,
                        const SceneClearanceChecker* exact, double obstacle_margin_m,
                        double self_margin_m, bool* used_exact) {
  *used_exact = false;
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  std::optional<SceneClearanceWorkspace> exact_workspace;
  if (exact != nullptr) exact_workspace.emplace(exact->MakeWorkspace());
  const int n = static_cast<int>(lead_in.states.size());
  for (int k = 1; k < n; ++k) {
    const WholeBodyState& state = lead_in.states[k];
    const ValidityFailure failure = validity.CheckOnFields(state, &workspace);
    if (failure == ValidityFailure::kNone) continue;
    if (exact != nullptr &&
        exact->IsCollisionFree(state, obstacle_margin_m, self_margin_m, &*exact_workspace)) {
      *used_exact = true;
      continue;
    }
    char text[160];
    std::snprintf(text, sizeof(text),
                  "moving start: the lead-in along the current heading (%.2f m, braking) "
                  "collides at %.2f m (%s)",
                  lead_in.distance_m, lead_in.distance_m * k / (n - 1),
                  std::string(ToString(failure)).c_str());
    return text;
  }
  return "";
}

}  // namespace topay
