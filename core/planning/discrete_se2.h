#pragma once

#include <Eigen/Core>
#include <numbers>
#include <vector>

#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of DiscreteSE2 (paper Algorithm 1, line "P_b <- DiscreteSE2(P_r, Delta l)").
struct DiscreteSE2Options {
  /// Delta l: largest distance (m) between consecutive base states along a straight segment;
  /// each segment of length D is split into ceil(D / delta_l_m) equal steps. Default: the
  /// reference implementation's 1.414 m (the authors' code).
  double delta_l_m = 1.414;
  /// Largest yaw change (rad) between consecutive turn-in-place states; a turn by |dyaw| is
  /// split into ceil(|dyaw| / max_turn_step_rad) equal steps.
  double max_turn_step_rad = std::numbers::pi / 4.0;
  /// Heading changes (rad) smaller than this are not turns: collinear segments merge into one
  /// straight run, and a start/goal yaw this close to the heading needs no turn.
  double min_turn_rad = 1e-6;
  /// Consecutive waypoints closer than this (m) are merged.
  double min_segment_m = 1e-6;
};

/// Throws std::invalid_argument naming the first option that is not positive and finite.
void CheckDiscreteSE2Options(const DiscreteSE2Options& options);

/// One base state of the discretised path: a layer of the arm's RRT* (paper Sec. III-A).
struct Se2Layer {
  double x_m = 0.0;
  double y_m = 0.0;
  /// Yaw, CONTINUOUS along the sequence (not wrapped): a turn from yaw a to yaw b goes
  /// linearly in yaw, so linear interpolation between adjacent layers is the base's motion.
  double yaw_rad = 0.0;
  double arc_length_m = 0.0;  ///< Distance driven from the first layer.
  /// Earliest arrival time (s) under the base limits: trapezoidal velocity profiles
  /// (v_max, a_max) along each straight run and (omega_max, beta_max) along each turn, from
  /// rest to rest (the base stops at every turn). time_s of the first layer = 0.
  double time_s = 0.0;
  /// time_s minus the previous layer's time_s (0 for the first layer): the shortest time in
  /// which the base can move from the previous layer to this one, used to clip joint steps
  /// (|dq_i| <= qd_max_i * step_time_s).
  double step_time_s = 0.0;
  /// True if this layer is reached from the previous one by turning in place (same x, y).
  bool turn_in_place = false;
};

/// The discrete SE(2) sequence P_b of one base path. Adjacent layers differ either by a
/// straight translation along the current yaw or by a turn in place, never both.
struct DiscreteSE2Path {
  std::vector<Se2Layer> layers;

  int num_layers() const { return static_cast<int>(layers.size()); }
  double total_time_s() const { return layers.empty() ? 0.0 : layers.back().time_s; }
  /// The whole-body state with the base of `layer` and joints q.
  WholeBodyState State(int layer, const Eigen::VectorXd& q_rad) const;
};

/// Which way the turns in place at the ends of a path go round (DiscreteSE2). Ours (finding 29,
/// its third case): a robot stopped with its arm held out over a table and its next path
/// starting behind it turns half a turn in place; the shorter way round may sweep the arm
/// through the table where the other way is clear, and which way is shorter flips with a few
/// milliradians of start yaw. The front end tries both (FrontEndOptions::other_way_turn_min_rad).
struct DiscreteSE2Turns {
  /// The turn at the start (from the start yaw to the first heading) goes the longer way
  /// round: 2 pi - |dyaw| the other way. No effect when that turn is below min_turn_rad.
  bool start_other_way = false;
  /// The same for the turn at the goal (to the goal yaw). A path of one waypoint has one turn,
  /// both at the start and at the goal: it goes the other way if either flag is set.
  bool goal_other_way = false;
};

/// DiscreteSE2 (paper Algorithm 1): turns a base polyline (first waypoint = start base
/// position, last = goal base position) into base states: a turn in place at the start from
/// start_yaw_rad to the first segment's heading, then along each straight run states at most
/// delta_l_m apart with yaw = the run's heading, a turn in place at each vertex to the next
/// heading, and a final turn to goal_yaw_rad. Turns take the shorter way round (|dyaw| <= pi)
/// unless `turns` says otherwise for the first or the last; the base always drives forward. The first layer's yaw equals start_yaw_rad; the last
/// layer's yaw equals goal_yaw_rad modulo 2 pi (continuous yaw, see Se2Layer).
/// A single waypoint (or all waypoints within min_segment_m) gives only the turn from the
/// start yaw to the goal yaw (one layer if those agree too).
/// Throws std::invalid_argument for no waypoints, a non-finite value, or non-positive
/// options or limits (v_max, a_max, omega_max, beta_max), naming the culprit.
DiscreteSE2Path DiscreteSE2(const std::vector<Eigen::Vector2d>& waypoints_W_m, double start_yaw_rad,
                            double goal_yaw_rad, const BaseLimits& limits,
                            const DiscreteSE2Options& options = {}, const DiscreteSE2Turns& turns = {});

/// The yaw change (rad, signed, continuous yaw) of the turn in place that begins the sequence
/// (its leading turn_in_place layers), or that ends it (the trailing ones; standing layers
/// add nothing). 0 when there is none.
double StartTurnRad(const DiscreteSE2Path& path);
double GoalTurnRad(const DiscreteSE2Path& path);

/// Time (s) at which a rest-to-rest trapezoidal profile with peak rate rate_max and
/// acceleration accel_max reaches position s along a run of length `total` (0 <= s <= total;
/// a triangle when the run is too short to reach rate_max).
double TrapezoidArrivalTime(double s, double total, double rate_max, double accel_max);

}  // namespace topay
