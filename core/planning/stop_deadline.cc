#include "core/planning/stop_deadline.h"

namespace topay {

StopDeadline::StopDeadline(std::stop_source* source, Clock::time_point deadline)
    : source_(source), deadline_(deadline), watcher_([this] { Watch(); }) {}

StopDeadline::~StopDeadline() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  watcher_.join();
}

void StopDeadline::Tighten(Clock::time_point deadline) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (deadline >= deadline_) return;
    deadline_ = deadline;
  }
  wake_.notify_all();
}

void StopDeadline::Watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!quit_) {
    if (deadline_ == Clock::time_point::max()) {
      wake_.wait(lock);
      continue;
    }
    if (Clock::now() >= deadline_) {
      source_->request_stop();
      return;
    }
    wake_.wait_until(lock, deadline_);
  }
}

}  // namespace topay
