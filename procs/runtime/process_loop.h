#pragma once
// The event loop of every process of the graph: one thread waits (poll) on the LCM file
// descriptor, on a signalfd for SIGINT/SIGTERM and on the next timer deadline, so an idle
// process sleeps. It publishes the HEARTBEAT (and with it a watchdog datagram to the launcher,
// watchdog_notify.h) and dispatches typed, checked subscriptions.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "procs/runtime/channel_stats.h"
#include "procs/runtime/process_options.h"
#include "procs/runtime/signal_fd.h"
#include "procs/runtime/watchdog_notify.h"
#include "topay_msgs/checked_decode.h"

namespace topay::procs {

/// Microseconds since the Unix epoch (the utime of every message).
std::int64_t NowUtime();

class ProcessLoop {
 public:
  using Clock = std::chrono::steady_clock;

  /// Opens LCM on options.lcm_url and blocks SIGINT/SIGTERM into a signalfd (construct it in
  /// main before any thread starts). Tries mlockall if options.mlockall (a warning if it is
  /// not permitted). Check ok() before Run().
  explicit ProcessLoop(const ProcessOptions& options);

  /// False if LCM could not be opened (e.g. no multicast route); error() says why.
  bool ok() const { return lcm_->good(); }
  std::string error() const;

  lcm::LCM& lcm() { return *lcm_; }
  const ProcessOptions& options() const { return options_; }
  ChannelStats& stats() { return stats_; }

  /// Calls `callback` every period_s seconds (first call one period after Run starts). Add
  /// timers before Run, not from a callback. A late timer skips to the next period (no burst).
  void AddTimer(double period_s, std::function<void()> callback);

  /// A timer that schedules itself: `callback` runs first when Run starts and returns when it
  /// wants to run next (e.g. the due time of the next plant step), so that a late wake-up does
  /// not shift its later deadlines as a fixed period would. Add it before Run.
  void AddScheduledTimer(std::function<Clock::time_point()> callback);

  /// Subscribes to `channel` decoding each message with CheckedDecode<Msg>; a message that
  /// fails is counted and logged (ChannelStats) and never reaches `handler`. Returns the LCM
  /// subscription (e.g. to change its queue capacity: LCM's default keeps 30 messages not yet
  /// handled and drops the rest).
  template <class Msg>
  lcm::Subscription* Subscribe(const std::string& channel, std::function<void(const Msg&)> handler);

  /// Handles the LCM messages already received, at most max_messages, without waiting (from a
  /// timer about to act on what arrived: the simulator after a stall). Returns how many were
  /// handled, or -1 if LCM failed.
  int HandlePending(int max_messages);

  /// Health and status text of the next heartbeats (heartbeat_t::OK/WARN/ERROR).
  void SetHealth(std::int8_t health, std::string status);

  /// Runs until SIGINT/SIGTERM or Stop(); publishes a heartbeat at once and then every
  /// heartbeat period. Returns the exit code: 0 (clean stop), 1 if LCM failed.
  int Run();
  /// Ends Run() after the current callback (for handlers and tests).
  void Stop() { stop_ = true; }
  /// Runs at most until `deadline` (tests): like Run(), but also returns at the deadline.
  int RunUntil(Clock::time_point deadline);

  std::int64_t heartbeats_sent() const { return heartbeat_seq_; }

 private:
  struct Timer {
    std::chrono::nanoseconds period;
    Clock::time_point next;
    std::function<void()> callback;
    std::function<Clock::time_point()> scheduled;  // AddScheduledTimer (then no period)
  };
  void PublishHeartbeat();
  void RunDueTimers(Clock::time_point now);
  Clock::time_point NextDeadline() const;

  ProcessOptions options_;
  SignalFd signals_;  // before LCM: any thread LCM may start inherits the blocked signals
  std::unique_ptr<lcm::LCM> lcm_;
  ChannelStats stats_;
  std::vector<Timer> timers_;
  std::vector<std::shared_ptr<void>> handlers_;  // keep the subscription closures alive
  std::int8_t health_ = 0;
  std::string status_ = "starting";
  std::int64_t heartbeat_seq_ = 0;
  WatchdogNotifier watchdog_;  // "WATCHDOG=1" to the launcher with every heartbeat (NOTIFY_SOCKET)
  bool watchdog_warned_ = false;
  bool stop_ = false;
};

template <class Msg>
lcm::Subscription* ProcessLoop::Subscribe(const std::string& channel, std::function<void(const Msg&)> handler) {
  struct Dispatch {
    ChannelStats* stats;
    std::function<void(const Msg&)> handler;
    void Handle(const lcm::ReceiveBuffer* rbuf, const std::string& channel_name) {
      std::string error;
      std::optional<Msg> msg = CheckedDecode<Msg>(rbuf->data, rbuf->data_size, &error);
      if (!msg) {
        stats->CountMalformed(channel_name, error);
        return;
      }
      stats->CountGood(channel_name);
      handler(*msg);
    }
  };
  auto dispatch = std::make_shared<Dispatch>(Dispatch{&stats_, std::move(handler)});
  lcm::Subscription* subscription = lcm_->subscribe(channel, &Dispatch::Handle, dispatch.get());
  handlers_.push_back(dispatch);
  return subscription;
}

}  // namespace topay::procs
