#include "procs/mapper/octomap_worker.h"

#include "procs/mapper/mapper_stats.h"
#include "procs/runtime/thread_priority.h"

namespace topay::mapper {
namespace {

constexpr int kNiceIncrement = 10;

}  // namespace

OctomapWorker::OctomapWorker(OctomapMirror mirror)
    : mirror_(std::move(mirror)), thread_([this] { Run(); }) {}

OctomapWorker::~OctomapWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool OctomapWorker::Submit(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP) {
  {
    std::lock_guard lock(mutex_);
    ++stats_.submitted;
    if (has_job_ || busy_) {
      ++stats_.dropped;
      return false;
    }
    job_origin_W_ = p_WS;
    job_points_W_.assign(p_WP.begin(), p_WP.end());
    has_job_ = true;
  }
  wake_.notify_one();
  return true;
}

void OctomapWorker::SaveWhenIdle(const std::string& path) {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return !has_job_ && !busy_; });
  mirror_.Save(path);
}

OctomapWorkerStats OctomapWorker::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void OctomapWorker::Run() {
  procs::LowerThisThreadPriority(kNiceIncrement);
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stop_ || has_job_; });
    if (!has_job_) return;  // stop_ and nothing left
    has_job_ = false;
    busy_ = true;
    lock.unlock();
    // The job's buffers are only written by Submit while !has_job_ && !busy_.
    const OctomapInsertSummary summary = mirror_.Insert(job_origin_W_, job_points_W_);
    lock.lock();
    busy_ = false;
    ++stats_.inserted;
    AddSample(&stats_.insert_ms, summary.ms);
    idle_.notify_all();
  }
}

}  // namespace topay::mapper
