#include "core/planner/whole_body_planner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "core/common/stopwatch.h"
#include "core/optimization/back_end_factory.h"
#include "core/planner/failure_cause.h"
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

FrontEndOptions FrontEndOptionsFor(const WholeBodyPlannerOptions& options,
                                   const Kinematics& kinematics) {
  FrontEndOptions front_end = options.front_end;
  front_end.base_limits = ResolveLimits(options, kinematics);
  // A state the exact zones accept must pass the validator.
  front_end.exact_zones.obstacle_margin_m = options.validator.obstacle_margin_m;
  front_end.exact_zones.self_margin_m = options.validator.self_margin_m;
  return front_end;
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
      validator_(kinematics, scene, base_limits_, options_.validator),
      front_end_(kinematics, base_field, arm_field, FrontEndOptionsFor(options_, kinematics),
                 &validator_.checker()),
      back_end_(MakeTrajectoryBackEnd(kinematics, base_field, arm_field, options_.optimizer)) {}

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
  const Clock::time_point t0 = Clock::now();
  WholeBodyPlanResult result;
  // One stop for the whole plan: the caller's, or the time limit.
  std::stop_source plan_stop;
  const std::stop_callback forward(stop, [&plan_stop] { plan_stop.request_stop(); });
  std::atomic<bool> time_limit_hit{false};
  {
    const Clock::time_point end = std::min(deadline, DeadlineAfter(t0, options_.time_limit_s));
    if (Clock::now() >= end) plan_stop.request_stop();  // already due: no race with the watcher
    const StopDeadline limit(&plan_stop, end);
    result.front_end = front_end_.Plan(start, X_WE_goal, hint, plan_stop.get_token());
    const FrontEndStats& stats = result.front_end.stats;
    result.timings.search_ms = stats.goal_ms + stats.topology_ms;
    result.timings.sampling_ms = stats.discretisation_ms + stats.acquisition_ms;
    result.timings.front_end_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());
    if (result.front_end.success()) {
      OptimizeCandidates(start, X_WE_goal, plan_stop.get_token(), &result);
    }
    time_limit_hit = plan_stop.stop_requested() && !stop.stop_requested();
  }
  result.timings.total_ms = Stopwatch::MillisecondsBetween(t0, Clock::now());

  if (!result.front_end.success()) {
    result.status = FromFrontEnd(result.front_end.status);
    if (result.status == PlanStatus::kCancelled) {
      result.stopped_stage = PlanStage::kFrontEnd;
      if (time_limit_hit) result.status = PlanStatus::kTimeLimit;
    }
    result.failure_reason = "front end: " + result.front_end.failure_reason;
    if (const auto cause = FrontEndFailureCause(result.front_end.status, front_end_.validity(),
                                                validator_.scene(), start, X_WE_goal)) {
      result.failure_reason += " (" + *cause + ")";
    }
    if (result.status == PlanStatus::kTimeLimit) {
      result.failure_reason = TimeLimitPrefix(options_.time_limit_s, PlanStage::kFrontEnd) +
                              result.failure_reason;
    }
    return result;
  }
  if (result.chosen >= 0) {
    result.status = PlanStatus::kSuccess;
    const BackEndSummary& chosen = result.candidates[result.chosen].optimization;
    result.sampled = chosen.Sampled();
    if (chosen.parameterisation == TrajectoryParameterisation::kArcLengthYaw) {
      result.trajectory.emplace(chosen.MakeTrajectory());
    }
    return result;
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
  return result;
}

void WholeBodyPlanner::RunCandidate(const TrajectoryProblem& plan_problem,
                                    const FrontEndPath& path, std::stop_token stop,
                                    std::stop_token plan_stop, CandidateReport* report) const {
  const Clock::time_point t = Clock::now();
  report->started = true;
  TrajectoryProblem problem = plan_problem;
  problem.exact_prefix_states = path.exact_prefix_states;
  problem.exact_suffix_states = path.exact_suffix_states;
  report->optimization = back_end_->Optimize(problem, path.path, stop);
  if (report->optimization.success()) {
    try {  // either parameterisation (arc length-yaw, or the flatness baseline)
      // The plan's stop (time limit, caller), not the early-termination window: a
      // validation that has begun finishes unless the plan must end.
      report->validation = validator_.Validate(report->optimization.Sampled(), problem.start,
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

void WholeBodyPlanner::OptimizeCandidates(const WholeBodyState& start,
                                          const Eigen::Isometry3d& X_WE_goal,
                                          std::stop_token plan_stop,
                                          WholeBodyPlanResult* result) const {
  const Clock::time_point t_begin = Clock::now();
  const std::vector<FrontEndPath>& paths = result->front_end.paths;
  const int n = std::min<int>(options_.max_candidates, paths.size());
  result->candidates.assign(n, CandidateReport{});
  for (int i = 0; i < n; ++i) result->candidates[i].path_index = i;
  const TrajectoryProblem problem{start, X_WE_goal, base_limits_};

  // The stage's stop: the plan's, or the early-termination window after the first success.
  std::stop_source stage_stop;
  const std::stop_callback forward(plan_stop, [&stage_stop] { stage_stop.request_stop(); });
  StopDeadline window(&stage_stop, Clock::time_point::max());
  std::atomic<int> next{0};
  std::atomic<std::int64_t> first_success_ns{std::numeric_limits<std::int64_t>::max()};
  auto work = [&] {
    while (!stage_stop.stop_requested()) {
      const int i = next.fetch_add(1);
      if (i >= n) return;
      CandidateReport& report = result->candidates[i];
      RunCandidate(problem, paths[i], stage_stop.get_token(), plan_stop, &report);
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
