#include "procs/runtime/process_loop.h"

#include <poll.h>
#include <sys/mman.h>
#include <unistd.h>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>

#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::procs {

std::int64_t NowUtime() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

ProcessLoop::ProcessLoop(const ProcessOptions& options)
    : options_(options),
      signals_({SIGINT, SIGTERM}),
      lcm_(std::make_unique<lcm::LCM>(options.lcm_url)) {
  if (options_.mlockall && mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    spdlog::warn("mlockall not permitted ({}); running without locked memory",
                 std::strerror(errno));
  }
}

std::string ProcessLoop::error() const {
  if (lcm_->good()) return "";
  return "cannot open LCM at '" + (options_.lcm_url.empty() ? "(default)" : options_.lcm_url) +
         "' (is there a multicast route? run inside a private network namespace)";
}

void ProcessLoop::AddTimer(double period_s, std::function<void()> callback) {
  const auto period = std::chrono::nanoseconds(static_cast<std::int64_t>(period_s * 1e9));
  timers_.push_back({std::max(period, std::chrono::nanoseconds(1000)), Clock::time_point::min(),
                     std::move(callback), nullptr});
}

void ProcessLoop::AddScheduledTimer(std::function<Clock::time_point()> callback) {
  timers_.push_back({std::chrono::nanoseconds(0), Clock::time_point::min(), nullptr, std::move(callback)});
}

void ProcessLoop::SetHealth(std::int8_t health, std::string status) {
  health_ = health;
  status_ = std::move(status);
}

void ProcessLoop::PublishHeartbeat() {
  heartbeat_t hb;
  hb.utime = NowUtime();
  hb.process_name = options_.name;
  hb.pid = static_cast<std::int32_t>(getpid());
  hb.seq = heartbeat_seq_++;
  hb.health = health_;
  hb.status = status_;
  if (stats_.total_malformed() > 0) {
    hb.status += " (malformed messages dropped: " + std::to_string(stats_.total_malformed()) + ")";
  }
  lcm_->publish(std::string(channels::HEARTBEAT), &hb);
  if (watchdog_.enabled() && !watchdog_.Notify() && !watchdog_warned_) {
    watchdog_warned_ = true;  // the bus heartbeat still goes out; said once
    spdlog::warn("{} (the launcher then sees only the bus heartbeat)", watchdog_.error());
  }
}

void ProcessLoop::RunDueTimers(Clock::time_point now) {
  for (Timer& timer : timers_) {
    if (now < timer.next) continue;
    if (timer.scheduled) {
      timer.next = timer.scheduled();
      continue;
    }
    // Catch up without bursts: the next deadline is the first period boundary after now.
    timer.next += timer.period;
    if (timer.next <= now) timer.next = now + timer.period;
    timer.callback();
  }
}

ProcessLoop::Clock::time_point ProcessLoop::NextDeadline() const {
  Clock::time_point next = Clock::time_point::max();
  for (const Timer& timer : timers_) next = std::min(next, timer.next);
  return next;
}

int ProcessLoop::HandlePending(int max_messages) {
  int handled = 0;
  while (handled < max_messages) {
    const int result = lcm_->handleTimeout(0);
    if (result < 0) return -1;
    if (result == 0) break;
    ++handled;
  }
  return handled;
}

int ProcessLoop::Run() { return RunUntil(Clock::time_point::max()); }

int ProcessLoop::RunUntil(Clock::time_point deadline) {
  if (!ok()) {
    spdlog::error("{}", error());
    return kExitConfigError;
  }
  const Clock::time_point start = Clock::now();
  for (Timer& timer : timers_) timer.next = timer.scheduled ? start : start + timer.period;
  AddTimer(options_.heartbeat_period_s, [this] { PublishHeartbeat(); });
  timers_.back().next = start;  // the first heartbeat at once: "ready" for the supervisor
  stop_ = false;
  const int lcm_fd = lcm_->getFileno();
  while (!stop_) {
    const Clock::time_point now = Clock::now();
    if (now >= deadline) break;
    RunDueTimers(now);
    if (stop_) break;
    // ppoll: nanosecond timeouts, so that fast timers (a 500 Hz plant) wake on time rather
    // than on the next millisecond.
    const auto wait = std::min(NextDeadline(), deadline) - Clock::now();
    const std::int64_t wait_ns = std::clamp<std::int64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count(), 0, 60'000'000'000LL);
    const timespec timeout{static_cast<time_t>(wait_ns / 1'000'000'000), static_cast<long>(wait_ns % 1'000'000'000)};
    pollfd fds[2] = {{lcm_fd, POLLIN, 0}, {signals_.fd(), POLLIN, 0}};
    const int ready = ppoll(fds, 2, &timeout, nullptr);
    if (ready < 0 && errno != EINTR) {
      spdlog::error("poll: {}", std::strerror(errno));
      return kExitConfigError;
    }
    if (fds[1].revents & POLLIN) {
      while (const std::optional<int> signal = signals_.Read()) {
        spdlog::info("{}: stopping on signal {}", options_.name, strsignal(*signal));
        stop_ = true;
      }
    }
    if (!stop_ && (fds[0].revents & POLLIN) && lcm_->handleTimeout(0) < 0) {
      spdlog::error("LCM receive failed");
      return kExitConfigError;
    }
  }
  timers_.pop_back();  // the heartbeat timer (RunUntil may be called again)
  return kExitOk;
}

}  // namespace topay::procs
