#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/planning/arm_rrt_star.h"
#include "core/planning/base_path.h"
#include "core/planning/discrete_se2.h"
#include "core/planning/front_end_result.h"
#include "core/planning/whole_body_validity.h"

namespace topay {

/// One arm search to run: a base path, its SE(2) layers and the RRT* seed.
struct ArmJob {
  BasePath base_path;
  int base_path_index = 0;
  DiscreteSE2Path base_sequence;
  std::uint64_t seed = 1;
  /// Non-empty if the job could not be set up (e.g. DiscreteSE2 rejected the path): it is
  /// reported as failed with this message and not run.
  std::string setup_error;
};

struct ParallelAcquisitionOptions {
  /// Options of every job's PlanArmRrtStar (the seed is the job's). With
  /// stop_at_first_solution = false (the default) each job runs the anytime search until the
  /// window below closes, its t_smax, or its cost bound. rrt.on_first_solution, if set, is
  /// still called (from the job's thread, concurrently with other jobs: it must be
  /// thread-safe).
  ArmRrtStarOptions rrt;
  /// Jobs still running this long (s) after the first solution found by any job are
  /// cancelled (+inf: never); a cancelled job that has a solution returns its best one.
  double improvement_window_s = 0.01;
  /// Jobs still running (or queued) this long (s) after the stage starts are cancelled.
  double budget_s = 0.5;
  /// Concurrent jobs (>= 1); the caller's TBB arena should have at least this many threads.
  int num_workers = 1;
  /// ArmJobReport::goal_attempt of the reports.
  int goal_attempt = 0;
};

struct ParallelAcquisitionResult {
  /// One per job, in job order.
  std::vector<ArmJobReport> jobs;
  /// Successful jobs' paths (base_path_index, homotopy_class filled), in job order.
  std::vector<FrontEndPath> paths;
  /// Since `t0`: when the first solution was found by any job (its on_first_solution call;
  /// +infinity if none).
  double first_success_ms = std::numeric_limits<double>::infinity();
  double wall_ms = 0.0;
  bool cancelled_by_caller = false;
};

/// The parallel stage of Algorithm 1 ("#pragma parallel for each P_r in P_b"): runs one
/// constrained bidirectional RRT* per job on the current TBB arena, num_workers at a time,
/// jobs taken in order (shortest base path first when the caller sorts them so). Cooperative
/// cancellation: every job polls one internal stop token, which fires when the caller's
/// `stop` fires (at once, through a std::stop_callback), at first solution of any job +
/// improvement_window_s (the jobs' ArmRrtStarOptions::on_first_solution moves the deadline),
/// or at the budget (a watcher thread, see StopDeadline). Jobs not yet
/// started when it fires are reported as not started. `t0` is the time origin of the
/// reported times. Never throws for a failing job (its report says why).
ParallelAcquisitionResult AcquireWholeBodyPaths(const std::vector<ArmJob>& jobs,
                                                const Eigen::VectorXd& q_start_rad,
                                                const Eigen::VectorXd& q_goal_rad,
                                                const WholeBodyValidity& validity,
                                                const ParallelAcquisitionOptions& options,
                                                std::chrono::steady_clock::time_point t0,
                                                std::stop_token stop = {});

}  // namespace topay
