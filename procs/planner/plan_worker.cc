#include "procs/planner/plan_worker.h"

#include <algorithm>
#include <exception>

#include <spdlog/spdlog.h>

#include "core/common/stopwatch.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/base_reachability.h"

namespace topay::planner {

PlanWorker::PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
                       UnknownVoxelPolicy unknown, double field_update_period_s)
    : kinematics_(kinematics),
      options_(options),
      field_update_period_s_(field_update_period_s),
      world_(kinematics, unknown),
      last_flush_(std::chrono::steady_clock::now()),
      thread_([this](std::stop_token stop) { Run(stop); }) {}

PlanWorker::~PlanWorker() {
  {
    std::lock_guard lock(mutex_);
    job_stop_.request_stop();
  }
  thread_.request_stop();
  wake_.notify_all();
}

void PlanWorker::SubmitMap(MapWork work) {
  {
    std::lock_guard lock(mutex_);
    maps_.push_back(std::move(work));
  }
  wake_.notify_all();
}

void PlanWorker::SubmitPlan(PlanJob job) {
  {
    std::lock_guard lock(mutex_);
    if (running_) job_stop_.request_stop();
    queued_ = std::move(job);
  }
  wake_.notify_all();
}

void PlanWorker::Cancel() {
  std::lock_guard lock(mutex_);
  if (running_) job_stop_.request_stop();
  queued_.reset();
}

std::optional<PlanJobOutcome> PlanWorker::TakeResult() {
  std::lock_guard lock(mutex_);
  if (results_.empty()) return std::nullopt;
  PlanJobOutcome out = std::move(results_.front());
  results_.pop_front();
  return out;
}

bool PlanWorker::busy() const {
  std::lock_guard lock(mutex_);
  return running_ || queued_.has_value();
}

PlanWorkerCounts PlanWorker::counts() const {
  std::lock_guard lock(mutex_);
  return counts_;
}

void PlanWorker::FlushMap() {
  {
    std::lock_guard lock(mutex_);
    while (!maps_.empty()) {
      world_.Queue(std::move(maps_.front()));
      maps_.pop_front();
    }
  }
  if (!world_.pending()) return;
  MapFlushSummary summary;
  try {
    summary = world_.Flush();
  } catch (const std::exception& e) {  // work that does not fit the grid: a bug upstream
    spdlog::error("planner map: {}", e.what());
    std::lock_guard lock(mutex_);
    ++counts_.map_errors;
    return;
  }
  last_flush_ = std::chrono::steady_clock::now();
  std::lock_guard lock(mutex_);
  ++counts_.flushes;
  counts_.last_flush_ms = summary.ms;
  counts_.max_flush_ms = std::max(counts_.max_flush_ms, summary.ms);
}

void PlanWorker::Run(std::stop_token thread_stop) {
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(field_update_period_s_));
  while (!thread_stop.stop_requested()) {
    std::optional<PlanJob> job;
    std::stop_token job_token;
    {
      std::unique_lock lock(mutex_);
      wake_.wait_until(lock, thread_stop, last_flush_ + period,
                       [this] { return queued_.has_value(); });
      if (thread_stop.stop_requested()) return;
      if (queued_) {
        job = std::move(queued_);
        queued_.reset();
        job_stop_ = std::stop_source();
        job_token = job_stop_.get_token();
        running_ = true;
      }
    }
    if (!job) {
      if (std::chrono::steady_clock::now() >= last_flush_ + period) FlushMap();
      continue;
    }
    PlanJobOutcome outcome = Execute(*job, job_token);
    std::lock_guard lock(mutex_);
    running_ = false;
    ++counts_.plans;
    if (outcome.result.status == PlanStatus::kCancelled) ++counts_.cancelled;
    results_.push_back(std::move(outcome));
  }
}

namespace {

PlanJobOutcome Failed(PlanStatus status, std::string reason) {
  PlanJobOutcome out;
  out.result.status = status;
  out.result.failure_reason = std::move(reason);
  return out;
}

}  // namespace

PlanJobOutcome PlanWorker::Execute(const PlanJob& job, std::stop_token job_stop) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(job.time_limit_s));
  const Stopwatch setup;
  FlushMap();
  PlanJobOutcome out;
  if (!world_.has_map()) {
    out = Failed(PlanStatus::kInvalidInput, "no map yet (no MAP_UPDATE snapshot received)");
  } else {
    const Scene& scene = world_.scene();
    out.map_seq = world_.map_seq();
    if (job.certify_reachability) {
      const BaseReachability cert = CertifyTargetUnreachable(
          scene, kinematics_, {job.start.state.x_m, job.start.state.y_m}, job.X_WE_goal);
      if (cert.certified_unreachable) {
        out = Failed(PlanStatus::kFrontEndFailed, "target unreachable: " + cert.reason);
        out.certified_unreachable = true;
      }
    }
    if (!out.certified_unreachable) {
      WholeBodyPlannerOptions options = options_;
      options.time_limit_s = job.time_limit_s;
      const VoxelMapFields& fields = world_.fields();
      const WholeBodyPlanner planner(kinematics_, fields.base_field_2d(), fields.field_3d(), scene,
                                     options);
      out.setup_ms = setup.ElapsedMs();
      out.result = planner.PlanBy(deadline, job.start.state, job.X_WE_goal, job.hint, job_stop);
    }
    out.map_seq = world_.map_seq();
  }
  out.job = job;
  return out;
}

}  // namespace topay::planner
