#include "core/planning/parallel_acquisition.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <utility>

#include <tbb/task_group.h>

#include "core/common/stopwatch.h"
#include "core/planning/stop_deadline.h"

namespace topay {
namespace {

using Clock = Stopwatch::Clock;

ArmJobReport MakeReport(const ArmJob& job, int goal_attempt) {
  ArmJobReport report;
  report.goal_attempt = goal_attempt;
  report.base_path_index = job.base_path_index;
  report.homotopy_class = job.base_path.homotopy_class;
  report.source = job.base_path.source;
  return report;
}

// Everything the workers share.
struct Shared {
  Shared(const std::vector<ArmJob>& jobs_in, const Eigen::VectorXd& q_start_in,
         const Eigen::VectorXd& q_goal_in, const WholeBodyValidity& validity_in,
         const ParallelAcquisitionOptions& options_in, Clock::time_point t0_in,
         std::stop_token stop_in, StopDeadline& deadline_in)
      : jobs(jobs_in), q_start(q_start_in), q_goal(q_goal_in), validity(validity_in),
        options(options_in), t0(t0_in), stop(std::move(stop_in)), deadline(deadline_in) {}

  const std::vector<ArmJob>& jobs;
  const Eigen::VectorXd& q_start;
  const Eigen::VectorXd& q_goal;
  const WholeBodyValidity& validity;
  const ParallelAcquisitionOptions& options;
  Clock::time_point t0;
  std::stop_token stop;
  StopDeadline& deadline;
  std::atomic<int> next_job{0};
  std::mutex first_success_mutex;
  double first_success_ms = std::numeric_limits<double>::infinity();  // guarded by the mutex
  std::vector<ArmJobReport> reports;
  std::vector<ArmRrtStarResult> results;
};

// A job found a solution at `when`: the first one starts the improvement window (the shared
// stop fires at when + improvement_window_s). Called from the job's search thread.
void NoteSuccess(Clock::time_point when, Shared* shared) {
  std::lock_guard<std::mutex> lock(shared->first_success_mutex);
  if (std::isfinite(shared->first_success_ms)) return;
  shared->first_success_ms = Stopwatch::MillisecondsBetween(shared->t0, when);
  shared->deadline.Tighten(DeadlineAfter(when, shared->options.improvement_window_s));
}

void RunJob(int index, Shared* shared) {
  const ArmJob& job = shared->jobs[index];
  ArmJobReport& report = shared->reports[index];
  if (!job.setup_error.empty()) {
    report.status = ArmRrtStarStatus::kInvalidInput;
    report.message = job.setup_error;
    return;
  }
  if (shared->stop.stop_requested()) {
    report.status = ArmRrtStarStatus::kCancelled;
    report.message = "cancelled before it started";
    return;
  }
  report.started = true;
  const Clock::time_point job_start = Clock::now();
  ArmRrtStarOptions rrt = shared->options.rrt;
  rrt.seed = job.seed;
  // Anytime search: the window starts when any job first has a solution, not when it returns.
  rrt.on_first_solution = [shared, caller = shared->options.rrt.on_first_solution](double cost) {
    NoteSuccess(Clock::now(), shared);
    if (caller) caller(cost);
  };
  ArmRrtStarResult result = PlanArmRrtStar(job.base_sequence, shared->q_start, shared->q_goal,
                                           shared->validity, rrt, shared->stop);
  const Clock::time_point job_end = Clock::now();
  report.status = result.status;
  report.message = result.message;
  report.stats = result.stats;
  report.wall_ms = Stopwatch::MillisecondsBetween(job_start, job_end);
  report.finished_at_ms = Stopwatch::MillisecondsBetween(shared->t0, job_end);
  if (result.success()) NoteSuccess(job_end, shared);  // no-op: the callback came first
  shared->results[index] = std::move(result);
}

void Work(Shared* shared) {
  const int num_jobs = static_cast<int>(shared->jobs.size());
  for (int index = shared->next_job++; index < num_jobs; index = shared->next_job++) {
    RunJob(index, shared);
  }
}

}  // namespace

ParallelAcquisitionResult AcquireWholeBodyPaths(const std::vector<ArmJob>& jobs,
                                                const Eigen::VectorXd& q_start_rad,
                                                const Eigen::VectorXd& q_goal_rad,
                                                const WholeBodyValidity& validity,
                                                const ParallelAcquisitionOptions& options,
                                                Clock::time_point t0, std::stop_token stop) {
  const Clock::time_point stage_start = Clock::now();
  std::stop_source internal;
  // Caller's stop -> every job's token, immediately (runs in the requesting thread).
  std::stop_callback forward(stop, [&internal] { internal.request_stop(); });
  StopDeadline deadline(&internal, DeadlineAfter(stage_start, options.budget_s));

  Shared shared(jobs, q_start_rad, q_goal_rad, validity, options, t0, internal.get_token(),
                deadline);
  shared.reports.reserve(jobs.size());
  for (const ArmJob& job : jobs) shared.reports.push_back(MakeReport(job, options.goal_attempt));
  shared.results.resize(jobs.size());

  const int num_workers =
      std::clamp(options.num_workers, 1, std::max(1, static_cast<int>(jobs.size())));
  tbb::task_group group;
  for (int w = 0; w < num_workers; ++w) group.run([&shared] { Work(&shared); });
  group.wait();

  ParallelAcquisitionResult out;
  out.cancelled_by_caller = stop.stop_requested();
  out.first_success_ms = shared.first_success_ms;
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    ArmRrtStarResult& result = shared.results[j];
    if (!result.success()) continue;
    FrontEndPath path;
    path.path = std::move(result.path);
    path.path.base_path_index = jobs[j].base_path_index;
    path.path.homotopy_class = jobs[j].base_path.homotopy_class;
    path.base_path = jobs[j].base_path;
    path.base_sequence = jobs[j].base_sequence;
    path.job = static_cast<int>(j);
    out.paths.push_back(std::move(path));
  }
  out.jobs = std::move(shared.reports);
  out.wall_ms = Stopwatch::MillisecondsBetween(stage_start, Clock::now());
  return out;
}

}  // namespace topay
