#include "core/planner/whole_body_planner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/optimization/back_end_factory.h"
#include "core/planner/failure_cause.h"
#include "core/planner/round_time.h"
#include "core/planning/stop_deadline.h"

namespace topay {
namespace {

using Clock = Stopwatch::Clock;


WholeBodyPlannerOptions Checked(WholeBodyPlannerOptions options) {
  CheckWholeBodyPlannerOptions(options);
  return options;
}

BaseLimits ResolveLimits(const WholeBodyPlannerOptions& options, const Kinematics& kinematics) {
  return options.base_limits.value_or(kinematics.model().base_limits);
}

// Round r's front end: round 0 as configured, round r > 0 with every seed derived from r
// and growth^r times the arm RRT* budget.
FrontEndOptions RoundFrontEndOptions(const WholeBodyPlannerOptions& options,
                                     const Kinematics& kinematics, int round) {
  FrontEndOptions front_end = options.front_end;
  front_end.base_limits = ResolveLimits(options, kinematics);
  // A state the exact zones accept must pass the validator.
  front_end.exact_zones.obstacle_margin_m = options.validator.obstacle_margin_m;
  front_end.exact_zones.self_margin_m = options.validator.self_margin_m;
  return RetryRoundFrontEnd(front_end, options.retry, round);
}

// The back end at margin level k: both clearance margins (their defaults resolved as
// SamplePenalties does) + k x retry.clearance_step_m; `slow`: the warm start's rates x
// retry.warm_start_slowdown.
TrajectoryOptimizerOptions MarginLevelOptions(const WholeBodyPlannerOptions& options,
                                              const SignedDistanceField2& base_field,
                                              const SignedDistanceField3& arm_field, int level,
                                              bool slow) {
  TrajectoryOptimizerOptions optimizer = options.optimizer;
  if (slow) optimizer.warm_start.rate_fraction *= options.retry.warm_start_slowdown;
  if (level == 0) return optimizer;
  SamplePenaltyOptions& penalties = optimizer.objective.penalties;
  const double extra_m = level * options.retry.clearance_step_m;
  penalties.base_field_margin_m =
      penalties.base_field_margin_m.value_or(base_field.exactness_margin_m()) + extra_m;
  penalties.arm_field_margin_m =
      penalties.arm_field_margin_m.value_or(arm_field.exactness_margin_m()) +
      extra_m;
  return optimizer;
}

// A round without a validated trajectory that another round (other seeds, wider margins)
// may turn into one. `cut`: its own share of the time ended it (not the plan's stop).
bool Retryable(const WholeBodyPlanResult& round, bool cut) {
  if (round.chosen >= 0) return false;
  if (round.front_end.success()) return true;  // paths, but no validated trajectory
  switch (round.front_end.status) {
    case FrontEndStatus::kNoGoal:
    case FrontEndStatus::kNoBasePath:
    case FrontEndStatus::kNoArmPath:
      return true;
    case FrontEndStatus::kCancelled:
      return cut;
    default:
      return false;
  }
}

bool AnyValidatorRejection(const std::vector<CandidateReport>& candidates) {
  return std::any_of(candidates.begin(), candidates.end(), [](const CandidateReport& c) {
    return c.validation.has_value() && !c.validation->ok && !c.validation->stopped;
  });
}

void AddTimings(const PlanTimings& round, PlanTimings* sum) {
  sum->search_ms += round.search_ms;
  sum->sampling_ms += round.sampling_ms;
  sum->front_end_ms += round.front_end_ms;
  sum->optimization_ms += round.optimization_ms;
  sum->wait_ms += round.wait_ms;
}

PlanStatus FromFrontEnd(FrontEndStatus status) {
  switch (status) {
    case FrontEndStatus::kInvalidInput:
      return PlanStatus::kInvalidInput;
    case FrontEndStatus::kCancelled:
      return PlanStatus::kCancelled;
    default:
      return PlanStatus::kFrontEndFailed;
  }
}

// "n x reason; m x other" over the candidates that did not validate.
std::string SummariseCandidates(const std::vector<CandidateReport>& candidates);

// A failed round in a few words, for the final reason.
std::string RoundFailure(const WholeBodyPlanResult& round) {
  if (!round.front_end.success()) {
    return std::string(ToString(round.front_end.status));
  }
  return SummariseCandidates(round.candidates);
}

std::string SummariseCandidates(const std::vector<CandidateReport>& candidates) {
  std::vector<std::pair<std::string, int>> counts;
  for (const CandidateReport& c : candidates) {
    std::string why;
    if (!c.started) {
      why = "not started";
    } else if (!c.optimization.success()) {
      why = std::string(ToString(c.optimization.status)) + " (" + c.optimization.reason + ")";
    } else if (c.validation && !c.validation->ok) {
      why = "rejected by the validator (" + c.validation->first_failure.message + ")";
    } else {
      continue;
    }
    auto it = std::find_if(counts.begin(), counts.end(),
                           [&why](const auto& entry) { return entry.first == why; });
    if (it == counts.end()) {
      counts.emplace_back(why, 1);
    } else {
      ++it->second;
    }
  }
  std::string out;
  for (const auto& [why, count] : counts) {
    if (!out.empty()) out += "; ";
    out += std::to_string(count) + " x " + why;
  }
  return out;
}

// The whole-body path from a moving start: the lead-in's states, then the front end's path
// from the lead-in's end (its first state, the lead-in's last, kept once). The exact prefix
// then counts from the start: through the lead-in if the path's own prefix is exact or if
// some lead-in state passed only the exact check (lead_in_exact). base_path and
// base_sequence stay the front end's (they begin at the lead-in's end).
void PrependLeadIn(const LeadIn& lead_in, bool lead_in_exact, FrontEndPath* path) {
  WholeBodyPath& p = path->path;
  const int extra = static_cast<int>(lead_in.states.size()) - 1;
  const double shift_s = lead_in.times_s.back();
  for (double& t : p.times_s) t += shift_s;
  p.states.insert(p.states.begin(), lead_in.states.begin(), lead_in.states.end() - 1);
  p.times_s.insert(p.times_s.begin(), lead_in.times_s.begin(), lead_in.times_s.end() - 1);
  if (path->exact_prefix_states > 0) {
    path->exact_prefix_states += extra;
  } else if (lead_in_exact) {
    path->exact_prefix_states = extra + 1;  // the start through the lead-in's end
  }
}

}  // namespace

std::string TimeLimitPrefix(double time_limit_s, PlanStage stage) {
  char text[96];
  std::snprintf(text, sizeof(text), "time limit %.3f s reached during %s: ", time_limit_s,
                std::string(ToString(stage)).c_str());
  return text;
}

WholeBodyPlanner::WholeBodyPlanner(const Kinematics& kinematics,
                                   const SignedDistanceField2& base_field,
                                   const SignedDistanceField3& arm_field, const Scene& scene,
                                   WholeBodyPlannerOptions options)
    : options_(Checked(std::move(options))),
      base_limits_(ResolveLimits(options_, kinematics)),
      validator_(kinematics, scene, base_limits_, options_.validator) {
  const bool slow = options_.retry.max_rounds > 1 && options_.retry.warm_start_slowdown < 1.0;
  for (int round = 0; round < options_.retry.max_rounds; ++round) {
    rounds_.push_back(std::make_unique<const FrontEnd>(
        kinematics, base_field, arm_field, RoundFrontEndOptions(options_, kinematics, round),
        &validator_.checker()));
    // Round r's margin level is at most r.
    back_ends_.push_back(MakeTrajectoryBackEnd(
        kinematics, base_field, arm_field,
        MarginLevelOptions(options_, base_field, arm_field, round, /*slow=*/false)));
    if (slow) {
      slow_back_ends_.push_back(MakeTrajectoryBackEnd(
          kinematics, base_field, arm_field,
          MarginLevelOptions(options_, base_field, arm_field, round, /*slow=*/true)));
    }
  }
}

WholeBodyPlanResult WholeBodyPlanner::Plan(const WholeBodyState& start,
                                           const Eigen::Isometry3d& X_WE_goal,
                                           const std::optional<WholeBodyState>& hint,
                                           std::stop_token stop) const {
  return PlanBy(Clock::time_point::max(), start, X_WE_goal, hint, stop);
}

WholeBodyPlanResult WholeBodyPlanner::PlanBy(Clock::time_point deadline,
                                             const WholeBodyState& start,
                                             const Eigen::Isometry3d& X_WE_goal,
                                             const std::optional<WholeBodyState>& hint,
                                             std::stop_token stop) const {
  return PlanBy(deadline, MovingState{start, WholeBodyRates{}}, X_WE_goal, hint, stop);
}

WholeBodyPlanResult WholeBodyPlanner::Plan(const MovingState& start,
                                           const Eigen::Isometry3d& X_WE_goal,
                                           const std::optional<WholeBodyState>& hint,
                                           std::stop_token stop) const {
  return PlanBy(Clock::time_point::max(), start, X_WE_goal, hint, stop);
}

WholeBodyPlanResult WholeBodyPlanner::PlanBy(Clock::time_point deadline,
                                             const MovingState& moving_start,
                                             const Eigen::Isometry3d& X_WE_goal,
                                             const std::optional<WholeBodyState>& hint,
                                             std::stop_token stop) const {
  const Clock::time_point t0 = Clock::now();
  WholeBodyPlanResult result;
  // A moving start: the braking lead-in along the current heading, checked before any
  // search (the front end plans from its end; with rest rates it is the start alone).
  LeadIn lead_in;
  lead_in.states = {moving_start.state};
  lead_in.times_s = {0.0};
  try {
    // Rest: the start alone, unchecked here (the front end reports a bad start as before).
    if (!moving_start.rates.IsAtRest()) {
      lead_in = MakeLeadIn(moving_start, base_limits_,
                           validator_.kinematics().model().joint_limits, options_.lead_in);
    }
  } catch (const std::invalid_argument& e) {
    result.status = PlanStatus::kInvalidInput;
    result.front_end.failure_reason = e.what();
    result.failure_reason = std::string("moving start: ") + e.what();
    return result;
  }
  bool lead_in_exact = false;  // some lead-in state passed only the exact check
  if (!lead_in.empty()) {
    const std::string collision =
        CheckLeadIn(lead_in, front_end().validity(), &validator_.checker(),
                    options_.validator.obstacle_margin_m, options_.validator.self_margin_m,
                    &lead_in_exact);
    if (!collision.empty()) {
      result.status = PlanStatus::kFrontEndFailed;
      result.front_end.status = FrontEndStatus::kStartInvalid;
      result.front_end.failure_reason = collision;
      result.failure_reason = collision;
      result.timings.total_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
      return result;
    }
  }
  // The front end's start: the lead-in's end (the start itself when at rest).
  const WholeBodyState& start = lead_in.end();
  // One stop for the whole plan: the caller's, or the time limit.
  std::stop_source plan_stop;
  const std::stop_callback forward(stop, [&plan_stop] { plan_stop.request_stop(); });
  bool time_limit_hit = false;
  {
    const Clock::time_point end = std::min(deadline, DeadlineAfter(t0, options_.time_limit_s));
    if (Clock::now() >= end) plan_stop.request_stop();  // already due: no race with the watcher
    const StopDeadline limit(&plan_stop, end);
    const std::chrono::duration<double> min_left(options_.retry.min_time_left_s);
    PlanTimings earlier;
    std::string earlier_failures;
    int level = 0;  // margin level: rounds so far with a validator rejection
    bool round_cut = false;  // the last round run was ended by its own share of the time
    for (int round = 0;; ++round) {
      // A round that may be followed by another gets its share of the time left; the last
      // round, the plan's limit alone.
      std::stop_source round_stop;
      const std::stop_callback forward_plan(plan_stop.get_token(),
                                            [&round_stop] { round_stop.request_stop(); });
      const bool may_retry = round + 1 < options_.retry.max_rounds;
      const double share = may_retry ? options_.retry.round_time_share : 1.0;
      const RoundTime time{&round_stop, RoundShareEnd(Clock::now(), end, share), end};
      result = PlanRound(round, level, moving_start, lead_in, lead_in_exact, X_WE_goal, hint,
                         time, plan_stop.get_token());
      round_cut = round_stop.stop_requested() && !plan_stop.stop_requested();
      AddTimings(result.timings, &earlier);
      const bool last = !may_retry || plan_stop.stop_requested() || end - Clock::now() < min_left;
      // A target no seed can reach (below the floor, outside the room, inside a box).
      const bool hopeless = !result.front_end.success() &&
                            FrontEndFailureCause(result.front_end.status, front_end().validity(),
                                                 validator_.scene(), start, X_WE_goal)
                                .has_value();
      if (last || hopeless || !Retryable(result, round_cut)) {
        result.rounds = round + 1;
        result.earlier_rounds = std::move(earlier_failures);
        break;
      }
      if (!earlier_failures.empty()) earlier_failures += "; ";
      earlier_failures += "round " + std::to_string(round + 1) + ": " + RoundFailure(result);
      if (AnyValidatorRejection(result.candidates)) ++level;
    }
    result.timings = earlier;
    time_limit_hit = (plan_stop.stop_requested() || round_cut) && !stop.stop_requested();
  }
  result.timings.total_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
  Conclude(time_limit_hit, stop, start, X_WE_goal, &result);
  return result;
}

WholeBodyPlanResult WholeBodyPlanner::PlanRound(int round, int level,
                                                const MovingState& start, const LeadIn& lead_in,
                                                bool lead_in_exact,
                                                const Eigen::Isometry3d& X_WE_goal,
                                                const std::optional<WholeBodyState>& hint,
                                                const RoundTime& time,
                                                std::stop_token plan_stop) const {
  const Clock::time_point t0 = Clock::now();
  const std::stop_token round_stop = time.stop->get_token();
  std::optional<StopDeadline> round_limit;
  if (time.round_end < time.plan_end) round_limit.emplace(time.stop, time.round_end);
  WholeBodyPlanResult result;
  result.front_end = rounds_[round]->Plan(lead_in.end(), X_WE_goal, hint, round_stop);
  if (result.front_end.success() && !lead_in.empty()) {
    for (FrontEndPath& path : result.front_end.paths) {
      PrependLeadIn(lead_in, lead_in_exact, &path);
    }
  }
  const FrontEndStats& stats = result.front_end.stats;
  result.timings.search_ms = stats.goal_ms + stats.topology_ms;
  result.timings.sampling_ms = stats.discretisation_ms + stats.acquisition_ms;
  result.timings.front_end_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
  if (result.front_end.success()) {
    // Time after this round's share for no whole round: the round keeps the plan's time.
    if (round_limit && RoundKeepsThePlanTime(time.round_end, time.plan_end,
                                             1e-3 * result.timings.front_end_ms,
                                             options_.retry.min_time_left_s)) {
      round_limit.reset();
    }
    // From a moving start the warm start keeps its rates: a slower profile would begin above
    // its own speed limit.
    const bool slow = round > 0 && start.rates.IsAtRest() && !slow_back_ends_.empty();
    const TrajectoryBackEnd& back_end = slow ? *slow_back_ends_[level] : *back_ends_[level];
    OptimizeCandidates(back_end, start, X_WE_goal, round_stop, plan_stop, &result);
  }
  result.margin_level = level;
  return result;
}

void WholeBodyPlanner::Conclude(bool time_limit_hit, std::stop_token stop,
                                const WholeBodyState& start, const Eigen::Isometry3d& X_WE_goal,
                                WholeBodyPlanResult* out) const {
  WholeBodyPlanResult& result = *out;
  const std::string rounds =
      result.earlier_rounds.empty() ? ""
                                    : " (after " + std::to_string(result.rounds) +
                                          " rounds; " + result.earlier_rounds + ")";
  if (!result.front_end.success()) {
    result.status = FromFrontEnd(result.front_end.status);
    if (result.status == PlanStatus::kCancelled) {
      result.stopped_stage = PlanStage::kFrontEnd;
      if (time_limit_hit) result.status = PlanStatus::kTimeLimit;
    }
    result.failure_reason = "front end: " + result.front_end.failure_reason;
    if (const auto cause = FrontEndFailureCause(result.front_end.status, front_end().validity(),
                                                validator_.scene(), start, X_WE_goal)) {
      result.failure_reason += " (" + *cause + ")";
    }
    if (result.status == PlanStatus::kTimeLimit) {
      result.failure_reason = TimeLimitPrefix(options_.time_limit_s, PlanStage::kFrontEnd) +
                              result.failure_reason;
    }
    result.failure_reason += rounds;
    return;
  }
  if (result.chosen >= 0) {
    result.status = PlanStatus::kSuccess;
    const BackEndSummary& chosen = result.candidates[result.chosen].optimization;
    result.sampled = chosen.Sampled();
    if (chosen.parameterisation == TrajectoryParameterisation::kArcLengthYaw) {
      result.trajectory.emplace(chosen.MakeTrajectory());
    }
    return;
  }
  result.status = stop.stop_requested() ? PlanStatus::kCancelled
                  : time_limit_hit      ? PlanStatus::kTimeLimit
                                        : PlanStatus::kOptimizationFailed;
  if (result.status != PlanStatus::kOptimizationFailed) {
    const bool in_validation =
        std::any_of(result.candidates.begin(), result.candidates.end(),
                    [](const CandidateReport& c) { return c.validation && c.validation->stopped; });
    result.stopped_stage = in_validation ? PlanStage::kValidation : PlanStage::kOptimization;
  }
  result.failure_reason = "no validated trajectory from " +
                          std::to_string(result.candidates.size()) + " candidate paths: " +
                          SummariseCandidates(result.candidates);
  if (result.status == PlanStatus::kTimeLimit) {
    result.failure_reason =
        TimeLimitPrefix(options_.time_limit_s, result.stopped_stage) + result.failure_reason;
  }
  result.failure_reason += rounds;
}

void WholeBodyPlanner::RunCandidate(const TrajectoryBackEnd& back_end,
                                    const TrajectoryProblem& plan_problem,
                                    const FrontEndPath& path, std::stop_token stop,
                                    std::stop_token plan_stop, CandidateReport* report) const {
  const Clock::time_point t = Clock::now();
  report->started = true;
  TrajectoryProblem problem = plan_problem;
  problem.exact_prefix_states = path.exact_prefix_states;
  problem.exact_suffix_states = path.exact_suffix_states;
  report->optimization = back_end.Optimize(problem, path.path, stop);
  if (report->optimization.success()) {
    try {  // either parameterisation (arc length-yaw, or the flatness baseline)
      // The plan's stop (time limit, caller), not the early-termination window: a
      // validation that has begun finishes unless the plan must end.
      // A moving start: the rates at t = 0 are checked too (rest: the rest-start check).
      report->validation =
          problem.start_rates.IsAtRest()
              ? validator_.Validate(report->optimization.Sampled(), problem.start,
                                    problem.X_WE_goal, plan_stop)
              : validator_.Validate(report->optimization.Sampled(),
                                    MovingState{problem.start, problem.start_rates},
                                    problem.X_WE_goal, plan_stop);
    } catch (const std::exception& e) {  // a malformed summary counts as a failure
      ValidationReport failed;
      failed.ok = false;
      failed.first_failure.message = std::string("could not rebuild the trajectory: ") + e.what();
      report->validation = failed;
    }
  }
  report->wall_ms = Stopwatch::MillisecondsBetween(t, Clock::now());
}

void WholeBodyPlanner::OptimizeCandidates(const TrajectoryBackEnd& back_end,
                                          const MovingState& start,
                                          const Eigen::Isometry3d& X_WE_goal,
                                          std::stop_token round_stop, std::stop_token plan_stop,
                                          WholeBodyPlanResult* result) const {
  const Clock::time_point t_begin = Clock::now();
  const std::vector<FrontEndPath>& paths = result->front_end.paths;
  const int n = std::min<int>(options_.max_candidates, paths.size());
  result->candidates.assign(n, CandidateReport{});
  for (int i = 0; i < n; ++i) result->candidates[i].path_index = i;
  TrajectoryProblem problem;
  problem.start = start.state;
  problem.start_rates = start.rates;
  problem.X_WE_goal = X_WE_goal;
  problem.base_limits = base_limits_;

  // The stage's stop: the round's, or the early-termination window after the first success.
  // A validation that has begun finishes unless the plan (not just the round) must end.
  std::stop_source stage_stop;
  const std::stop_callback forward(round_stop, [&stage_stop] { stage_stop.request_stop(); });
  StopDeadline window(&stage_stop, Clock::time_point::max());
  std::atomic<int> next{0};
  std::atomic<std::int64_t> first_success_ns{std::numeric_limits<std::int64_t>::max()};
  auto work = [&] {
    while (!stage_stop.stop_requested()) {
      const int i = next.fetch_add(1);
      if (i >= n) return;
      CandidateReport& report = result->candidates[i];
      RunCandidate(back_end, problem, paths[i], stage_stop.get_token(), plan_stop, &report);
      if (report.validated()) {
        const Clock::time_point now = Clock::now();
        std::int64_t expected = std::numeric_limits<std::int64_t>::max();
        first_success_ns.compare_exchange_strong(expected, (now - t_begin).count());
        if (options_.sequential) continue;
        if (options_.early_termination_window_s <= 0.0) {
          stage_stop.request_stop();  // at once, not when the deadline's thread wakes
        } else {
          window.Tighten(DeadlineAfter(now, options_.early_termination_window_s));
        }
      }
    }
  };
  // The workers and the optimizers' parallel sample chunks share one arena of num_threads
  // (1 in the sequential ablation): a worker without a candidate helps the others' chunks.
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads =
      options_.sequential ? 1 : (options_.num_threads > 0 ? options_.num_threads : hardware);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    if (options_.sequential) {
      work();
      return;
    }
    tbb::task_group group;
    for (int w = 1; w < std::min(n, threads); ++w) group.run(work);
    work();  // the calling thread is a worker too
    group.wait();
  });
  const Clock::time_point t_end = Clock::now();

  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const CandidateReport& c = result->candidates[i];
    if (c.validated() && c.optimization.duration_s < best) {
      best = c.optimization.duration_s;
      result->chosen = i;
    }
  }
  const std::int64_t first = first_success_ns.load();
  if (first != std::numeric_limits<std::int64_t>::max()) {
    const double first_ms = std::chrono::duration<double, std::milli>(Clock::duration(first)).count();
    result->timings.optimization_ms = first_ms;
    result->timings.wait_ms = Stopwatch::MillisecondsBetween(t_begin, t_end) - first_ms;
  } else {
    result->timings.optimization_ms = Stopwatch::MillisecondsBetween(t_begin, t_end);
  }
}

}  // namespace topay
