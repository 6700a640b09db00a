#pragma once
// Plays an LCM log into the graph's bus: real time scaled by a speed factor, from a start
// offset, only the channels matching a filter, leaving out the channels that the replayed
// processes publish themselves.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdint>
#include <memory>
#include <regex>
#include <set>
#include <string>

namespace topay::launch {

struct ReplayOptions {
  std::string log_path;         ///< the LCM log to play
  double speed = 1.0;           ///< factor on the recorded pace; <= 0: as fast as possible
  double start_offset_s = 0.0;  ///< skip the first start_offset_s seconds of the log
  std::string channels = ".*";  ///< regular expression (whole name) of the channels to play
  double linger_s = 1.0;        ///< after the last message: time before the graph is stopped
};

class LogPlayer {
 public:
  using Clock = std::chrono::steady_clock;

  /// Opens the log; throws std::runtime_error naming the file if it cannot be read.
  /// `excluded`: channels never played (the graph's own outputs).
  LogPlayer(const ReplayOptions& options, std::set<std::string> excluded);

  /// Starts the clock: the first played message goes out now.
  void Start(Clock::time_point now);
  bool started() const { return started_; }
  /// Publishes every message due at `now`. Returns true once the log is exhausted.
  bool Pump(Clock::time_point now, lcm::LCM* lcm);
  /// When the next message is due (time_point::max() when done or not started).
  Clock::time_point NextDue() const;
  bool done() const { return done_; }
  std::int64_t published() const { return published_; }
  std::int64_t skipped() const { return skipped_; }

 private:
  bool Advance();   // reads the next playable event into next_; false at the end
  bool Playable();  // next_ is at or after the start offset, passes the filter, not excluded

  ReplayOptions options_;
  std::set<std::string> excluded_;
  std::regex filter_;
  std::unique_ptr<lcm::LogFile> log_;
  const lcm::LogEvent* next_ = nullptr;
  std::int64_t begin_utime_ = 0;   // log time of the start offset
  std::int64_t first_utime_ = -1;  // log time that maps to start_
  Clock::time_point start_;
  bool started_ = false;
  bool done_ = false;
  std::int64_t published_ = 0;
  std::int64_t skipped_ = 0;
};

}  // namespace topay::launch
