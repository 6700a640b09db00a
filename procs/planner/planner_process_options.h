#pragma once
// topay-planner's own options (config/planner/planner.yaml): which robot and core planner
// configuration, how the live map is taken in, when to replan and when to stop. The core
// planner's options stay in their own file (config/planner/topay.yaml, core/io/planner_config.h).

#include <cstdint>
#include <optional>
#include <string>

#include "core/map/voxel_map_fields.h"
#include "core/planner/whole_body_planner_options.h"
#include "core/robot/robot_model.h"
#include "core/validate/trajectory_collision_scan.h"
#include "procs/planner/drifted_collision.h"
#include "procs/planner/trajectory_delivery.h"

namespace topay::planner {

/// How the planner takes in MAP_UPDATE.
struct PlannerMapOptions {
  /// How never-observed voxels count for the fields and the exact checks (docs/planner.md):
  /// "free" (default: plan through unseen space; every scan is checked against the trajectory
  /// ahead, so what appears there triggers a replan), "occupied", "occupied_in_base_bands".
  UnknownVoxelPolicy unknown = UnknownVoxelPolicy::kFree;
  /// Map changes reach the planner's distance fields in the background, a square slice of the
  /// map (slice_m wide) at a time, once the slice's oldest change is this old (s), while no
  /// plan runs: updating the whole map costs ~0.4 s while the robot drives into unseen space
  /// (docs/benchmarks.md), too much for every scan, and a slice ~50 ms. > 0.
  double field_update_period_s = 1.0;
  double slice_m = 5.0;
  /// Before a plan starts, the changes within fresh_radius_m (m, an xy square's half side) of
  /// its start and within fresh_collision_radius_m of each collision it replans for reach the
  /// fields at once (so a replan sees the obstacle that triggered it, in tens of ms); the rest
  /// may lag by field_update_period_s plus the slices' work. > 0.
  double fresh_radius_m = 2.0;
  double fresh_collision_radius_m = 1.5;
  /// A plan from rest (the robot waits for it) first brings every change into the fields.
  bool flush_all_from_rest = true;
  /// A plan from rest validates against the map without the blocked voxels the robot's base
  /// reaches into, and without those its arm spheres reach into by at most this much (m;
  /// ClearArmOverlaps: the sensed map standing out of a surface the arm stopped near). 0: the
  /// arm's overlaps all stay. >= 0.
  double start_arm_overlap_m = 0.03;
  /// The escape (finding 18): when a plan from rest fails because the standing arm is in the
  /// map's voxels deeper than start_arm_overlap_m, the goal's next plans from rest leave out the
  /// voxels it reaches into by at most this much (m) until one goes out, so the arm can be
  /// planned out of them. A voxel holds a surface up to a voxel (0.05 m) inside it, so a
  /// stopped arm 4.8 cm in voxels had not touched the table; deeper than this it may have.
  /// 0: no escape. >= start_arm_overlap_m (or 0).
  double start_arm_escape_overlap_m = 0.06;
  /// Added to the core planner's validator obstacle margin (m) when it validates a plan
  /// against the map's voxel boxes (the check of the trajectory ahead triggers at
  /// triggers.check_obstacle_margin_m). 0 by default: the fields do not carry a margin, and
  /// with 0.02 m most plans in the graph test were rejected by the validator by a fraction of
  /// a millimetre (as the sensed-map benchmark found for 0.05 m, docs/benchmarks.md). >= 0.
  double validator_margin_m = 0.0;
  /// The map is stale when its newest scan (MAP_UPDATE utime) is older than this (s): a robot
  /// moving on a trajectory is stopped (a stopping trajectory along it, as for a predicted
  /// collision) and no plan goes out until a fresh map comes; then the goal is planned again.
  /// The robot must not drive into space it no longer sees (scans or map updates lost, the
  /// mapper down or lagging): with the map frozen for 10 s the fault suite saw contacts. The
  /// mapper publishes every 10 Hz scan it integrates (at least 2 Hz). 0: never stale. >= 0.
  double stale_stop_s = 1.5;
  /// While the robot moves at speed v (its trajectory's at now, or the measured one, the
  /// larger), the map is stale already once older than stale_blind_distance_m / v, but never
  /// below stale_min_s: so many metres driven on a map that no longer updates, rather than so
  /// many seconds. At 1 m/s, 0.6 s instead of 1.5 s: a box that appeared as the map froze was
  /// hit 2 s later in the fault suite (docs/reliability.md, finding 30). stale_min_s stays
  /// above the mapper's 10 Hz updates with their latency (p95 31 ms, max 64 ms measured). 0:
  /// the fixed limit only. >= 0.
  double stale_blind_distance_m = 0.6;
  double stale_min_s = 0.6;
};

/// When a plan starts and how long it may take.
struct PlanTimingOptions {
  /// A plan from rest (no trajectory under way) may take this long (s); the core planner's
  /// time_limit_s is replaced by it. > 0.
  double from_rest_time_limit_s = 3.0;
  /// A replan while the robot moves starts at t0 = now + this budget (s) on the current
  /// trajectory, so it must be on the bus before t0: its time limit is the budget less
  /// publish_margin_s, and a result that comes after t0 is dropped. > publish_margin_s.
  double replan_budget_s = 1.0;
  double publish_margin_s = 0.05;
  /// A finished plan is checked against the newest map before it goes out (its fields may
  /// lag the map away from its start). If its first collision is more than this (s) from now,
  /// it goes out all the same and a replan starts at once (time enough to replan before any
  /// stop could be due: more than a stop's duration + stop.latency_s + stop.margin_s);
  /// sooner, it is dropped and replanned. > 0.
  double publish_collision_horizon_s = 5.0;
  /// Below this base speed (m/s) and yaw rate (rad/s) and every joint rate (rad/s) the robot
  /// counts as at rest (a plan from rest starts at its measured state).
  double rest_speed = 0.02;
  /// A failed replan is retried after this long (s) while the goal stands.
  double retry_period_s = 0.3;
  /// A robot moving off any trajectory of ours is planned from its measured state extrapolated
  /// to the plan's start t0 at its measured rates; a state older than this (s) when the plan is
  /// asked for (or stamped that far ahead) is not extrapolated: the plan waits, saying so (a
  /// stale ROBOT_STATE, replayed from a log, put a start's joint 1 at 17 rad). > 0.
  double max_state_age_s = 1.0;
  /// A goal fails (FAILED) after this many plans without a trajectory for it (a target the
  /// certificate proves unreachable, or bad input, at once): in a room seen for the first
  /// time a first plan is often overtaken by the next scan. >= 1.
  int first_plan_attempts = 3;
  /// A goal that had its trajectory fails (FAILED, "stuck: ...") after this many plans in a
  /// row from rest fail (e.g. stopped beside a new obstacle with no way on): the mission may
  /// resend it or give up, rather than the planner retrying for ever. >= 1.
  int max_failed_plans_from_rest = 10;
};

/// What makes the planner replan (each counted and logged with its reason).
struct ReplanTriggerOptions {
  /// The rest of the current trajectory is checked against every map update (exact, the
  /// map's blocked voxels as boxes; TrajectoryCollisionScanOptions: every 0.02 s, margin 0).
  TrajectoryCollisionScanOptions check;
  /// The robot has drifted from the trajectory (ROBOT_STATE against the trajectory at the
  /// state's time) by more than these: base position (m), yaw (rad), any joint (rad).
  double drift_position_m = 0.3;
  double drift_yaw_rad = 0.35;
  double drift_joint_rad = 0.35;
  /// Below those, a robot off the trajectory by more than drift_check's tolerances is checked
  /// against the map as it drifts (the trajectory ahead with its error carried along, with
  /// `check`'s sampling and margin): a collision replans from the drifted robot and stops it if
  /// no plan comes in time (procs/planner/drifted_collision.h, finding 34).
  DriftCheckOptions drift_check;
  /// Where a drift replan (and a replan for a drifted robot's collision) starts, at t0 a
  /// replanning budget ahead: true (YAML `drift_start: tracked`) where the tracker will have
  /// brought the robot by then (TrackedRobotPredictor: the tracker's NMPC, with
  /// tracker_config's options, in closed loop on an ideal plant from the measured state and
  /// rates); false (`carried`) the trajectory at t0 with the robot's error carried along
  /// unchanged (PredictDriftedStart). The tracker closes an error, so the carried start lay
  /// 0.26-0.3 m and 0.3 rad from where the robot then was (finding 34).
  bool drift_start_tracked = true;
  /// The map check looks at the blocked voxels within this distance (m) of the base axis
  /// along the rest of the trajectory: the robot's whole extent (arm stretched out over the
  /// base) with room to spare. > 0.
  double check_reach_m = 1.6;
};

/// The safe stop (a stopping trajectory along the current path).
struct SafeStopOptions {
  /// The stopping trajectory starts this long (s) after it is decided (its publication and
  /// the tracker's reaction).
  double latency_s = 0.1;
  /// It is published when the predicted collision is less than its own duration + latency +
  /// this margin (s) ahead and no new trajectory has come.
  double margin_s = 0.5;
  /// ... and also once a collision predicted within timing.publish_collision_horizon_s, or
  /// within grace_reach_m (m, straight line from where the robot is), has waited this long
  /// (s) for a new trajectory: the robot slows while the planner keeps trying (the plan in
  /// progress is replaced by one from the stopping trajectory). The graph's contract is a
  /// trajectory clear of a new obstacle within 300 ms of the scan (stack-design.md), and a
  /// replan on a long route may take a second. Farther collisions (a table found 10 m down
  /// a long route) wait for the replan: stopping for each would make the robot stop and go
  /// all the way through a room it is discovering. > 0.
  double replan_grace_s = 0.25;
  double grace_reach_m = 4.0;
  /// The stop for a stale map (map.stale_stop_s) brakes with this duration_per_rate_ratio
  /// (StoppingTrajectoryOptions, 3.0 for the other stops): the planner is blind then and
  /// anything may have appeared ahead, so the robot stops sooner and shorter (StopPlanner's
  /// test: 1.93 s and 0.78 m against 2.78 s and 1.06 m; a stop from 0.87 m/s lasted 3.4 s and
  /// ran 1.35 m into a box placed meanwhile: fault campaign finding 26). >= 1.5 (the time scaling's peak deceleration is 1.5 / ratio of each
  /// limit; lengthened when beyond them).
  double blind_duration_per_rate_ratio = 1.6;
};

/// Goals the planner refuses at once (PLANNER_STATUS FAILED with the reason).
struct GoalCheckOptions {
  /// A target nearer than this (m) to a blocked voxel's box counts as inside an obstacle
  /// (0: only a target inside one).
  double target_clearance_m = 0.0;
  /// A target inside a body the LiDAR saw only from outside (its voxel never observed, its
  /// unseen pocket near it and walled mostly by occupied voxels: core/map/unseen_pocket.h,
  /// finding 35) counts as inside an obstacle: refused at once, and a goal in hand fails (the
  /// robot stops) when the map comes to show it so. The pocket may reach this far (m) from the
  /// target along x and y; wider bodies are not recognised. 0: the check is off. >= 0.
  double unseen_pocket_reach_m = 1.0;
  /// ... and this share of its rim must be occupied, in [0, 1].
  double unseen_pocket_rim_share = 0.5;
  /// Run the base reachability certificate (core/planning/base_reachability.h) on the map's
  /// voxels: a target no base pose the robot can reach lets the arm touch fails at once.
  bool certify_reachability = true;
  /// A plan from rest is not made when the robot's end effector already is within these of the
  /// target (a safe stop that ended at the goal; a goal where the robot stands): the goal
  /// counts as reached (SUCCEEDED, "goal reached at rest ..."). Position (m) and the angle of
  /// R_WE,target^T R_WE (rad); >= 0 (0, 0: never).
  double reached_position_m = 0.02;
  double reached_orientation_rad = 0.05;
};

/// Deterministic mode (docs/planner.md#replay): the same message sequence gives the same
/// decisions and the same trajectories, whatever the machine's speed or the replay speed. For
/// replay and tests, not for the robot (a plan may take longer than the robot can wait):
///  - the core planner's options go through MakeDeterministic (work budgets below);
///  - the node's clock is message time (PlannerClock): every decision is taken when a message
///    is handled, at the newest utime of the messages handled so far;
///  - plans are synchronous: messages that come while a plan runs wait in the node's inbox
///    and are handled, in order, after its result (the LCM loop itself keeps reading the bus
///    and heartbeating);
///  - a plan's fields include every map update handled before it (the fields are updated only
///    when a plan asks), and every plan may take time_limit_s.
struct DeterministicModeOptions {
  bool enabled = false;  ///< off by default: the robot runs on the wall clock
  /// Visibility PRM samples of the front end (DeterministicBudgets::prm_samples). > 0.
  int prm_samples = 2000;
  /// Iterations of each arm RRT* job (DeterministicBudgets::rrt_iterations). > 0.
  std::int64_t rrt_iterations = 600;
  /// The outer bound of every plan (s), a safety only: a plan that reaches it fails and may not
  /// repeat exactly. Replaces timing.from_rest_time_limit_s and the replanning budget's
  /// limit. > 0.
  double time_limit_s = 30.0;
};

/// The limits plans keep to, against the robot's (config/robot/: what the tracker may command
/// and the CAN bridge enforces).
struct PlanLimitOptions {
  /// Plans (and stops) use this share of the robot's base and joint acceleration limits (base
  /// a_max and beta_max, each joint's qdd_max), so that a tracker behind its reference can
  /// still brake harder than planned: at the full limits a robot lagging at the start of a
  /// braking phase overshoots the trajectory's end (docs/reliability.md, finding 16). In (0, 1].
  double acceleration_share = 0.85;
};

struct PlannerProcessOptions {
  std::string source;       ///< The file these came from ("" = defaults).
  std::string robot_urdf;   ///< "" = the shipped robot (config/robot/topay_mm.urdf).
  std::string robot_yaml;   ///< "" = config/robot/topay_mm.yaml.
  std::string planner_config;  ///< Core planner YAML; "" = config/planner/topay.yaml.
  /// The tracker's YAML (its `nmpc` section: how the tracker closes an error, for
  /// triggers.drift_start tracked); "" = config/tracker/tracker.yaml.
  std::string tracker_config;
  PlannerMapOptions map;
  PlanTimingOptions timing;
  /// The newest TRAJECTORY sent again until the tracker reports it (`delivery`:
  /// resend_period_s 0.1 s, give_up_s 2 s after its start; trajectory_delivery.h).
  TrajectoryDeliveryOptions delivery;
  ReplanTriggerOptions triggers;
  SafeStopOptions stop;
  GoalCheckOptions goals;
  PlanLimitOptions limits;
  DeterministicModeOptions deterministic;
  /// PLANNER_STATUS is sent on every change and at least this often (s). > 0.
  double status_period_s = 1.0;
};

/// Loads options from YAML (every key optional, relative paths from the file's folder).
/// Throws ConfigError naming the file and the dotted field for an unreadable file, an
/// unknown key or a value out of range.
PlannerProcessOptions LoadPlannerProcessOptions(const std::string& path);

/// Throws ConfigError (source `source`) for the first value out of range.
void CheckPlannerProcessOptions(const PlannerProcessOptions& options, const std::string& source);

/// The core planner's options as this process runs them: map.validator_margin_m added to the
/// validator's obstacle margin; in deterministic mode, MakeDeterministic with the section's
/// budgets and its time limit.
void AdaptPlannerOptions(const PlannerProcessOptions& options, WholeBodyPlannerOptions* planner);

/// The robot's limits as plans keep to them: limits.acceleration_share of the base and joint
/// acceleration limits, in `model` (what the planner's kinematics and stops read) and in
/// planner->base_limits (set to the model's first if absent).
void ApplyPlanLimits(const PlannerProcessOptions& options, RobotModel* model, WholeBodyPlannerOptions* planner);

/// How often the field thread updates the fields by itself (s): map.field_update_period_s; in
/// deterministic mode never (only when a plan asks, so that the batches follow the messages
/// and not the thread's timing).
double FieldUpdatePeriod(const PlannerProcessOptions& options);

/// "free", "occupied", "occupied_in_base_bands" <-> the policy (nullopt for another name).
std::optional<UnknownVoxelPolicy> ParseUnknownVoxelPolicy(const std::string& name);
const char* ToString(UnknownVoxelPolicy policy);

}  // namespace topay::planner
