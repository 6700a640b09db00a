#pragma once
// The Foxglove WebSocket protocol v1 (subprotocol foxglove.websocket.v1) on the server side,
// above the transport: per client, serverInfo and advertise on connect, its subscriptions, the
// message data frames of the channels it subscribed to, and refusals of what a read-only server
// does not take (client publishing, services, parameters), each as a status message. Also the
// replay controls of our own page ("x-topay-playback"). Thread-safe: the transport's thread
// calls On*, the LCM thread Publish and TakePendingLatched.

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "procs/viz/viz_channels.h"

namespace topay::viz {

using HubClientId = std::uint64_t;

/// What the hub asks its transport to send (a text or a binary WebSocket message).
using HubSend = std::function<void(HubClientId client, std::shared_ptr<const std::string> bytes, bool binary)>;

/// A replay command from a client: "play", "pause", "seek" (t, s since the epoch) or "speed".
struct PlaybackCommand {
  std::string command;
  double t = 0.0;
  double speed = 1.0;
};

/// A subscription that needs its channel's latched message (sent by the LCM thread).
struct LatchedRequest {
  HubClientId client = 0;
  std::uint32_t subscription = 0;
  Topic topic = Topic::kCount;
};

struct FoxgloveHubOptions {
  std::string server_name = "topay-viz";
  bool replay = false;                  ///< advertise the "time" capability; accept playback
  std::size_t max_subscriptions = 64;   ///< per client
};

struct FoxgloveHubCounts {
  std::int64_t clients = 0;          ///< connected now
  std::int64_t messages_sent = 0;    ///< message data frames
  std::int64_t bytes_sent = 0;       ///< of every frame handed to the transport
  std::int64_t bad_requests = 0;     ///< malformed or refused client messages
};

class FoxgloveHub {
 public:
  FoxgloveHub(FoxgloveHubOptions options, HubSend send);

  /// Our page's replay controls go here (replay mode only; live: a status warning).
  void SetPlaybackHandler(std::function<void(const PlaybackCommand&)> handler);

  // Transport events.
  void OnOpen(HubClientId client);
  void OnText(HubClientId client, std::string_view text);
  void OnBinary(HubClientId client, std::string_view bytes);
  void OnClose(HubClientId client);

  /// Sends a channel's message to every client subscribed to it (log time in us).
  void Publish(Topic topic, std::int64_t log_utime, const std::string& payload);
  /// Sends one message to one subscription (a latched message for a new subscriber).
  void SendTo(const LatchedRequest& request, std::int64_t log_utime, const std::string& payload);
  /// Sends a binary time message (replay clock) to every client.
  void PublishTime(std::int64_t utime);
  /// The subscriptions made since the last call whose channel is latched.
  std::vector<LatchedRequest> TakePendingLatched();
  /// Every current subscription to a latched channel (a replay's seek resends them all).
  std::vector<LatchedRequest> LatchedSubscriptions() const;

  FoxgloveHubCounts counts() const;

 private:
  struct Client {
    std::map<std::uint32_t, Topic> subscriptions;  // subscription id -> channel
  };
  void SendText(HubClientId client, const std::string& text);
  void Status(HubClientId client, int level, const std::string& message);
  void Refuse(HubClientId client, const std::string& why);
  void Subscribe(HubClientId client, const nlohmann::json& request);
  void Unsubscribe(HubClientId client, const nlohmann::json& request);
  void Playback(HubClientId client, const nlohmann::json& request);
  std::shared_ptr<const std::string> DataFrame(std::uint32_t subscription, std::int64_t log_utime,
                                               const std::string& payload) const;

  FoxgloveHubOptions options_;
  HubSend send_;
  std::array<VizChannel, kNumTopics> channels_;
  std::string advertise_;  // the advertise message (all channels)
  mutable std::mutex mutex_;
  std::map<HubClientId, Client> clients_;
  std::vector<LatchedRequest> pending_latched_;
  std::function<void(const PlaybackCommand&)> playback_;
  FoxgloveHubCounts counts_;
};

}  // namespace topay::viz
