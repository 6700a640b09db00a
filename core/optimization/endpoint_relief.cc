#include "core/optimization/endpoint_relief.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/optimization/sample_penalties.h"
#include "core/planning/whole_body_validity.h"

namespace topay {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("EndpointRelief: " + message);
}

/// max(0, threshold - value), + slack if positive.
double Deficit(double threshold_m, double value_m, double slack_m) {
  const double shortfall = threshold_m - value_m;
  return shortfall > 0.0 ? shortfall + slack_m : 0.0;
}

void CheckFraction(double fraction, const char* which) {
  Require(fraction > 0.0 && fraction <= 1.0,
          std::string(which) + " ramp fraction " + std::to_string(fraction) +
              " must be in (0, 1]");
}

void CheckDeficit(const ClearanceDeficit& deficit, const char* which) {
  Require(std::isfinite(deficit.base_m) && deficit.base_m >= 0.0,
          std::string(which) + " base deficit must be finite and >= 0");
  Require(std::isfinite(deficit.base_primary_m) && deficit.base_primary_m >= 0.0,
          std::string(which) + " primary-band base deficit must be finite and >= 0");
  Require(deficit.spheres_m.allFinite() && (deficit.spheres_m.array() >= 0.0).all(),
          std::string(which) + " sphere deficits must be finite and >= 0");
}

/// The ramp's extent from the path's fraction of time at a state, + one piece.
double RampFraction(double path_fraction, int num_pieces) {
  return std::min(1.0, std::max(0.0, path_fraction) + 1.0 / num_pieces);
}

void CheckPathTimes(const Eigen::VectorXd& path_times_s, int count, int num_pieces,
                    const char* what) {
  Require(path_times_s.size() > 0, "the path has no states");
  Require(num_pieces >= 1, "num_pieces must be >= 1");
  Require(count >= 0, std::string(what) + " = " + std::to_string(count) + " must be >= 0");
}

std::string Part(const char* which, const ClearanceDeficit& deficit, const char* where,
                 double fraction) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "%s base %.3f m, arm max %.3f m over the %s %.0f %%",
                which, deficit.base_m, deficit.max_sphere_m(), where, 100.0 * fraction);
  return buffer;
}

// ComputeClearanceDeficit with the caller's kinematics cache (one for a stretch of states).
ClearanceDeficit DeficitWithCache(const SamplePenalties& penalties, const WholeBodyState& state,
                                  double slack_m, KinematicsCache* cache) {
  const Kinematics& kinematics = penalties.kinematics();
  Require(state.num_joints() == kinematics.num_joints() && state.IsFinite(),
          "endpoint state must be finite with " + std::to_string(kinematics.num_joints()) +
              " joints");
  ClearanceDeficit deficit;
  // Eq. (13) as SamplePenalties evaluates it: the base on the 2D field, the arm spheres it
  // checks on the 3D field.
  const Eigen::Vector2d p_WB(state.x_m, state.y_m);
  deficit.base_m =
      Deficit(penalties.base_threshold_m(), penalties.base_field().Distance(p_WB), slack_m);
  const SignedDistanceField2* primary = penalties.base_field().primary_band();
  deficit.base_primary_m =
      primary ? Deficit(penalties.base_threshold_m(), primary->Distance(p_WB), slack_m)
              : deficit.base_m;
  const Eigen::VectorXd& thresholds = penalties.sphere_thresholds_m();
  deficit.spheres_m.setZero(thresholds.size());
  kinematics.Update(state, cache);
  for (const int s : penalties.arm_field_spheres()) {
    deficit.spheres_m(s) =
        Deficit(thresholds(s), penalties.arm_field().Distance(cache->p_WS[s]), slack_m);
  }
  return deficit;
}

// Part by part: deficit <- max(deficit, other).
void RaiseTo(const ClearanceDeficit& other, ClearanceDeficit* deficit) {
  deficit->base_m = std::max(deficit->base_m, other.base_m);
  deficit->base_primary_m = std::max(deficit->base_primary_m, other.base_primary_m);
  deficit->spheres_m = deficit->spheres_m.cwiseMax(other.spheres_m);
}

// Raises `deficit` to the deficits along the edge a -> b (b included), interpolated every
// 2 cm of base travel and 0.05 rad of yaw or joint motion.
void RaiseToEdge(const SamplePenalties& penalties, const WholeBodyState& a,
                 const WholeBodyState& b, double slack_m, ClearanceDeficit* deficit) {
  const int steps = WholeBodyValidity::EdgeInterpolationSteps(a, b, 0.02, 0.05);
  KinematicsCache cache = penalties.kinematics().MakeCache();
  WholeBodyState between;
  for (int i = 1; i <= steps; ++i) {
    WholeBodyValidity::Interpolate(a, b, static_cast<double>(i) / steps, &between);
    RaiseTo(DeficitWithCache(penalties, between, slack_m, &cache), deficit);
  }
}

// Full relief over the exactly validated stretch (f less the extra piece), at least over half
// the ramp; then down over the extra piece.
double Plateau(double fraction, int num_pieces) {
  return std::max(0.5 * fraction, fraction - 1.0 / num_pieces);
}

}  // namespace

void CheckEndpointReliefOptions(const EndpointReliefOptions& options) {
  if (!(std::isfinite(options.slack_m) && options.slack_m >= 0.0)) {
    throw std::invalid_argument("EndpointReliefOptions: slack_m = " +
                                std::to_string(options.slack_m) + " must be finite and >= 0");
  }
}

