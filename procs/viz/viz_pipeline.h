#pragma once
// The graph's LCM messages -> the viewer's channels (docs/viewer.md): decodes each message of
// a known channel (topay::CheckedDecode; malformed ones are counted and dropped), turns it into
// its channel's JSON payload and forwards it no faster than the channel's rate (the latest
// message wins; one that waits goes out on the next Flush once its interval has passed). The
// map goes as the blocks that changed; scans downsampled; a trajectory once per id. The same
// pipeline feeds the live server, the log replay and the MCAP conversion (rates 0: every
// message). Single-threaded: the owner's thread calls everything.

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/robot/whole_body_state.h"
#include "procs/viz/map_blocks.h"
#include "procs/viz/robot_view.h"
#include "procs/viz/scan_view.h"
#include "procs/viz/trajectory_view.h"
#include "procs/viz/viz_channels.h"

namespace topay::viz {

/// Highest rate of each channel to the browser, Hz (0: every message). config/viz/viz.yaml.
struct VizRates {
  double robot_state_hz = 30.0;
  double map_hz = 2.0;
  double scan_hz = 5.0;
  double plot_hz = 20.0;
  double status_hz = 10.0;  ///< planner, tracker and mission status
  double drive_hz = 5.0;
  double sim_hz = 2.0;
  /// Every channel at every message (the MCAP conversion).
  static VizRates Unlimited() { return {0, 0, 0, 0, 0, 0, 0}; }
};

struct VizPipelineOptions {
  VizRates rates;
  ScanViewOptions scan;
  TrajectoryViewOptions trajectory;
  int max_contacts = 500;  ///< contacts kept in the Contacts payload (the newest)
};

/// Messages seen per outcome.
struct VizPipelineCounts {
  std::int64_t messages = 0;   ///< of a channel the viewer shows
  std::int64_t malformed = 0;  ///< failed CheckedDecode or the conversion's checks
  std::int64_t ignored = 0;    ///< other channels
  std::int64_t emitted = 0;    ///< payloads forwarded
  std::string last_error;      ///< "<CHANNEL>: <why>" of the last malformed message
};

class VizPipeline {
 public:
  /// Called with each payload to forward: its channel, the time it stands for (the message's
  /// receive / log time, us since the epoch) and the JSON text.
  using Sink = std::function<void(Topic topic, std::int64_t log_utime, const std::string& payload)>;

  VizPipeline(const RobotView& robot, const VizPipelineOptions& options, Sink sink);

  /// One LCM message as received (raw bytes) at recv_utime.
  void Handle(std::string_view channel, const void* data, std::size_t size, std::int64_t recv_utime);

  /// Forwards what waited for its interval and the map's changed blocks when due. Call often
  /// (30 Hz live; after the last message in a conversion) with the current (log) time.
  void Flush(std::int64_t now_utime);

  /// The last payload of a latched channel (the map: the whole map as one reset); nullopt if
  /// none yet or the channel is not latched.
  std::optional<std::string> Latched(Topic topic) const;

  /// The robot description payload (always there).
  const std::string& description() const { return description_; }

  /// Forgets everything but the robot (a replay's seek starts again from the log's start).
  void Reset();

  const VizPipelineCounts& counts() const { return counts_; }

 private:
  struct TopicState {
    std::int64_t min_interval_us = 0;  // 0: every message
    std::int64_t last_emit_utime = 0;
    bool emitted_once = false;
    std::optional<std::pair<std::int64_t, std::string>> waiting;  // (log time, payload)
    std::string last;                                             // latched
  };
  void Offer(Topic topic, std::int64_t log_utime, std::string payload);
  void Emit(Topic topic, std::int64_t log_utime, std::string payload);
  bool Due(const TopicState& state, std::int64_t utime) const;
  void Malformed(std::string_view channel, const std::string& why);
  void HandleRobotState(const void* data, std::size_t size, std::int64_t recv_utime);
  void HandleMap(const void* data, std::size_t size, std::int64_t recv_utime);
  void HandleTrajectory(const void* data, std::size_t size, std::int64_t recv_utime);
  void HandleContact(const void* data, std::size_t size, std::int64_t recv_utime);
  void HandleScan(const void* data, std::size_t size, std::int64_t recv_utime);
  template <class Msg>
  void HandleStatus(std::string_view channel, const void* data, std::size_t size, std::int64_t recv_utime,
                    Topic topic, nlohmann::json (*to_json)(const Msg&));

  const RobotView& robot_;
  VizPipelineOptions options_;
  Sink sink_;
  std::string description_;
  std::array<TopicState, kNumTopics> topics_;
  MapBlocks map_;
  std::int64_t map_utime_ = 0;
  TrajectoryView trajectory_;
  std::optional<WholeBodyState> robot_state_;
  nlohmann::json contacts_ = nlohmann::json::array();
  std::int64_t contact_count_ = 0;
  VizPipelineCounts counts_;
};

}  // namespace topay::viz
