#include "procs/planner/plan_worker.h"

#include <algorithm>
#include <exception>

#include <spdlog/spdlog.h>

#include "core/common/stopwatch.h"
#include "core/map/voxel_boxes.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/base_reachability.h"
#include "core/trajectory/arc_yaw_state_at.h"

namespace topay::planner {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration Seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

PlanJobOutcome Failed(PlanStatus status, std::string reason) {
  PlanJobOutcome out;
  out.result.status = status;
  out.result.failure_reason = std::move(reason);
  return out;
}

}  // namespace

PlanWorker::PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
                       UnknownVoxelPolicy unknown, double field_update_period_s)
    : kinematics_(kinematics),
      options_(options),
      unknown_(unknown),
      field_update_period_s_(field_update_period_s),
      world_(kinematics, unknown),
      field_thread_([this](std::stop_token stop) { RunFields(stop); }),
      plan_thread_([this](std::stop_token stop) { RunPlans(stop); }) {}

PlanWorker::~PlanWorker() {
  {
    std::lock_guard lock(mutex_);
    job_stop_.request_stop();
  }
  plan_thread_.request_stop();
  field_thread_.request_stop();
  wake_plans_.notify_all();
  wake_fields_.notify_all();
  fields_ready_.notify_all();
}

void PlanWorker::SubmitMap(MapWork work) {
  std::lock_guard lock(mutex_);
  maps_.push_back(std::move(work));
}

void PlanWorker::UpdateFieldsSoon() {
  {
    std::lock_guard lock(mutex_);
    fields_soon_ = true;
  }
  wake_fields_.notify_all();
}

void PlanWorker::SubmitPlan(PlanJob job) {
  {
    std::lock_guard lock(mutex_);
    if (running_) job_stop_.request_stop();
    queued_ = std::move(job);
  }
  wake_plans_.notify_all();
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

std::optional<PlanJobOutcome> PlanWorker::WaitForResult(double timeout_s) {
  std::unique_lock lock(mutex_);
  result_ready_.wait_for(lock, Seconds(timeout_s), [this] { return !results_.empty(); });
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
  if (summary.ms > 300.0) {
    const VoxelMapUpdateSummary& u = summary.update;
    spdlog::info("planner fields: {} voxel changes{} in {:.0f} ms ({} for the fields{}; 3D {:.0f} ms, {} windows, {} cells; "
                 "2D {:.0f} ms, {} windows, {} cells)", summary.changes, summary.reset ? " after a new grid" : "", summary.ms,
                 summary.field_changes, summary.rebuilt ? ", rebuilt whole" : "", 1e3 * u.field_3d_s, u.num_windows_3d,
                 u.num_cells_3d, 1e3 * u.field_2d_s, u.num_windows_2d, u.num_cells_2d);
  }
  if (!world_.has_map()) return;
  auto snapshot = std::make_shared<const FieldSnapshot>(
      FieldSnapshot{world_.fields().base_field_2d(), world_.fields().field_3d(), world_.map_seq()});
  std::lock_guard lock(mutex_);
  fields_ = std::move(snapshot);
  ++counts_.flushes;
  counts_.last_flush_ms = summary.ms;
  counts_.max_flush_ms = std::max(counts_.max_flush_ms, summary.ms);
  fields_ready_.notify_all();
}

void PlanWorker::RunFields(std::stop_token thread_stop) {
  while (!thread_stop.stop_requested()) {
    {
      std::unique_lock lock(mutex_);
      wake_fields_.wait_for(lock, thread_stop, Seconds(field_update_period_s_),
                            [this] { return fields_soon_; });
      fields_soon_ = false;
    }
    if (thread_stop.stop_requested()) return;
    FlushMap();
  }
}

std::shared_ptr<const FieldSnapshot> PlanWorker::Fields(Clock::time_point deadline, std::stop_token stop) {
  std::unique_lock lock(mutex_);
  if (!fields_) {
    fields_soon_ = true;
    wake_fields_.notify_all();
    fields_ready_.wait_until(lock, stop, deadline, [this] { return fields_ != nullptr; });
  }
  return fields_;
}

std::shared_ptr<const FieldSnapshot> PlanWorker::FieldsWithMap(std::int64_t map_seq, Clock::time_point deadline,
                                                               std::stop_token stop) {
  std::unique_lock lock(mutex_);
  fields_soon_ = true;
  wake_fields_.notify_all();
  const auto has_map = [&] { return fields_ != nullptr && fields_->map_seq >= map_seq; };
  fields_ready_.wait_until(lock, stop, deadline, has_map);
  return has_map() ? fields_ : nullptr;
}

void PlanWorker::RunPlans(std::stop_token thread_stop) {
  while (!thread_stop.stop_requested()) {
    PlanJob job;
    std::stop_token job_token;
    {
      std::unique_lock lock(mutex_);
      wake_plans_.wait(lock, thread_stop, [this] { return queued_.has_value(); });
      if (thread_stop.stop_requested()) return;
      job = std::move(*queued_);
      queued_.reset();
      job_stop_ = std::stop_source();
      job_token = job_stop_.get_token();
      running_ = true;
    }
    PlanJobOutcome outcome = Execute(job, job_token);
    std::lock_guard lock(mutex_);
    running_ = false;
    ++counts_.plans;
    if (outcome.result.status == PlanStatus::kCancelled) ++counts_.cancelled;
    results_.push_back(std::move(outcome));
    result_ready_.notify_all();
  }
}

PlanJobOutcome PlanWorker::Execute(const PlanJob& job, std::stop_token job_stop) {
  const auto deadline = Clock::now() + Seconds(job.time_limit_s);
  const Stopwatch setup;
  PlanJobOutcome out;
  const std::shared_ptr<const FieldSnapshot> fields =
      job.map_states == nullptr ? nullptr
      : job.flush_all_map       ? FieldsWithMap(job.map_seq, deadline, job_stop)
                                : Fields(deadline, job_stop);
  if (job.map_states == nullptr) {
    out = Failed(PlanStatus::kInvalidInput, "no map yet (no MAP_UPDATE snapshot received)");
  } else if (fields == nullptr) {
    out = Failed(job_stop.stop_requested() ? PlanStatus::kCancelled : PlanStatus::kTimeLimit,
                 "the planner's fields were not built within the time limit");
  } else {
    Scene scene;
    scene.boxes = BlockedVoxelBoxes(job.map_geometry, *job.map_states, unknown_);
    scene.bounds_W_m = GridBounds(job.map_geometry);
    scene.kind = "map";
    if (job.certify_reachability) {
      const BaseReachability cert = CertifyTargetUnreachable(
          scene, kinematics_, {job.start.state.x_m, job.start.state.y_m}, job.X_WE_goal);
      // A start the certificate does not allow (a noisy voxel at the robot's base on a sensed
      // map) proves nothing about the target: the plan itself reports its start.
      if (cert.certified_unreachable && cert.component_cells > 0) {
        out = Failed(PlanStatus::kFrontEndFailed, "target unreachable: " + cert.reason);
        out.certified_unreachable = true;
      }
    }
    if (!out.certified_unreachable) {
      WholeBodyPlannerOptions options = options_;
      options.time_limit_s = job.time_limit_s;
      const WholeBodyPlanner planner(kinematics_, fields->base_field, fields->arm_field, scene, options);
      out.setup_ms = setup.ElapsedMs();
      out.result = planner.PlanBy(deadline, MovingStateOf(job.start), job.X_WE_goal, job.hint, job_stop);
    }
    out.fields_map_seq = fields->map_seq;
  }
  out.job = job;
  return out;
}

}  // namespace topay::planner
