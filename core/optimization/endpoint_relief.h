#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/robot/whole_body_state.h"

namespace topay {

class SamplePenalties;

/// Options of the endpoint relief (MakeEndpointRelief).
struct EndpointReliefOptions {
  /// Added to every positive clearance deficit (m): the endpoint then lies this far inside
  /// its relieved threshold, not on it (the smoothed penalty acts from the threshold on).
  /// Default 0: the endpoint lies on its relieved threshold, so samples near it must be at
  /// least as clear on the fields as it is. With 0.005 or 0.02 m the optimizer let an arm
  /// sphere approach a goal 3 mm from a floating cube closer than the goal itself, and the
  /// exact validator rejected it (tests/core/planner/close_quarters_test.cc).
  double slack_m = 0.0;
};

/// Throws std::invalid_argument unless slack_m is finite and >= 0.
void CheckEndpointReliefOptions(const EndpointReliefOptions& options);

/// How far an endpoint state falls short of the sample penalties' clearance thresholds
/// (eq. (13)'s r_thr with the penalty's factors and field margins), plus the slack where it
/// does: base = max(0, base threshold - field2(x, y)), sphere s = max(0, threshold_s -
/// field3(p_WS)), each + slack_m if > 0. Spheres the penalty does not check on the 3D field
/// (SpheresToCheckOnArmField) have deficit 0.
struct ClearanceDeficit {
  double base_m = 0.0;
  /// The base against the 2D field's primary band alone (SignedDistanceField::primary_band:
  /// the obstacles the base cylinder itself can touch), <= base_m; base_m for a field without
  /// a lowered band. Where the base's requirement is relieved, the primary band's is relieved
  /// by this much only, so a base leaving a table top's shadow keeps its margin to the legs.
  double base_primary_m = 0.0;
  Eigen::VectorXd spheres_m;  ///< One per RobotModel::spheres.

  bool IsZero() const { return base_m == 0.0 && (spheres_m.array() == 0.0).all(); }
  double max_sphere_m() const { return spheres_m.size() > 0 ? spheres_m.maxCoeff() : 0.0; }
};

/// The deficit of `state` against the thresholds `penalties` compares against (without any
/// tightening), on its fields.
ClearanceDeficit ComputeClearanceDeficit(const SamplePenalties& penalties,
                                         const WholeBodyState& state, double slack_m);

/// The ramp coordinate of a trajectory sample: u = (piece + local_fraction) / num_pieces, the
/// piece-index fraction (local_fraction = local time / piece duration in [0, 1]). It does not
/// depend on the durations as long as the sample's place within its piece is fixed (the
/// optimizer's samples: panel end l of K, local fraction l / K), so a relief at u is a
/// constant of the optimization and the penalty gradients stay exact.
inline double PieceFraction(int piece, double local_fraction, int num_pieces) {
  return (piece + local_fraction) / num_pieces;
}

/// The ramp weight at distance d (in u) from its endpoint for a ramp of extent f in (0, 1]
/// with a plateau p in (0, f] (default f / 2): 1 on [0, p], then a half cosine down to 0 at
/// f, 0 beyond. Continuous and non-increasing in d.
double ReliefRampWeight(double d, double f, double p);
inline double ReliefRampWeight(double d, double f) { return ReliefRampWeight(d, f, 0.5 * f); }

/// Clearance margins relaxed near a start and a goal that lie inside them (the front end
/// validated the first / last stretch of its path exactly rather than on the fields:
/// TrajectoryProblem::exact_prefix_states / exact_suffix_states). At ramp coordinate u
/// (PieceFraction) the relief of a part (base, sphere s) is
///   max(w_start(u) x deficit_start, w_goal(u) x deficit_goal),
/// w_start(u) = ReliefRampWeight(u, f_start, p_start), w_goal(u) = ReliefRampWeight(1 - u,
/// f_goal, p_goal);
/// the sample penalties compare against threshold (+ tightening) - relief, the optimizer's
/// field check against radius + margin - relief. Default-constructed: no relief (0
/// everywhere). Lookups are allocation-free.
class EndpointRelief {
 public:
  /// Both weights at one u (to look up several parts at one sample).
  struct Weights {
    double start = 0.0;
    double goal = 0.0;
  };

  EndpointRelief() = default;

