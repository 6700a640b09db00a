#pragma once
// The viewer's data path from messages to clients, shared by the live server and the log
// replay: the pipeline's payloads go to the hub's subscribers; new subscribers to a latched
// channel get its current message on the next Tick; VizStats and Playback are published from
// here. Runs on one thread (the LCM loop's or the replay's).

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "procs/viz/foxglove_hub.h"
#include "procs/viz/viz_pipeline.h"

namespace topay::viz {

/// What the transport counted (procs/viz/server), for VizStats.
struct TransportCounts {
  std::int64_t clients = 0;
  std::int64_t frames_sent = 0;
  std::int64_t frames_dropped = 0;  ///< dropped from full client queues (slow clients)
  std::int64_t bytes_sent = 0;
};

/// The replay clock as Playback shows it.
struct PlaybackState {
  bool replay = false;
  double t = 0.0, start_t = 0.0, end_t = 0.0;  ///< s since the epoch
  bool playing = false;
  double speed = 1.0;
  /// Seeks so far: when it changes, a client drops what it drew (the latched channels that
  /// had a message by the new time are resent; the others had none then).
  int seeks = 0;
};

class VizFeed {
 public:
  VizFeed(const RobotView& robot, const VizPipelineOptions& options, FoxgloveHub* hub);

  /// One LCM message (raw bytes) received / logged at utime.
  void Handle(std::string_view channel, const void* data, std::size_t size, std::int64_t utime) {
    pipeline_.Handle(channel, data, size, utime);
  }

  /// Serves new subscribers their latched messages, then forwards what is due.
  void Tick(std::int64_t now_utime);
  /// Serves new subscribers their latched messages (as they stand now).
  void ServeNewSubscribers(std::int64_t now_utime);

  /// Forgets every message (a replay's seek).
  void Reset() { pipeline_.Reset(); }
  /// While muted, payloads update the latched state but go to no client (a seek's catch-up).
  void SetMuted(bool muted) { muted_ = muted; }
  /// Forwards what waited (the map's changed blocks included), without serving subscribers.
  void Flush(std::int64_t now_utime) { pipeline_.Flush(now_utime); }
  /// Sends every subscriber of a latched channel its current message (after a seek).
  void ResendLatched(std::int64_t now_utime);

  /// Publishes VizStats (bytes_per_s over the time since the last call).
  void PublishStats(std::int64_t now_utime, const TransportCounts& transport);
  void PublishPlayback(std::int64_t now_utime, const PlaybackState& state);

  const VizPipeline& pipeline() const { return pipeline_; }
  /// A one-line status for the heartbeat.
  std::string StatusLine(const TransportCounts& transport) const;

 private:
  void Serve(const LatchedRequest& request, std::int64_t now_utime);

  FoxgloveHub* hub_;
  bool muted_ = false;
  VizPipeline pipeline_;
  std::int64_t last_stats_utime_ = 0;
  std::int64_t last_stats_bytes_ = 0;
};

}  // namespace topay::viz
