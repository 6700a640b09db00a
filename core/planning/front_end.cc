#include "core/planning/front_end.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include <tbb/task_arena.h>

#include "core/collision/start_target_diagnosis.h"
#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/planning/base_escape.h"
#include "core/planning/base_free_space.h"
#include "core/planning/base_reachable_region.h"
#include "core/planning/goal_clearance.h"
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

// The IK options of the goal search's second round.
WholeBodyIkOptions RetryIkOptions(const FrontEndOptions& o) {
  WholeBodyIkOptions ik = o.ik;
  const GoalRetryOptions& retry = o.goal_retry;
  ik.max_base_candidates = std::max(ik.max_base_candidates, retry.max_base_candidates);
  ik.restarts_per_base = std::max(ik.restarts_per_base, retry.restarts_per_base);
  ik.time_budget_s = std::max(ik.time_budget_s, retry.time_budget_s);
  ik.max_total_iterations = std::max(ik.max_total_iterations, retry.max_total_iterations);
  ik.seed = DeriveSeed(o.ik.seed, 1);  // other base poses and restarts than the first round
  return ik;
}

Eigen::Vector2d BaseOf(const WholeBodyState& state) { return {state.x_m, state.y_m}; }

// 1 + the index of the last of the first states within the zone around `centre` (from the
// front, or from the back) that the fields reject, or that ends an edge (interpolated as the
// arm search checks it) along which they reject a state; 0 if none. A tight start's way out
// may lie between two path states the fields accept.
int CountRejectedInZone(const WholeBodyValidity& validity, const std::vector<WholeBodyState>& states,
                        const Eigen::Vector2d& centre, bool from_back) {
  WholeBodyValidityWorkspace workspace = validity.MakeWorkspace();
  const double radius_m = validity.exact_zones().options.radius_m;
  const int n = static_cast<int>(states.size());
  const auto at = [&](int k) -> const WholeBodyState& { return states[from_back ? n - 1 - k : k]; };
  const auto rejected = [&](const WholeBodyState& state) {
    return validity.CheckOnFields(state, &workspace) != ValidityFailure::kNone;
  };
  WholeBodyState between;
  int count = 0;
  for (int k = 0; k < n; ++k) {
    if ((BaseOf(at(k)) - centre).norm() > radius_m) break;
    bool any = rejected(at(k));
    if (k > 0) {
      const int steps = validity.EdgeSteps(at(k - 1), at(k));
      for (int i = 1; i < steps && !any; ++i) {
        WholeBodyValidity::Interpolate(at(k - 1), at(k), static_cast<double>(i) / steps, &between);
        any = rejected(between);
      }
    }
    if (any) count = k + 1;
  }
  return count;
}

// Where the base path search starts or ends for an end: its escape's exit, or its base.
Eigen::Vector2d SearchEndOf(const std::optional<BaseEscape>& escape,
                            const WholeBodyState& state) {
  return escape ? escape->exit() : BaseOf(state);
}

// An escape route for `state` (FindBaseEscape); with a region, out of a pocket into it.
using EscapeFinder = std::function<std::optional<BaseEscape>(const WholeBodyState& state,
                                                             const BaseReachableRegion* region)>;

// After a failed base search: the goal, else the start, in a pocket the other end's region
// (from its escape's exit, if any) does not reach gets a route into that region, which
// replaces its escape. False if neither has one. Only an end in an exact zone can leave a
// pocket, so the other end's region (a flood fill of the 2D grid) is built for it alone.
bool LeavePocket(const SignedDistanceField2& field, double safe_distance_m,
                 const ExactZones& zones, const EscapeFinder& escape,
                 const WholeBodyState& start, const WholeBodyState& goal,
                 std::optional<BaseEscape>* start_escape,
                 std::optional<BaseEscape>* goal_escape) {
  // `end` leaves its pocket for the region of `other` (searched from `other_escape`'s exit).
  const auto leave = [&](const WholeBodyState& end, const WholeBodyState& other,
                         const std::optional<BaseEscape>& other_escape,
                         std::optional<BaseEscape>* end_escape) {
    if (!zones.Contains(BaseOf(end))) return false;
    const BaseReachableRegion region(field, SearchEndOf(other_escape, other), safe_distance_m);
    if (!region.start_joins_grid()) return false;
    std::optional<BaseEscape> out = escape(end, &region);
    if (!out) return false;
    *end_escape = std::move(out);
    return true;
  };
  return leave(goal, start, *start_escape, goal_escape) ||
         leave(start, goal, *goal_escape, start_escape);
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
  /// Set if the fields reject the start but the exact scene accepts it (CheckStart).
  std::optional<Eigen::Vector2d> start_zone_W;
};

