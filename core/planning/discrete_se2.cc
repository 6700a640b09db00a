#include "core/planning/discrete_se2.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/angles.h"

namespace topay {
namespace {

void RequirePositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("DiscreteSE2: ") + name +
                                " must be positive and finite, got " + std::to_string(value));
  }
}

void Validate(const std::vector<Eigen::Vector2d>& waypoints, double start_yaw, double goal_yaw,
              const BaseLimits& limits, const DiscreteSE2Options& options) {
  if (waypoints.empty()) throw std::invalid_argument("DiscreteSE2: no waypoints");
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    if (!waypoints[i].allFinite()) {
      throw std::invalid_argument("DiscreteSE2: waypoint " + std::to_string(i) + " is not finite");
    }
  }
  if (!std::isfinite(start_yaw)) throw std::invalid_argument("DiscreteSE2: start yaw not finite");
  if (!std::isfinite(goal_yaw)) throw std::invalid_argument("DiscreteSE2: goal yaw not finite");
  CheckDiscreteSE2Options(options);
  RequirePositive(limits.v_max_mps, "limits.v_max_mps");
  RequirePositive(limits.a_max_mps2, "limits.a_max_mps2");
  RequirePositive(limits.omega_max_radps, "limits.omega_max_radps");
  RequirePositive(limits.beta_max_radps2, "limits.beta_max_radps2");
}

double Heading(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  return std::atan2(d.y(), d.x());
}

/// Drops near-duplicate waypoints, then interior vertices where the heading does not turn
/// (collinear segments become one straight run).
std::vector<Eigen::Vector2d> Simplify(const std::vector<Eigen::Vector2d>& waypoints,
                                      const DiscreteSE2Options& options) {
  std::vector<Eigen::Vector2d> distinct{waypoints.front()};
  for (const Eigen::Vector2d& p : waypoints) {
    if ((p - distinct.back()).norm() >= options.min_segment_m) distinct.push_back(p);
  }
  // Keep the goal position exactly (the last distinct point may be a near-duplicate of it).
  if (distinct.size() > 1) distinct.back() = waypoints.back();
  std::vector<Eigen::Vector2d> runs{distinct.front()};
  for (std::size_t i = 1; i + 1 < distinct.size(); ++i) {
    const double turn =
        WrapAngle(Heading(distinct[i], distinct[i + 1]) - Heading(runs.back(), distinct[i]));
    if (std::abs(turn) >= options.min_turn_rad) runs.push_back(distinct[i]);
  }
  if (distinct.size() > 1) runs.push_back(distinct.back());
  return runs;
}

/// Builds the sequence layer by layer; each run (straight or turn) is timed from rest to rest.
class LayerBuilder {
 public:
  LayerBuilder(const BaseLimits& limits, const DiscreteSE2Options& options)
      : limits_(limits), options_(options) {}

  void Start(const Eigen::Vector2d& p, double yaw) {
    Se2Layer first;
    first.x_m = p.x();
    first.y_m = p.y();
    first.yaw_rad = yaw;
    path_.layers.push_back(first);
  }

  /// Turns in place from the current yaw to `target_yaw` (mod 2 pi), the shorter way round
  /// or, if other_way, the longer.
  void TurnTo(double target_yaw, bool other_way = false) {
    const Se2Layer from = path_.layers.back();
    double turn = WrapAngle(target_yaw - from.yaw_rad);
    if (std::abs(turn) < options_.min_turn_rad) return;
    if (other_way) turn -= std::copysign(2.0 * std::numbers::pi, turn);
    const int steps = static_cast<int>(std::ceil(std::abs(turn) / options_.max_turn_step_rad));
    for (int k = 1; k <= steps; ++k) {
      const double swept = std::abs(turn) * k / steps;
      Se2Layer layer = from;
      layer.yaw_rad = from.yaw_rad + (k == steps ? turn : turn * k / steps);
      layer.turn_in_place = true;
      layer.time_s =
          from.time_s + TrapezoidArrivalTime(swept, std::abs(turn), limits_.omega_max_radps,
                                             limits_.beta_max_radps2);
      Push(layer);
    }
  }