  /// The start's (goal's) deficit, ramp extent f in (0, 1] and plateau p in (0, f] (NaN, the
  /// default: f / 2) (set again: replaced); throws std::invalid_argument for f outside
  /// (0, 1], p outside (0, f], a negative or non-finite deficit, or sphere counts that
  /// differ between the start and the goal.
  void SetStart(const ClearanceDeficit& deficit, double fraction,
                double plateau = std::numeric_limits<double>::quiet_NaN());
  void SetGoal(const ClearanceDeficit& deficit, double fraction,
               double plateau = std::numeric_limits<double>::quiet_NaN());

  /// No part is relieved anywhere (no endpoint set, or only zero deficits).
  bool empty() const { return !has_start_ && !has_goal_; }

  Weights WeightsAt(double u) const;
  double base_m(const Weights& w) const {
    return std::max(w.start * start_.base_m, w.goal * goal_.base_m);
  }
  double base_primary_m(const Weights& w) const {
    return std::max(w.start * start_.base_primary_m, w.goal * goal_.base_primary_m);
  }
  /// Sphere s (a RobotModel::spheres index); 0 where an endpoint has no deficit for it.
  double sphere_m(int s, const Weights& w) const {
    const double a = s < start_.spheres_m.size() ? w.start * start_.spheres_m(s) : 0.0;
    const double b = s < goal_.spheres_m.size() ? w.goal * goal_.spheres_m(s) : 0.0;
    return std::max(a, b);
  }
  double base_m(double u) const { return base_m(WeightsAt(u)); }
  double base_primary_m(double u) const { return base_primary_m(WeightsAt(u)); }
  double sphere_m(int s, double u) const { return sphere_m(s, WeightsAt(u)); }

  bool has_start() const { return has_start_; }
  bool has_goal() const { return has_goal_; }
  const ClearanceDeficit& start_deficit() const { return start_; }
  const ClearanceDeficit& goal_deficit() const { return goal_; }
  double start_fraction() const { return f_start_; }
  double goal_fraction() const { return f_goal_; }

  /// E.g. "start base 0.031 m, arm max 0.072 m over the first 18 % / goal base 0.000 m, arm
  /// max 0.050 m over the last 12 %" (only the endpoints with a deficit); "" if empty.
  std::string Describe() const;

 private:
  bool has_start_ = false;
  bool has_goal_ = false;
  ClearanceDeficit start_, goal_;
  double f_start_ = 0.0;
  double f_goal_ = 0.0;
  double p_start_ = 0.0;
  double p_goal_ = 0.0;
};

/// The ramp extents from the warm start's timing of the front-end path (WarmStart::
/// path_times_s, one time per path state) and its piece count M:
///   f_start = t(exact_prefix_states) / t(last) + 1 / M,
///   f_goal  = (t(last) - t(size - 1 - exact_suffix_states)) / t(last) + 1 / M,
/// state indices clamped to the path, clamped to (0, 1] (1 for a path that takes no time).
/// The warm start's pieces are equal and its waypoints at equal time fractions, so the
/// fraction of the path's time is the piece-index fraction of the path state; the extra piece
/// leaves room for the optimized durations to differ. Throws std::invalid_argument for an
/// empty path, M < 1 or a negative count.
double StartReliefFraction(const Eigen::VectorXd& path_times_s, int exact_prefix_states,
                           int num_pieces);
double GoalReliefFraction(const Eigen::VectorXd& path_times_s, int exact_suffix_states,
                          int num_pieces);

/// The relief of a problem: the start's deficit over f_start if exact_prefix_states > 0, the
/// goal's over f_goal if exact_suffix_states > 0; an endpoint whose deficit is zero is left
/// out. Both counts 0: an empty relief. An endpoint's deficit is the part-by-part maximum
/// over the stretch of the front-end path the front end validated exactly: `start` and
/// path_states[1 .. exact_prefix_states - 1]; path_states[n - exact_suffix_states .. n - 1]
/// (the last is the goal). So a start that the fields accept but whose way out they do not
/// (a pocket left under a table top) is relieved as much as that way out needs, and in full
/// over that stretch (plateau max(f / 2, f - 1 / M)), then down over one more piece. Throws
/// std::invalid_argument for bad options or inputs.
EndpointRelief MakeEndpointRelief(const SamplePenalties& penalties, const WholeBodyState& start,
                                  const std::vector<WholeBodyState>& path_states,
                                  const Eigen::VectorXd& path_times_s, int num_pieces,
                                  int exact_prefix_states, int exact_suffix_states,
                                  const EndpointReliefOptions& options = {});

}  // namespace topay
