#pragma once
// The planning thread of topay-planner: it owns the planner's world (fields and boxes from the
// live map, PlannerWorld), takes the map work the LCM thread hands it, updates the fields in
// batches (every field_update_period_s, and before every plan) and runs one plan at a time.
// A new plan request replaces a queued one and cancels a running one through the planner's
// stop token (cooperatively: the plan returns within a short step). The LCM thread never
// waits on it: Submit* only queue, TakeResult only takes.

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

#include <Eigen/Geometry>

#include "core/planner/whole_body_plan_result.h"
#include "core/planner/whole_body_planner_options.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/trajectory_sample.h"
#include "procs/planner/map_intake.h"
#include "procs/planner/planner_world.h"

namespace topay::planner {

/// One plan to run.
struct PlanJob {
  std::int64_t job_id = 0;
  std::int64_t goal_id = 0;
  std::string trigger;                 ///< why it was asked for (logged, in the status)
  /// The start: state and rates (v, omega, a, beta, qd, qdd; all zero from rest).
  TrajectorySample start;
  bool from_rest = true;               ///< false: a moving start on the current trajectory
  std::int64_t t0_utime = 0;           ///< when the new trajectory starts (moving start)
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  std::optional<WholeBodyState> hint;
  double time_limit_s = 3.0;
  /// Run the base reachability certificate on the map first (a goal's first plan).
  bool certify_reachability = false;
};

/// A finished (or cancelled) job.
struct PlanJobOutcome {
  PlanJob job;
  WholeBodyPlanResult result;
  /// Set when the certificate proved the target unreachable (result then kFrontEndFailed
  /// with this reason, no plan run).
  bool certified_unreachable = false;
  std::int64_t map_seq = 0;      ///< the map the plan ran on
  MapFlushSummary flush;         ///< the field update just before it
  double setup_ms = 0.0;         ///< boxes, certificate and planner construction
};

/// Counters of the planning thread (for the heartbeat and the report).
struct PlanWorkerCounts {
  std::int64_t plans = 0;
  std::int64_t cancelled = 0;
  std::int64_t flushes = 0;
  std::int64_t map_errors = 0;
  double last_flush_ms = 0.0;
  double max_flush_ms = 0.0;
};

class PlanWorker {
 public:
  /// `kinematics` outlives the worker; `options` are the core planner's (time_limit_s is
  /// replaced by each job's).
  PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
             UnknownVoxelPolicy unknown, double field_update_period_s);
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
  /// True while a job is queued or running.
  bool busy() const;
  PlanWorkerCounts counts() const;

 private:
  void Run(std::stop_token thread_stop);
  PlanJobOutcome Execute(const PlanJob& job, std::stop_token job_stop);
  void FlushMap();

  const Kinematics& kinematics_;
  WholeBodyPlannerOptions options_;
  double field_update_period_s_;
  PlannerWorld world_;  // the planning thread's only
  std::chrono::steady_clock::time_point last_flush_;

  mutable std::mutex mutex_;
  std::condition_variable_any wake_;
  std::deque<MapWork> maps_;
  std::optional<PlanJob> queued_;
  bool running_ = false;
  std::stop_source job_stop_;
  std::deque<PlanJobOutcome> results_;
  PlanWorkerCounts counts_;
  std::jthread thread_;  // last: starts after everything above exists
};

}  // namespace topay::planner
