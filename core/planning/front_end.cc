#include "core/planning/front_end.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include <tbb/task_arena.h>

#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/planning/base_reachable_region.h"
#include "core/planning/field_clearance.h"
#include "core/planning/parallel_acquisition.h"

namespace topay {
namespace {

using Clock = Stopwatch::Clock;

// Empty if `state` is usable, else what is wrong with it.
std::string CheckState(const WholeBodyState& state, int num_joints) {
  if (state.num_joints() != num_joints) {
    return "has " + std::to_string(state.num_joints()) + " joints, the robot " +
           std::to_string(num_joints);
  }
  if (!state.IsFinite()) return "contains NaN or infinity";
  return "";
}

// "n x message; m x other" over the failed jobs' distinct messages.
std::string SummariseJobFailures(const std::vector<ArmJobReport>& jobs) {
  std::vector<std::pair<std::string, int>> counts;
  for (const ArmJobReport& job : jobs) {
    auto it = std::find_if(counts.begin(), counts.end(),
                           [&job](const auto& c) { return c.first == job.message; });
    if (it == counts.end()) {
      counts.emplace_back(job.message, 1);
    } else {
      ++it->second;
    }
  }
  std::string out;
  for (const auto& [message, count] : counts) {
    if (!out.empty()) out += "; ";
    out += std::to_string(count) + " x " + message;
  }
  return out;
}

}  // namespace

struct FrontEnd::Arena {
  explicit Arena(int num_threads)
      : arena(num_threads > 0 ? num_threads : tbb::task_arena::automatic) {}
  tbb::task_arena arena;
};

struct FrontEnd::PlanContext {
  const WholeBodyState& start;
  const Eigen::Isometry3d& X_WE_target;
  const std::optional<WholeBodyState>& hint;
  std::stop_token stop;
  Clock::time_point t0;
  FrontEndResult* result;
};

FrontEnd::FrontEnd(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                   const SignedDistanceField3& arm_field, FrontEndOptions options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      options_((CheckFrontEndOptions(options), std::move(options))),
      validity_(kinematics, base_field, arm_field, options_.validity),
      ik_(kinematics, options_.ik),
      arena_(std::make_unique<Arena>(options_.num_threads)) {}

FrontEnd::~FrontEnd() = default;

FrontEndResult FrontEnd::Plan(const WholeBodyState& start, const Eigen::Isometry3d& X_WE_target,
                              const std::optional<WholeBodyState>& hint,
                              std::stop_token stop) const {
  const Stopwatch watch;
  const Clock::time_point t0 = watch.start();
  FrontEndResult result;
  auto fail = [&](FrontEndStatus status, std::string reason) {
    result.status = status;
    result.failure_reason = std::move(reason);
    result.stats.total_ms = watch.ElapsedMs();
    return result;
  };
  const int n = kinematics_.num_joints();
  std::string why = CheckState(start, n);
  if (!why.empty()) return fail(FrontEndStatus::kInvalidInput, "start state: " + why);
  if (!X_WE_target.matrix().allFinite()) {
    return fail(FrontEndStatus::kInvalidInput, "target pose X_WE: contains NaN or infinity");
  }
  if (hint) {
    why = CheckState(*hint, n);
    if (!why.empty()) return fail(FrontEndStatus::kInvalidInput, "goal hint: " + why);
  }
  WholeBodyValidityWorkspace workspace = validity_.MakeWorkspace();
  const ValidityFailure start_failure = validity_.Check(start, &workspace);
  if (start_failure != ValidityFailure::kNone) {
    return fail(FrontEndStatus::kStartInvalid,
                "start state: " + std::string(ToString(start_failure)));
  }
  if (stop.stop_requested()) return fail(FrontEndStatus::kCancelled, "cancelled before start");

  PlanContext context{start, X_WE_target, hint, stop, t0, &result};
  arena_->arena.execute([&] { PlanInArena(&context); });

  std::stable_sort(result.paths.begin(), result.paths.end(),
                   [](const FrontEndPath& a, const FrontEndPath& b) {
                     if (a.duration_s() != b.duration_s()) return a.duration_s() < b.duration_s();
                     return a.path.cost < b.path.cost;
                   });
  if (result.success()) {
    result.status = FrontEndStatus::kSuccess;
    result.failure_reason.clear();
  } else if (stop.stop_requested()) {
    result.status = FrontEndStatus::kCancelled;
    result.failure_reason = "cancelled (" + result.failure_reason + ")";
  }
  result.stats.total_ms = watch.ElapsedMs();
  return result;
}

void FrontEnd::PlanInArena(PlanContext* context) const {
  if (!FindGoals(context)) return;
  if (AttemptGoals(0, context)) return;
  FrontEndResult& result = *context->result;
  if (!options_.reachable_goal_search || result.status != FrontEndStatus::kNoBasePath ||
      context->stop.stop_requested()) {
    return;
  }
  const int first = static_cast<int>(result.goal_candidates.candidates.size());
  const FrontEndStatus status = result.status;
  const std::string reason = result.failure_reason;
  if (!FindReachableGoals(context)) {
    // Keep the first round's failure: it says why the candidates had no base path.
    result.status = status;
    result.failure_reason = reason + "; no goal the base can reach from the start (" +
                            result.failure_reason + ")";
    return;
  }
  AttemptGoals(first, context);
}

bool FrontEnd::AttemptGoals(int first, PlanContext* context) const {
  const int end = std::min<int>(first + options_.max_goal_attempts,
                                context->result->goal_candidates.candidates.size());
  for (int attempt = first; attempt < end; ++attempt) {
    if (context->stop.stop_requested()) return false;
    if (AttemptGoal(attempt, context)) return true;
  }
  return false;
}

bool FrontEnd::FindReachableGoals(PlanContext* context) const {
  FrontEndResult& result = *context->result;
  result.stats.used_reachable_goal_search = true;
  const Stopwatch watch;
  const double safe_distance_m =
      kinematics_.model().base_cylinder.radius_m +
      std::max(options_.fallback_base_clearance_m, validity_.base_margin_m());
  const BaseReachableRegion region(base_field_, {context->start.x_m, context->start.y_m},
                                   safe_distance_m);
  WholeBodyValidityWorkspace workspace = validity_.MakeWorkspace();
  const std::stop_token& stop = context->stop;
  const StateClearanceFn clearance = [&](const WholeBodyState& state) {
    if (stop.stop_requested()) return std::numeric_limits<double>::quiet_NaN();
    if (!region.Contains({state.x_m, state.y_m})) return -1.0;  // rejected like a collision
    return FieldClearance(validity_, base_field_, arm_field_, state, &workspace);
  };
  GoalCandidatesResult more = FindGoalCandidates(ik_, context->X_WE_target, context->start,
                                                 std::nullopt, clearance, options_.goal);
  result.stats.goal_ms += watch.ElapsedMs();
  if (!more.success()) {
    result.failure_reason = region.start_joins_grid() ? more.failure_reason
                                                      : "the start base position joins no "
                                                        "traversable cell of the 2D field";
    return false;
  }
  std::vector<GoalCandidate>& candidates = result.goal_candidates.candidates;
  candidates.insert(candidates.end(), more.candidates.begin(), more.candidates.end());
  result.stats.num_goal_candidates = static_cast<int>(candidates.size());
  return true;
}

bool FrontEnd::FindGoals(PlanContext* context) const {
  FrontEndResult& result = *context->result;
  const Stopwatch watch;
  WholeBodyValidityWorkspace workspace = validity_.MakeWorkspace();
  const std::stop_token& stop = context->stop;
  // Cancelled: every state is rejected (NaN), so the IK ends within its current DLS run.
  const StateClearanceFn clearance = [&](const WholeBodyState& state) {
    if (stop.stop_requested()) return std::numeric_limits<double>::quiet_NaN();
    return FieldClearance(validity_, base_field_, arm_field_, state, &workspace);
  };
  result.goal_candidates = FindGoalCandidates(ik_, context->X_WE_target, context->start,
                                              context->hint, clearance, options_.goal);
  result.stats.goal_ms += watch.ElapsedMs();
  result.stats.num_goal_candidates = static_cast<int>(result.goal_candidates.candidates.size());
  if (!result.goal_candidates.success()) {
    result.status = FrontEndStatus::kNoGoal;
    result.failure_reason = result.goal_candidates.failure_reason;
    return false;
  }
  return true;
}

bool FrontEnd::AttemptGoal(int attempt, PlanContext* context) const {
  FrontEndResult& result = *context->result;
  const GoalCandidate& goal = result.goal_candidates.candidates[attempt];
  const std::string where = "goal candidate " + std::to_string(attempt) + ": ";
  ++result.stats.num_goal_attempts;

  const TopologicalPathSearchResult search = SearchBasePaths(attempt, goal, context);
  if (!search.ok()) {
    result.status = FrontEndStatus::kNoBasePath;
    result.failure_reason = where + "base paths: " + search.reason;
    return false;
  }
  const std::vector<ArmJob> jobs = MakeArmJobs(attempt, goal, search, context);
  ParallelAcquisitionResult acquired = AcquireArmPaths(attempt, goal, jobs, context);
  const int job_offset = static_cast<int>(result.jobs.size());
  result.jobs.insert(result.jobs.end(), acquired.jobs.begin(), acquired.jobs.end());
  if (acquired.paths.empty()) {
    result.status = FrontEndStatus::kNoArmPath;
    result.failure_reason = where + "no arm path on " + std::to_string(jobs.size()) +
                            " base paths: " + SummariseJobFailures(acquired.jobs);
    return false;
  }
  for (FrontEndPath& path : acquired.paths) path.job += job_offset;
  result.paths = std::move(acquired.paths);
  result.goal = goal.state;
  result.stats.goal_from_hint = goal.from_hint;
  return true;
}

TopologicalPathSearchResult FrontEnd::SearchBasePaths(int attempt, const GoalCandidate& goal,
                                                      PlanContext* context) const {
  FrontEndResult& result = *context->result;
  FrontEndStats& stats = result.stats;
  const WholeBodyState& start = context->start;
  // Base paths, free at the validity's base margin at least.
  TopologicalPathSearchOptions topology = options_.topology;
  topology.base_radius_m = kinematics_.model().base_cylinder.radius_m;
  topology.clearance_m = std::max(topology.clearance_m, validity_.base_margin_m());
  topology.prm.seed = DeriveSeed(options_.seed, 2 * static_cast<std::uint64_t>(attempt));
  const Stopwatch watch;
  const Eigen::Vector2d start_W(start.x_m, start.y_m), goal_W(goal.state.x_m, goal.state.y_m);
  TopologicalPathSearchResult search =
      SearchTopologicalBasePaths(base_field_, start_W, goal_W, topology, context->stop);
  // Narrow passages, or a start or goal near an obstacle: search again at the smallest
  // clearance the validity allows.
  const double fallback_clearance_m =
      std::max(options_.fallback_base_clearance_m, validity_.base_margin_m());
  if (!search.ok() && search.status != TopologicalPathSearchResult::Status::kCancelled &&
      search.status != TopologicalPathSearchResult::Status::kInvalidInput &&
      fallback_clearance_m < topology.clearance_m) {
    topology.clearance_m = fallback_clearance_m;
    search = SearchTopologicalBasePaths(base_field_, start_W, goal_W, topology, context->stop);
    stats.used_fallback_base_clearance = true;
  }
  stats.topology_ms += watch.ElapsedMs();
  result.topology = search.stats;
  result.base_paths = search.paths;
  stats.num_prm_nodes = search.stats.num_guards + search.stats.num_connectors;
  stats.num_raw_paths = search.stats.num_raw_paths;
  stats.num_classes_kept = search.stats.num_classes_kept;
  stats.num_base_paths = static_cast<int>(search.paths.size());
  stats.jps_ok = search.stats.jps_ok;
  return search;
}

std::vector<ArmJob> FrontEnd::MakeArmJobs(int attempt, const GoalCandidate& goal,
                                          const TopologicalPathSearchResult& search,
                                          PlanContext* context) const {
  // One job per base path, shortest first.
  const Stopwatch watch;
  const BaseLimits limits = options_.base_limits.value_or(kinematics_.model().base_limits);
  std::vector<int> order(search.paths.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&search](int a, int b) {
    return search.paths[a].length_m < search.paths[b].length_m;
  });
  std::vector<ArmJob> jobs;
  for (int index : order) {
    ArmJob job;
    job.base_path = search.paths[index];
    job.base_path_index = index;
    job.seed = DeriveSeed(options_.seed, 1000 * static_cast<std::uint64_t>(attempt + 1) + index);
    try {
      job.base_sequence = DiscreteSE2(job.base_path.waypoints_W_m, context->start.yaw_rad,
                                      goal.state.yaw_rad, limits, options_.discretisation);
    } catch (const std::exception& e) {
      job.setup_error = std::string("DiscreteSE2: ") + e.what();
    }
    jobs.push_back(std::move(job));
  }
  context->result->stats.discretisation_ms += watch.ElapsedMs();
  return jobs;
}

ParallelAcquisitionResult FrontEnd::AcquireArmPaths(int attempt, const GoalCandidate& goal,
                                                    const std::vector<ArmJob>& jobs,
                                                    PlanContext* context) const {
  FrontEndStats& stats = context->result->stats;
  ParallelAcquisitionOptions acquisition;
  acquisition.rrt = options_.rrt;
  acquisition.improvement_window_s = options_.improvement_window_s;
  acquisition.budget_s = options_.acquisition_budget_s;
  acquisition.num_workers = tbb::this_task_arena::max_concurrency();
  acquisition.goal_attempt = attempt;
  ParallelAcquisitionResult acquired =
      AcquireWholeBodyPaths(jobs, context->start.q_rad, goal.state.q_rad, validity_, acquisition,
                            context->t0, context->stop);
  stats.acquisition_ms += acquired.wall_ms;
  stats.num_jobs += static_cast<int>(acquired.jobs.size());
  for (const ArmJobReport& job : acquired.jobs) {
    stats.rrt_iterations += job.stats.iterations;
    if (job.status == ArmRrtStarStatus::kSuccess) {
      ++stats.num_jobs_succeeded;
      stats.rrt_first_solution_ms =
          std::min(stats.rrt_first_solution_ms, 1e3 * job.stats.time_to_first_solution_s);
    }
  }
  stats.time_to_first_solution_ms =
      std::min(stats.time_to_first_solution_ms, acquired.first_success_ms);
  return acquired;
}

}  // namespace topay