ClearanceDeficit ComputeClearanceDeficit(const SamplePenalties& penalties,
                                         const WholeBodyState& state, double slack_m) {
  KinematicsCache cache = penalties.kinematics().MakeCache();
  return DeficitWithCache(penalties, state, slack_m, &cache);
}

double ReliefRampWeight(double d, double f, double p) {
  if (d <= p) return 1.0;
  if (d >= f) return 0.0;
  return 0.5 * (1.0 + std::cos(std::numbers::pi * (d - p) / (f - p)));
}

void EndpointRelief::SetStart(const ClearanceDeficit& deficit, double fraction,
                              double plateau) {
  CheckFraction(fraction, "start");
  if (std::isnan(plateau)) plateau = 0.5 * fraction;
  Require(plateau > 0.0 && plateau <= fraction,
          "start ramp plateau " + std::to_string(plateau) + " must be in (0, fraction]");
  CheckDeficit(deficit, "start");
  Require(!has_goal_ || goal_.spheres_m.size() == deficit.spheres_m.size(),
          "the start's and the goal's deficits have different sphere counts");
  start_ = deficit;
  f_start_ = fraction;
  p_start_ = plateau;
  has_start_ = true;
}

void EndpointRelief::SetGoal(const ClearanceDeficit& deficit, double fraction,
                              double plateau) {
  CheckFraction(fraction, "goal");
  if (std::isnan(plateau)) plateau = 0.5 * fraction;
  Require(plateau > 0.0 && plateau <= fraction,
          "goal ramp plateau " + std::to_string(plateau) + " must be in (0, fraction]");
  CheckDeficit(deficit, "goal");
  Require(!has_start_ || start_.spheres_m.size() == deficit.spheres_m.size(),
          "the start's and the goal's deficits have different sphere counts");
  goal_ = deficit;
  f_goal_ = fraction;
  p_goal_ = plateau;
  has_goal_ = true;
}

EndpointRelief::Weights EndpointRelief::WeightsAt(double u) const {
  Weights w;
  if (has_start_) w.start = ReliefRampWeight(u, f_start_, p_start_);
  if (has_goal_) w.goal = ReliefRampWeight(1.0 - u, f_goal_, p_goal_);
  return w;
}

std::string EndpointRelief::Describe() const {
  std::string out;
  if (has_start_) out = Part("start", start_, "first", f_start_);
  if (has_goal_) out += (out.empty() ? "" : " / ") + Part("goal", goal_, "last", f_goal_);
  return out;
}

double StartReliefFraction(const Eigen::VectorXd& path_times_s, int exact_prefix_states,
                           int num_pieces) {
  CheckPathTimes(path_times_s, exact_prefix_states, num_pieces, "exact_prefix_states");
  const int last = static_cast<int>(path_times_s.size()) - 1;
  const double total = path_times_s(last);
  if (!(total > 0.0)) return 1.0;
  return RampFraction(path_times_s(std::min(exact_prefix_states, last)) / total, num_pieces);
}

double GoalReliefFraction(const Eigen::VectorXd& path_times_s, int exact_suffix_states,
                          int num_pieces) {
  CheckPathTimes(path_times_s, exact_suffix_states, num_pieces, "exact_suffix_states");
  const int last = static_cast<int>(path_times_s.size()) - 1;
  const double total = path_times_s(last);
  if (!(total > 0.0)) return 1.0;
  const int state = std::max(last - exact_suffix_states, 0);
  return RampFraction((total - path_times_s(state)) / total, num_pieces);
}

EndpointRelief MakeEndpointRelief(const SamplePenalties& penalties, const WholeBodyState& start,
                                  const std::vector<WholeBodyState>& path_states,
                                  const Eigen::VectorXd& path_times_s, int num_pieces,
                                  int exact_prefix_states, int exact_suffix_states,
                                  const EndpointReliefOptions& options) {
  CheckEndpointReliefOptions(options);
  const int n = static_cast<int>(path_states.size());
  EndpointRelief relief;
  if (exact_prefix_states != 0) {
    const double f = StartReliefFraction(path_times_s, exact_prefix_states, num_pieces);
    ClearanceDeficit deficit = ComputeClearanceDeficit(penalties, start, options.slack_m);
    for (int k = 1; k < std::min(exact_prefix_states, n); ++k) {
      RaiseToEdge(penalties, path_states[k - 1], path_states[k], options.slack_m, &deficit);
    }
    if (!deficit.IsZero()) relief.SetStart(deficit, f, Plateau(f, num_pieces));
  }
  if (exact_suffix_states != 0) {
    const double f = GoalReliefFraction(path_times_s, exact_suffix_states, num_pieces);
    const WholeBodyState& end = n > 1 ? path_states.back() : start;
    ClearanceDeficit deficit = ComputeClearanceDeficit(penalties, end, options.slack_m);
    for (int k = std::max(1, n - exact_suffix_states); k < n; ++k) {
      RaiseToEdge(penalties, path_states[k - 1], path_states[k], options.slack_m, &deficit);
    }
    if (!deficit.IsZero()) relief.SetGoal(deficit, f, Plateau(f, num_pieces));
  }
  return relief;
}

}  // namespace topay
