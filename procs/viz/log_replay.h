#pragma once
// topay-viz --log FILE: a recorded LCM log served as if live, under the page's play / pause /
// speed / seek (docs/viewer.md). Messages go through the same VizFeed as live ones, stamped with
// their log times. A seek (or a play from the end) starts the log again from its beginning with
// the clients muted, up to the new time, so the map, the trajectory, the contacts and every
// status are as they stood then; the latched channels are then resent to every subscriber.

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "procs/viz/foxglove_hub.h"
#include "procs/viz/replay_clock.h"
#include "procs/viz/viz_feed.h"

namespace topay::viz {

/// The log's span and size, from one pass over it.
struct LogSpan {
  std::int64_t first_utime = 0, last_utime = 0;
  std::int64_t events = 0;
};

/// Reads the log once; throws std::runtime_error naming the file if it cannot be opened or
/// holds no event.
LogSpan ScanLog(const std::string& path);

class LogReplay {
 public:
  /// `feed` and the path must outlive this. Throws like ScanLog. Starts playing at the
  /// log's start unless `paused`.
  LogReplay(const std::string& path, VizFeed* feed, bool paused, double speed);

  /// Queues a page's command (any thread; applied on the next Tick).
  void Command(const PlaybackCommand& command);

  /// Applies queued commands, feeds the events up to the clock's time and serves the clients.
  /// `wall_utime`: now.
  void Tick(std::int64_t wall_utime);

  /// The clock as Playback shows it.
  PlaybackState State(std::int64_t wall_utime);

  std::int64_t events_fed() const { return events_fed_; }

 private:
  void Apply(const PlaybackCommand& command, std::int64_t wall_utime);
  void Restart();                           // reopens the log at its start, feed reset
  void FeedUntil(std::int64_t log_utime);   // every event with timestamp <= log_utime
  // A seek: a muted feed up to log_utime, the new Playback (so that clients drop what they
  // drew), then the latched channels resent.
  void CatchUp(std::int64_t log_utime, std::int64_t wall_utime);

  std::string path_;
  VizFeed* feed_;
  LogSpan span_;
  ReplayClock clock_;
  std::unique_ptr<lcm::LogFile> log_;
  struct Event {
    std::int64_t utime = 0;
    std::string channel;
    std::vector<std::uint8_t> data;
  };
  bool ReadNext();                          // into next_; false at the end of the log
  std::optional<Event> next_;               // read, not yet fed
  std::int64_t fed_until_ = 0;
  std::int64_t events_fed_ = 0;
  int seeks_ = 0;
  bool play_on_first_tick_ = false;
  std::mutex commands_mutex_;
  std::deque<PlaybackCommand> commands_;
};

}  // namespace topay::viz
