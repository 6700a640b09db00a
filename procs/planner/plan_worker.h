#pragma once
// The worker thread of topay-planner. It owns the planner's distance fields on the live map
// (PlannerWorld) and runs the plans, one at a time, so the two never compete for the two cores
// and a plan reads the fields in place (no copy):
//  - the map work the LCM thread hands over is folded into the world's pending changes;
//  - a plan first brings the fields up to date where it needs them (its fresh regions: its
//    start, the collisions it replans for; in tens of ms), then plans on them and validates on
//    the exact boxes of the very voxel states the fields were made from (a consistent world;
//    the LCM thread checks the result against the newest map before it goes out);
//  - between plans, the rest of the map reaches the fields a slice at a time once it is
//    field_update_period_s old (each slice ~50 ms, so a new plan waits at most one slice).
// A new plan request replaces a queued one and cancels a running one through the planner's
// stop token (cooperatively: the plan returns within a short step). The LCM thread never waits
// on it: Submit* only queue, TakeResult only takes.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include "core/planner/whole_body_plan_result.h"
#include "core/planner/whole_body_planner_options.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/trajectory_sample.h"
#include "procs/planner/map_intake.h"
#include "procs/planner/planner_world.h"
#include "procs/planner/standing_robot.h"

namespace topay::planner {

/// One plan to run.
struct PlanJob {
  std::int64_t job_id = 0;
  std::int64_t goal_id = 0;
  std::string trigger;                 ///< why it was asked for (logged, in the status)
  /// The start: state and rates (v, omega, a, beta, qd, qdd; all zero from rest).
  TrajectorySample start;
  bool from_rest = true;               ///< false: a moving start on the current trajectory
  /// The trajectory the start lies on (0: from rest or from the measured state): a result is
  /// published only if that trajectory is still the one under way at t0.
  std::int64_t on_trajectory_id = 0;
  std::int64_t t0_utime = 0;           ///< when the new trajectory starts (moving start)
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  std::optional<WholeBodyState> hint;
  double time_limit_s = 3.0;
  /// Run the base reachability certificate on the map first (a goal's first plan).
  bool certify_reachability = false;
  /// The map changes in these xy regions (world, m) reach the fields before the plan starts
  /// (PlannerWorld::FlushWithin); the rest as the background got to them.
  std::vector<Eigen::AlignedBox2d> fresh_regions_xy_W_m;
  /// The plan waits until its fields hold every map update submitted before it (a full
  /// flush: deterministic, but up to ~0.4 s more while the robot drives into unseen space).
  bool flush_all_map = false;
  /// From rest: the blocked voxels the arm at the start reaches into by at most this much (m)
  /// are left out of the exact check (ClearArmOverlaps; the base's all are).
  double clear_arm_overlap_m = 0.0;
  std::int64_t map_seq = 0;            ///< the newest map update the LCM thread had (the record)

  /// The robot at the start, as a plan from rest is validated without its own voxels.
  StandingRobot Standing() const { return {start.state, clear_arm_overlap_m}; }
};

/// A finished (or cancelled) job.
struct PlanJobOutcome {
  PlanJob job;
  WholeBodyPlanResult result;
  /// Set when the certificate proved the target unreachable (result then kFrontEndFailed
  /// with this reason, no plan run).
  bool certified_unreachable = false;
  std::int64_t fields_map_seq = 0;  ///< the newest map update wholly in the fields (may lag map_seq)
  std::int64_t changes_left = 0;    ///< map changes not yet in the fields when it planned
  double fresh_ms = 0.0;            ///< bringing the fields up to date in its fresh regions
  double setup_ms = 0.0;            ///< that, boxes, certificate and planner construction
};

/// Counters of the worker (for the heartbeat and the report).
struct PlanWorkerCounts {
  std::int64_t plans = 0;
  std::int64_t cancelled = 0;
  std::int64_t flushes = 0;          ///< background slices and full flushes
  std::int64_t map_errors = 0;
  double last_flush_ms = 0.0;
  double max_flush_ms = 0.0;
  double max_fresh_ms = 0.0;         ///< the longest update of a plan's fresh regions
  std::int64_t pending_changes = 0;  ///< map changes not yet in the fields
};

class PlanWorker {
 public:
  /// `kinematics` outlives the worker; `options` are the core planner's (time_limit_s is
  /// replaced by each job's). Background slices are `slice_m` wide and applied once
  /// `field_update_period_s` old.
  PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
             UnknownVoxelPolicy unknown, double field_update_period_s, double slice_m = 5.0);
  ~PlanWorker();  // cancels and joins
  PlanWorker(const PlanWorker&) = delete;
  PlanWorker& operator=(const PlanWorker&) = delete;

  void SubmitMap(MapWork work);
  /// Replaces a queued job; cancels the running one (its outcome still comes, kCancelled).
  void SubmitPlan(PlanJob job);
  /// Cancels the queued and the running job.
  void Cancel();
  /// The next finished job, if any (oldest first).
  std::optional<PlanJobOutcome> TakeResult();
  /// Waits up to timeout_s for the next finished job.
  std::optional<PlanJobOutcome> WaitForResult(double timeout_s);
  /// True while a job is queued or running.
  bool busy() const;
  PlanWorkerCounts counts() const;

 private:
  void Run(std::stop_token thread_stop);
  PlanJobOutcome Execute(const PlanJob& job, std::stop_token job_stop);
  // Applies the world's pending work the way `flush` does, counting it; false on bad map work.
  template <typename Flush>
  bool FlushCounted(Flush flush, MapFlushSummary* summary);
  void RecordFlush(const MapFlushSummary& summary, bool fresh);

  const Kinematics& kinematics_;
  WholeBodyPlannerOptions options_;
  UnknownVoxelPolicy unknown_;
  double field_update_period_s_;
  PlannerWorld world_;  // the worker thread's only

  mutable std::mutex mutex_;
  std::condition_variable_any wake_, results_ready_;
  std::deque<MapWork> maps_;
  std::optional<PlanJob> queued_;
  bool running_ = false;
  std::stop_source job_stop_;
  std::deque<PlanJobOutcome> results_;
  PlanWorkerCounts counts_;
  // Last: it starts after everything above exists.
  std::jthread thread_;
};

}  // namespace topay::planner
