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

// A slow flush in the log: what it applied and what the 3D and 2D updates cost.
void LogFlush(const char* what, const MapFlushSummary& s) {
  const VoxelMapUpdateSummary& u = s.update;
  spdlog::info("planner fields ({}): {} changes{}{} in {:.0f} ms, {} left (3D {:.0f} ms, {} windows, {} cells; "
               "2D {:.0f} ms, {} windows, {} cells)", what, s.field_changes, s.reset ? " after a new grid" : "",
               s.rebuilt ? ", rebuilt whole" : "", s.ms, s.left_pending, 1e3 * u.field_3d_s, u.num_windows_3d,
               u.num_cells_3d, 1e3 * u.field_2d_s, u.num_windows_2d, u.num_cells_2d);
}

}  // namespace

PlanWorker::PlanWorker(const Kinematics& kinematics, const WholeBodyPlannerOptions& options,
                       UnknownVoxelPolicy unknown, double field_update_period_s, double slice_m)
    : kinematics_(kinematics),
      options_(options),
      unknown_(unknown),
      field_update_period_s_(field_update_period_s),
      world_(kinematics, unknown, slice_m),
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

std::optional<PlanJobOutcome> PlanWorker::WaitForResult(double timeout_s) {
  std::unique_lock lock(mutex_);
  results_ready_.wait_for(lock, Seconds(timeout_s), [this] { return !results_.empty(); });
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

template <typename Flush>
bool PlanWorker::FlushCounted(Flush flush, MapFlushSummary* summary) {
  try {
    *summary = flush();
    return true;
  } catch (const std::exception& e) {  // work that does not fit the grid: a bug upstream
    spdlog::error("planner map: {}", e.what());
    std::lock_guard lock(mutex_);
    ++counts_.map_errors;
    return false;
  }
}

void PlanWorker::RecordFlush(const MapFlushSummary& summary, bool fresh) {
  if (summary.ms > (fresh ? 100.0 : 300.0)) LogFlush(fresh ? "before a plan" : "background", summary);
  std::lock_guard lock(mutex_);
  counts_.pending_changes = world_.pending_changes();
  if (fresh) {
    counts_.max_fresh_ms = std::max(counts_.max_fresh_ms, summary.ms);
    return;
  }
  ++counts_.flushes;
  counts_.last_flush_ms = summary.ms;
  counts_.max_flush_ms = std::max(counts_.max_flush_ms, summary.ms);
}

void PlanWorker::Run(std::stop_token thread_stop) {
  while (!thread_stop.stop_requested()) {
    std::deque<MapWork> maps;
    std::optional<PlanJob> job;
    std::stop_token job_token;
    {
      std::unique_lock lock(mutex_);
      const std::optional<Clock::time_point> oldest = world_.OldestPending();
      const Clock::time_point due =
          oldest ? (*oldest == Clock::time_point::min() ? Clock::now() : *oldest + Seconds(field_update_period_s_))
                 : Clock::now() + Seconds(3600.0);
      wake_.wait_until(lock, thread_stop, due, [this] { return queued_.has_value() || !maps_.empty(); });
      if (thread_stop.stop_requested()) return;
      maps.swap(maps_);
      if (queued_) {
        job = std::move(*queued_);
        queued_.reset();
        job_stop_ = std::stop_source();
        job_token = job_stop_.get_token();
        running_ = true;
      }
    }
    for (MapWork& work : maps) world_.Queue(std::move(work));
    if (job) {
      PlanJobOutcome outcome = Execute(*job, job_token);
      const bool cancelled = outcome.result.status == PlanStatus::kCancelled;
      {
        std::lock_guard lock(mutex_);
        running_ = false;
        ++counts_.plans;
        if (cancelled) ++counts_.cancelled;
        results_.push_back(std::move(outcome));
        results_ready_.notify_all();
      }
      if (cancelled) continue;  // replaced by an urgent plan (a new collision): it goes first
    }
    // One overdue slice per pass, also between back-to-back plans (not before a plan that
    // replaced a cancelled one): while the robot replans
    // continuously the map far from its start would otherwise never reach the fields (stale
    // obstacles closed passages the map had long opened, and the plans went round them).
    const std::optional<Clock::time_point> oldest = world_.OldestPending();
    if (oldest && (*oldest == Clock::time_point::min() || Clock::now() >= *oldest + Seconds(field_update_period_s_))) {
      MapFlushSummary summary;
      if (FlushCounted([this] { return world_.FlushOldestSlice(); }, &summary)) RecordFlush(summary, false);
    }
  }
}

PlanJobOutcome PlanWorker::Execute(const PlanJob& job, std::stop_token job_stop) {
  const auto deadline = Clock::now() + Seconds(job.time_limit_s);
  const Stopwatch setup;
  MapFlushSummary fresh;
  const bool flushed = FlushCounted(
      [&] { return job.flush_all_map ? world_.Flush() : world_.FlushWithin(job.fresh_regions_xy_W_m); }, &fresh);
  if (flushed) RecordFlush(fresh, true);
  PlanJobOutcome out;
  if (!world_.has_map()) {
    out = Failed(PlanStatus::kInvalidInput, "no map yet (no MAP_UPDATE snapshot received)");
  } else {
    const GridGeometry3& geometry = world_.fields().geometry();
    Scene scene;
    if (job.from_rest) {  // the robot stands there: its own footprint is free
      std::vector<std::uint8_t> states(world_.states().begin(), world_.states().end());
      ClearStandingRobot(geometry, kinematics_, job.Standing(), unknown_, &states);
      scene.boxes = BlockedVoxelBoxes(geometry, states, unknown_);
    } else {
      scene.boxes = BlockedVoxelBoxes(geometry, world_.states(), unknown_);
    }
    scene.bounds_W_m = GridBounds(geometry);
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
      const VoxelMapFields& fields = world_.fields();
      const WholeBodyPlanner planner(kinematics_, fields.base_field_2d(), fields.field_3d(), scene, options);
      out.setup_ms = setup.ElapsedMs();
      out.result = planner.PlanBy(deadline, MovingStateOf(job.start), job.X_WE_goal, job.hint, job_stop);
    }
  }
  out.fields_map_seq = world_.map_seq();
  out.changes_left = world_.pending_changes();
  out.fresh_ms = fresh.ms;
  out.job = job;
  return out;
}

}  // namespace topay::planner