FrontEnd::FrontEnd(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                   const SignedDistanceField3& arm_field, FrontEndOptions options,
                   const SceneClearanceChecker* exact)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      options_((CheckFrontEndOptions(options), std::move(options))),
      validity_(kinematics, base_field, arm_field, options_.validity),
      ik_(kinematics, options_.ik),
      ik_retry_(kinematics, RetryIkOptions(options_)),
      exact_(exact),
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
  PlanContext context{start, X_WE_target, hint, stop, t0, &result, std::nullopt};
  why = CheckStart(&context);
  if (!why.empty()) return fail(FrontEndStatus::kStartInvalid, "start state: " + why);
  if (stop.stop_requested()) return fail(FrontEndStatus::kCancelled, "cancelled before start");

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

std::string FrontEnd::CheckStart(PlanContext* context) const {
  const WholeBodyState& start = context->start;
  WholeBodyValidityWorkspace workspace = validity_.MakeWorkspace();
  const ValidityFailure failure = validity_.Check(start, &workspace);
  if (failure == ValidityFailure::kNone) {
    // Valid on the fields but closer to an obstacle than the base path search keeps: its way
    // out may lead through space only the exact scene accepts (under a table top).
    if (exact_ != nullptr && BaseIsTight(start)) context->start_zone_W = BaseOf(start);
    return "";
  }
  if (exact_ == nullptr ||
      (failure != ValidityFailure::kBaseCollision && failure != ValidityFailure::kArmCollision)) {
    return std::string(ToString(failure));
  }
  // The fields are conservative: the exact scene decides.
  const ExactZones zone{exact_, options_.exact_zones, {BaseOf(start)}};
  if (validity_.WithExactZones(zone).Check(start, &workspace) == ValidityFailure::kNone) {
    context->start_zone_W = BaseOf(start);
    context->result->stats.start_in_exact_zone = true;
    return "";
  }
  StartDiagnosisOptions diagnosis;
  diagnosis.obstacle_margin_m = options_.exact_zones.obstacle_margin_m;
  diagnosis.self_margin_m = std::max(options_.exact_zones.self_margin_m, options_.validity.self_margin_m);
  const auto why = DiagnoseStartState(kinematics_, exact_->scene(), start, diagnosis);
  return why ? *why : std::string(ToString(ValidityFailure::kExactCollision));
}

GoalCandidatesResult FrontEnd::SearchGoals(
    const WholeBodyState* hint, const std::function<bool(const WholeBodyState&)>& admit,
    PlanContext* context) const {
  FrontEndStats& stats = context->result->stats;
  const Stopwatch watch;
  GoalClearance goal_clearance(validity_, base_field_, arm_field_, exact_, options_.exact_zones);
  const std::stop_token& stop = context->stop;
  // Cancelled: every state is rejected (NaN), so the IK ends within its current DLS run.
  const StateClearanceFn clearance = [&](const WholeBodyState& state) {
    if (stop.stop_requested()) return std::numeric_limits<double>::quiet_NaN();
    if (admit && !admit(state)) return -1.0;  // rejected like a collision
    return goal_clearance(state);
  };
  const std::optional<WholeBodyState> hint_state =
      hint ? std::optional<WholeBodyState>(*hint) : std::nullopt;
  GoalCandidatesResult found = FindGoalCandidates(ik_, context->X_WE_target, context->start,
                                                  hint_state, clearance, options_.goal);
  if (!found.success() && options_.goal_retry.enabled && !stop.stop_requested()) {
    stats.used_goal_retry = true;
    GoalCandidatesResult again = FindGoalCandidates(ik_retry_, context->X_WE_target,
                                                    context->start, hint_state, clearance,
                                                    options_.goal);
    again.time_s += found.time_s;
    if (!again.success()) {
      again.failure_reason = found.failure_reason + "; again with more base poses and "
                             "restarts: " + again.failure_reason;
    }
    found = std::move(again);
  }
  const GoalClearanceTally& tally = goal_clearance.tally();
  if (!found.success()) found.failure_reason += " (" + tally.Describe() + ")";
  GoalClearanceTally& sum = stats.goal_clearance;
  sum.field_accepted += tally.field_accepted;
  sum.exact_accepted += tally.exact_accepted;
  sum.joint_limit += tally.joint_limit;
  sum.self_collision += tally.self_collision;
  sum.exact_base += tally.exact_base;
  sum.exact_arm += tally.exact_arm;
  sum.field_only += tally.field_only;
  stats.goal_ms += watch.ElapsedMs();
  return found;
}

