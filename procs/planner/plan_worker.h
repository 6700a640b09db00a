#pragma once
// The two worker threads of topay-planner. The field thread owns the planner's distance fields
// on the live map (PlannerWorld): it takes the map work the LCM thread hands it, updates the
// fields in batches (every field_update_period_s, or at once when a plan asks for it) and
// publishes each result as an immutable snapshot. The planning thread runs one plan at a
// time on the newest snapshot of the fields and on the exact boxes of the newest map states
// (given with the job, so a plan never waits for a field update: its own validator sees every
// voxel the LCM thread had). A new plan request replaces a queued one and cancels a running
// one through the planner's stop token (cooperatively: the plan returns within a short step).
// The LCM thread never waits on them: Submit* only queue, TakeResult only takes.

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
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include <memory>
#include <vector>
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
  /// The map as the LCM thread holds it when the plan is asked for (null: no map yet): the
  /// plan's exact boxes (its validator, the certificate) come from these states.
  std::shared_ptr<const std::vector<std::uint8_t>> map_states;
  GridGeometry3 map_geometry;
  std::int64_t map_seq = 0;
  /// The plan waits until its fields include every map update submitted before it (a field
  /// snapshot with map_seq >= this job's map_seq), asking the field thread to update at once,
  /// instead of planning on the newest snapshot (deterministic mode: the fields then depend on
  /// the messages, not on the field thread's timing).
  bool flush_all_map = false;
};

/// The planner's fields after one update, shared read-only with the plans that use them.
struct FieldSnapshot {
  SignedDistanceField2 base_field;
  SignedDistanceField3 arm_field;
  std::int64_t map_seq = 0;  ///< the last map update in them
};

/// A finished (or cancelled) job.
struct PlanJobOutcome {
  PlanJob job;
  WholeBodyPlanResult result;
  /// Set when the certificate proved the target unreachable (result then kFrontEndFailed
  /// with this reason, no plan run).
  bool certified_unreachable = false;
  std::int64_t fields_map_seq = 0;  ///< the map update the fields had (may lag map_seq)
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
  /// replaced by each job's). A plan waits for the first field snapshot at most
  /// first_fields_wait_s of its time limit.
  PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
             UnknownVoxelPolicy unknown, double field_update_period_s);
  ~PlanWorker();  // cancels and joins
  PlanWorker(const PlanWorker&) = delete;
  PlanWorker& operator=(const PlanWorker&) = delete;

  void SubmitMap(MapWork work);
  /// Asks the field thread to apply what it has now rather than at its next period.
  void UpdateFieldsSoon();
  /// Replaces a queued job; cancels the running one (its outcome still comes, kCancelled).
  void SubmitPlan(PlanJob job);
  /// Cancels the queued and the running job.
  void Cancel();
  /// The next finished job, if any (oldest first).
  std::optional<PlanJobOutcome> TakeResult();
  /// Like TakeResult, but blocks up to timeout_s until a result is there.
  std::optional<PlanJobOutcome> WaitForResult(double timeout_s);
  /// True while a job is queued or running.
  bool busy() const;
  PlanWorkerCounts counts() const;

 private:
  void RunPlans(std::stop_token thread_stop);
  void RunFields(std::stop_token thread_stop);
  PlanJobOutcome Execute(const PlanJob& job, std::stop_token job_stop);
  // The newest field snapshot, waiting for the first one until `deadline` (null: none yet).
  std::shared_ptr<const FieldSnapshot> Fields(std::chrono::steady_clock::time_point deadline,
                                              std::stop_token stop);
  void FlushMap();
  // The first snapshot whose map_seq >= `map_seq`, asking the field thread to update at once,
  // waiting until `deadline` (null: none by then).
  std::shared_ptr<const FieldSnapshot> FieldsWithMap(std::int64_t map_seq,
                                                     std::chrono::steady_clock::time_point deadline,
                                                     std::stop_token stop);

  const Kinematics& kinematics_;
  WholeBodyPlannerOptions options_;
  UnknownVoxelPolicy unknown_;
  double field_update_period_s_;
  PlannerWorld world_;  // the field thread's only

  mutable std::mutex mutex_;
  std::condition_variable_any wake_plans_, wake_fields_, fields_ready_, result_ready_;
  std::deque<MapWork> maps_;
  bool fields_soon_ = false;
  std::shared_ptr<const FieldSnapshot> fields_;
  std::optional<PlanJob> queued_;
  bool running_ = false;
  std::stop_source job_stop_;
  std::deque<PlanJobOutcome> results_;
  PlanWorkerCounts counts_;
  // Last: they start after everything above exists.
  std::jthread field_thread_;
  std::jthread plan_thread_;
};

}  // namespace topay::planner
