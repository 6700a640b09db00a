#include "procs/sim/scan_worker.h"

#include <algorithm>
#include <optional>

#include "procs/runtime/thread_priority.h"

namespace topay::simproc {
namespace {

constexpr int kNiceIncrement = 10;

}  // namespace

ScanWorker::ScanWorker(std::unique_ptr<ScanSensor> sensor, std::function<void(ScanResult&&)> on_done,
                       bool latest_scan_only)
    : sensor_(std::move(sensor)),
      on_done_(std::move(on_done)),
      latest_scan_only_(latest_scan_only),
      thread_([this] { Run(); }) {}

ScanWorker::~ScanWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ScanWorker::SetWorld(std::vector<OrientedBox> boxes) {
  {
    std::lock_guard lock(mutex_);
    jobs_.emplace_back(std::move(boxes));
  }
  wake_.notify_one();
}

void ScanWorker::Request(const WholeBodyState& state, double t_s) {
  {
    std::lock_guard lock(mutex_);
    if (latest_scan_only_) {
      const auto waiting = [](const Job& job) { return std::holds_alternative<ScanJob>(job); };
      const std::size_t before = jobs_.size();
      std::erase_if(jobs_, waiting);
      dropped_ += static_cast<std::int64_t>(before - jobs_.size());
    }
    jobs_.emplace_back(ScanJob{state, t_s});
  }
  wake_.notify_one();
}

std::vector<ScanResult> ScanWorker::TakeCompleted() {
  std::lock_guard lock(mutex_);
  std::vector<ScanResult> done;
  done.swap(done_);
  return done;
}

void ScanWorker::Drain() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return jobs_.empty() && running_ == 0; });
}

int ScanWorker::backlog() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(jobs_.size()) + running_;
}

std::int64_t ScanWorker::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

void ScanWorker::Run() {
  // A lower priority (nice + kNiceIncrement): on a busy machine the scheduler then lets the
  // plant thread run as soon as it wakes instead of at the end of the scan's time slice. The
  // scans keep their 10 Hz (one takes ~5 % of a core).
  procs::LowerThisThreadPriority(kNiceIncrement);
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
    if (jobs_.empty()) return;  // stop_ and nothing left
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    ++running_;
    lock.unlock();
    std::optional<ScanResult> result;
    if (auto* boxes = std::get_if<std::vector<OrientedBox>>(&job)) {
      sensor_->SetWorld(*boxes);
    } else {
      const ScanJob& scan = std::get<ScanJob>(job);
      result = sensor_->Scan(scan.state, scan.t_s);
      if (on_done_) {
        on_done_(std::move(*result));
        result.reset();
      }
    }
    lock.lock();
    if (result) done_.push_back(std::move(*result));
    --running_;
    if (jobs_.empty() && running_ == 0) idle_.notify_all();
  }
}

}  // namespace topay::simproc