bool FrontEnd::FindReachableGoals(PlanContext* context) const {
  FrontEndResult& result = *context->result;
  result.stats.used_reachable_goal_search = true;
  const double safe_distance_m =
      kinematics_.model().base_cylinder.radius_m +
      std::max(options_.fallback_base_clearance_m, validity_.base_margin_m());
  Eigen::Vector2d seed_W = BaseOf(context->start);
  if (context->start_zone_W) {  // a start the field rejects: from its escape position
    const BaseFreeSpace free_space(base_field_, safe_distance_m);
    const WholeBodyValidity validity =
        validity_.WithExactZones({exact_, options_.exact_zones, {*context->start_zone_W}});
    if (!free_space.IsFree(seed_W)) {
      const std::optional<BaseEscape> escape = FindBaseEscape(
          free_space, validity, seed_W, context->start.yaw_rad, options_.base_escape);
      if (escape) seed_W = escape->exit();
    }
  }
  const BaseReachableRegion region(base_field_, seed_W, safe_distance_m);
  GoalCandidatesResult more = SearchGoals(
      nullptr, [&region](const WholeBodyState& state) { return region.Contains(BaseOf(state)); },
      context);
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
  result.goal_candidates =
      SearchGoals(context->hint ? &*context->hint : nullptr, nullptr, context);
  result.stats.num_goal_candidates = static_cast<int>(result.goal_candidates.candidates.size());
  if (!result.goal_candidates.success()) {
    result.status = FrontEndStatus::kNoGoal;
    result.failure_reason = result.goal_candidates.failure_reason;
    return false;
  }
  return true;
}

bool FrontEnd::BaseIsTight(const WholeBodyState& state) const {
  const double search_clearance_m =
      std::max(options_.topology.clearance_m, validity_.base_margin_m());
  return !(base_field_.Distance(BaseOf(state)) >=
           kinematics_.model().base_cylinder.radius_m + search_clearance_m);
}

WholeBodyValidity FrontEnd::AttemptValidity(const GoalCandidate& goal,
                                            PlanContext* context) const {
  ExactZones zones{exact_, options_.exact_zones, {}};
  if (context->start_zone_W) zones.centres_W_m.push_back(*context->start_zone_W);
  if (exact_ != nullptr) {
    WholeBodyValidityWorkspace workspace = validity_.MakeWorkspace();
    if (validity_.CheckOnFields(goal.state, &workspace) != ValidityFailure::kNone ||
        BaseIsTight(goal.state)) {
      zones.centres_W_m.push_back(BaseOf(goal.state));
    }
  }
  return validity_.WithExactZones(std::move(zones));
}

bool FrontEnd::AttemptGoal(int attempt, PlanContext* context) const {
  FrontEndResult& result = *context->result;
  const GoalCandidate& goal = result.goal_candidates.candidates[attempt];
  const std::string where = "goal candidate " + std::to_string(attempt) + ": ";
  ++result.stats.num_goal_attempts;

  const WholeBodyValidity validity = AttemptValidity(goal, context);
  const TopologicalPathSearchResult search = SearchBasePaths(attempt, goal, validity, context);
  if (!search.ok()) {
    result.status = FrontEndStatus::kNoBasePath;
    result.failure_reason = where + "base paths: " + search.reason;
    return false;
  }
  const std::vector<ArmJob> jobs = MakeArmJobs(attempt, goal, search, context);
  ParallelAcquisitionResult acquired = AcquireArmPaths(attempt, goal, jobs, validity, context);
  const int job_offset = static_cast<int>(result.jobs.size());
  result.jobs.insert(result.jobs.end(), acquired.jobs.begin(), acquired.jobs.end());
  if (acquired.paths.empty()) {
    result.status = FrontEndStatus::kNoArmPath;
    result.failure_reason = where + "no arm path on " + std::to_string(jobs.size()) +
                            " base paths: " + SummariseJobFailures(acquired.jobs);
    return false;
  }
  // AttemptValidity added the goal's zone after the start's.
  const bool goal_zone = validity.exact_zones().centres_W_m.size() >
                         (context->start_zone_W ? 1u : 0u);
  for (FrontEndPath& path : acquired.paths) {
    path.job += job_offset;
    if (context->start_zone_W) {
      path.exact_prefix_states =
          CountRejectedInZone(validity, path.path.states, *context->start_zone_W, false);
    }
    if (goal_zone) {
      path.exact_suffix_states =
          CountRejectedInZone(validity, path.path.states, BaseOf(goal.state), true);
    }
  }
  result.stats.goal_in_exact_zone = goal_zone;
  result.paths = std::move(acquired.paths);
  result.goal = goal.state;
  result.stats.goal_from_hint = goal.from_hint;
  return true;
}