  /// Drives straight from the current position to `to` (the yaw must already face it).
  void DriveTo(const Eigen::Vector2d& to) {
    const Se2Layer from = path_.layers.back();
    const Eigen::Vector2d p0(from.x_m, from.y_m);
    const double length = (to - p0).norm();
    const int steps = static_cast<int>(std::ceil(length / options_.delta_l_m));
    for (int k = 1; k <= steps; ++k) {
      const double s = length * k / steps;
      const Eigen::Vector2d p = k == steps ? to : Eigen::Vector2d(p0 + (to - p0) * k / steps);
      Se2Layer layer = from;
      layer.x_m = p.x();
      layer.y_m = p.y();
      layer.arc_length_m = from.arc_length_m + s;
      layer.turn_in_place = false;
      layer.time_s =
          from.time_s + TrapezoidArrivalTime(s, length, limits_.v_max_mps, limits_.a_max_mps2);
      Push(layer);
    }
  }

  DiscreteSE2Path Take() { return std::move(path_); }

 private:
  void Push(Se2Layer layer) {
    layer.step_time_s = layer.time_s - path_.layers.back().time_s;
    path_.layers.push_back(layer);
  }

  const BaseLimits& limits_;
  const DiscreteSE2Options& options_;
  DiscreteSE2Path path_;
};

}  // namespace

void CheckDiscreteSE2Options(const DiscreteSE2Options& options) {
  RequirePositive(options.delta_l_m, "options.delta_l_m");
  RequirePositive(options.max_turn_step_rad, "options.max_turn_step_rad");
  RequirePositive(options.min_turn_rad, "options.min_turn_rad");
  RequirePositive(options.min_segment_m, "options.min_segment_m");
}

WholeBodyState DiscreteSE2Path::State(int layer, const Eigen::VectorXd& q_rad) const {
  const Se2Layer& l = layers.at(static_cast<std::size_t>(layer));
  WholeBodyState state;
  state.x_m = l.x_m;
  state.y_m = l.y_m;
  state.yaw_rad = l.yaw_rad;
  state.q_rad = q_rad;
  return state;
}

double TrapezoidArrivalTime(double s, double total, double rate_max, double accel_max) {
  // Rest-to-rest trapezoid: accelerate at accel_max to the peak rate, cruise, decelerate.
  // The peak is rate_max, or sqrt(accel_max * total) for a triangle (total < rate_max^2 / a).
  const double peak = std::min(rate_max, std::sqrt(accel_max * total));
  const double ramp_length = 0.5 * peak * peak / accel_max;  // s_a = v_p^2 / (2 a)
  const double ramp_time = peak / accel_max;
  const double cruise_length = total - 2.0 * ramp_length;
  const double total_time = 2.0 * ramp_time + std::max(cruise_length, 0.0) / peak;
  if (s <= 0.0 || total <= 0.0) return 0.0;
  if (s >= total) return total_time;
  if (s <= ramp_length) return std::sqrt(2.0 * s / accel_max);  // s = a t^2 / 2
  if (s <= total - ramp_length) return ramp_time + (s - ramp_length) / peak;
  return total_time - std::sqrt(2.0 * (total - s) / accel_max);  // mirror of the ramp-up
}

DiscreteSE2Path DiscreteSE2(const std::vector<Eigen::Vector2d>& waypoints_W_m, double start_yaw_rad,
                            double goal_yaw_rad, const BaseLimits& limits,
                            const DiscreteSE2Options& options, const DiscreteSE2Turns& turns) {
  Validate(waypoints_W_m, start_yaw_rad, goal_yaw_rad, limits, options);
  const std::vector<Eigen::Vector2d> runs = Simplify(waypoints_W_m, options);
  LayerBuilder builder(limits, options);
  builder.Start(runs.front(), start_yaw_rad);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    builder.TurnTo(Heading(runs[i - 1], runs[i]), i == 1 && turns.start_other_way);
    builder.DriveTo(runs[i]);
  }
  builder.TurnTo(goal_yaw_rad, turns.goal_other_way || (runs.size() == 1 && turns.start_other_way));
  return builder.Take();
}

double StartTurnRad(const DiscreteSE2Path& path) {
  const std::vector<Se2Layer>& layers = path.layers;
  std::size_t last = 0;
  while (last + 1 < layers.size() && layers[last + 1].turn_in_place) ++last;
  return layers.empty() ? 0.0 : layers[last].yaw_rad - layers.front().yaw_rad;
}

double GoalTurnRad(const DiscreteSE2Path& path) {
  const std::vector<Se2Layer>& layers = path.layers;
  if (layers.empty()) return 0.0;
  std::size_t first = layers.size() - 1;
  while (first > 0 && layers[first].turn_in_place) --first;
  return layers.back().yaw_rad - layers[first].yaw_rad;
}

}  // namespace topay