TopologicalPathSearchResult FrontEnd::SearchBasePaths(int attempt, const GoalCandidate& goal,
                                                      const WholeBodyValidity& validity,
                                                      PlanContext* context) const {
  FrontEndResult& result = *context->result;
  FrontEndStats& stats = result.stats;
  if (goal.base_stays) {  // no search: the base stands still (a standing goal candidate)
    TopologicalPathSearchResult stays;
    stays.status = TopologicalPathSearchResult::Status::kSuccess;
    BasePath path;
    path.waypoints_W_m = {BaseOf(context->start), BaseOf(goal.state)};
    path.source = BasePathSource::kStanding;
    stays.paths.push_back(std::move(path));
    result.base_paths = stays.paths;
    stats.num_base_paths = 1;
    stats.standing_base_path = true;
    return stays;
  }
  // Base paths, free at the validity's base margin at least.
  TopologicalPathSearchOptions topology = options_.topology;
  topology.base_radius_m = kinematics_.model().base_cylinder.radius_m;
  topology.clearance_m = std::max(topology.clearance_m, validity_.base_margin_m());
  topology.prm.seed = DeriveSeed(options_.seed, 2 * static_cast<std::uint64_t>(attempt));
  const Stopwatch watch;
  TopologicalPathSearchResult search =
      SearchBasePathsAt(topology.clearance_m, goal, topology, validity, context);
  // Narrow passages, or a start or goal near an obstacle: search again at the smallest
  // clearance the validity allows.
  const double fallback_clearance_m =
      std::max(options_.fallback_base_clearance_m, validity_.base_margin_m());
  if (!search.ok() && search.status != TopologicalPathSearchResult::Status::kCancelled &&
      search.status != TopologicalPathSearchResult::Status::kInvalidInput &&
      fallback_clearance_m < topology.clearance_m) {
    search = SearchBasePathsAt(fallback_clearance_m, goal, topology, validity, context);
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

TopologicalPathSearchResult FrontEnd::SearchBasePathsAt(
    double clearance_m, const GoalCandidate& goal, const TopologicalPathSearchOptions& topology,
    const WholeBodyValidity& validity, PlanContext* context) const {
  TopologicalPathSearchOptions options = topology;
  options.clearance_m = clearance_m;
  const double safe_distance_m = options.base_radius_m + clearance_m;
  const BaseFreeSpace free_space(base_field_, safe_distance_m);
  // A start or goal in an exact zone that the field rejects at this clearance: search from
  // (to) the exit of its escape route (FindBaseEscape). With a region: an end the field
  // accepts but that lies outside the region the other end reaches (a pocket shut by table
  // tops' shadows) leaves the pocket for the region by an exactly checked route.
  const auto escape = [&](const WholeBodyState& state,
                          const BaseReachableRegion* region) -> std::optional<BaseEscape> {
    const Eigen::Vector2d p_W = BaseOf(state);
    if (!validity.exact_zones().Contains(p_W)) return std::nullopt;
    if (region == nullptr ? free_space.IsFree(p_W) : region->Contains(p_W)) return std::nullopt;
    return FindBaseEscape(free_space, validity, p_W, state.yaw_rad, options_.base_escape, region);
  };
  std::optional<BaseEscape> start_escape = escape(context->start, nullptr);
  std::optional<BaseEscape> goal_escape = escape(goal.state, nullptr);
  const auto search_base_paths = [&] {
    return SearchTopologicalBasePaths(base_field_, SearchEndOf(start_escape, context->start),
                                      SearchEndOf(goal_escape, goal.state), options,
                                      context->stop);
  };
  TopologicalPathSearchResult search = search_base_paths();
  if (!search.ok() && !context->stop.stop_requested() &&
      LeavePocket(base_field_, safe_distance_m, validity.exact_zones(), escape, context->start,
                  goal.state, &start_escape, &goal_escape)) {
    search = search_base_paths();
  }
  const bool start_escaped = start_escape.has_value(), goal_escaped = goal_escape.has_value();
  if (!search.ok() || !(start_escaped || goal_escaped)) return search;
  for (BasePath& path : search.paths) {
    // start, the start's route up to (not including) its exit, the searched path (exit to
    // exit), the goal's route back from (not including) its exit, goal.
    std::vector<Eigen::Vector2d> waypoints;
    if (start_escaped) {
      waypoints.push_back(BaseOf(context->start));
      const std::vector<Eigen::Vector2d>& route = start_escape->waypoints_W_m;
      waypoints.insert(waypoints.end(), route.begin(), route.end() - 1);
    }
    waypoints.insert(waypoints.end(), path.waypoints_W_m.begin(), path.waypoints_W_m.end());
    if (goal_escaped) {
      const std::vector<Eigen::Vector2d>& route = goal_escape->waypoints_W_m;
      waypoints.insert(waypoints.end(), route.rbegin() + 1, route.rend());
      waypoints.push_back(BaseOf(goal.state));
    }
    path.waypoints_W_m = std::move(waypoints);
    path.length_m = PolylineLength(path.waypoints_W_m);
  }
  FrontEndStats& stats = context->result->stats;
  stats.start_base_escape = stats.start_base_escape || start_escaped;
  stats.goal_base_escape = goal_escaped;
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
    job.setup_error = Discretise(job.base_path, goal, limits, {}, *context, &job.base_sequence);
    // The same base path with a half turn at an end the other way round, right after it (a
    // job queued behind every other may never start within the acquisition budget).
    std::vector<ArmJob> other_ways;
    const auto add_other_way = [&](double turn_rad, const DiscreteSE2Turns& turns, std::uint64_t salt) {
      if (!job.setup_error.empty() || std::abs(turn_rad) < options_.other_way_turn_min_rad) return;
      ArmJob& other = other_ways.emplace_back();
      other.base_path = job.base_path;
      other.base_path_index = index;
      other.seed = DeriveSeed(job.seed, salt);
      other.setup_error = Discretise(job.base_path, goal, limits, turns, *context, &other.base_sequence);
    };
    add_other_way(StartTurnRad(job.base_sequence), {true, false}, 1);
    add_other_way(GoalTurnRad(job.base_sequence), {false, true}, 2);
    jobs.push_back(std::move(job));
    for (ArmJob& other : other_ways) jobs.push_back(std::move(other));
  }
  context->result->stats.discretisation_ms += watch.ElapsedMs();
  return jobs;
}

std::string FrontEnd::Discretise(const BasePath& path, const GoalCandidate& goal, const BaseLimits& limits,
                                 const DiscreteSE2Turns& turns, const PlanContext& context,
                                 DiscreteSE2Path* sequence) const {
  try {
    *sequence = DiscreteSE2(path.waypoints_W_m, context.start.yaw_rad, goal.state.yaw_rad, limits,
                            options_.discretisation, turns);
    AddArmDwell(context.start.q_rad, goal.state.q_rad, kinematics_.model().joint_limits.qd_max_radps,
                options_.arm_dwell, sequence);
  } catch (const std::exception& e) {
    return std::string("DiscreteSE2: ") + e.what();
  }
  return "";
}

ParallelAcquisitionResult FrontEnd::AcquireArmPaths(int attempt, const GoalCandidate& goal,
                                                    const std::vector<ArmJob>& jobs,
                                                    const WholeBodyValidity& validity,
                                                    PlanContext* context) const {
  FrontEndStats& stats = context->result->stats;
  ParallelAcquisitionOptions acquisition;
  acquisition.rrt = options_.rrt;
  acquisition.improvement_window_s = options_.improvement_window_s;
  acquisition.budget_s = options_.acquisition_budget_s;
  acquisition.num_workers = tbb::this_task_arena::max_concurrency();
  acquisition.goal_attempt = attempt;
  ParallelAcquisitionResult acquired =
      AcquireWholeBodyPaths(jobs, context->start.q_rad, goal.state.q_rad, validity, acquisition,
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
