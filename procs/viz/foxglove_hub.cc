#include "procs/viz/foxglove_hub.h"
#include "procs/viz/json_text.h"

#include <chrono>
#include <set>

namespace topay::viz {
namespace {

using nlohmann::json;

// Binary opcodes (spec: "Message Data" and "Time").
constexpr std::uint8_t kMessageData = 0x01;
constexpr std::uint8_t kTime = 0x02;

void PutLittleEndian(std::string* out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

// Ops of the protocol a client may send that this read-only server does not take.
const std::set<std::string>& UnsupportedOps() {
  static const std::set<std::string> ops = {
      "advertise", "unadvertise", "getParameters", "setParameters", "subscribeParameterUpdates",
      "unsubscribeParameterUpdates", "subscribeConnectionGraph", "unsubscribeConnectionGraph", "fetchAsset"};
  return ops;
}

std::optional<std::uint32_t> Uint32Of(const json& value) {
  if (!value.is_number_integer()) return std::nullopt;
  if (value.is_number_unsigned()) {
    const auto v = value.get<std::uint64_t>();
    return v <= 0xffffffffULL ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(v)) : std::nullopt;
  }
  const auto v = value.get<std::int64_t>();
  return v >= 0 && v <= 0xffffffffLL ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(v)) : std::nullopt;
}

// The unsigned 32-bit integer field `key` of an object, if it is one.
std::optional<std::uint32_t> FieldUint32(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key)) return std::nullopt;
  return Uint32Of(object[key]);
}

}  // namespace

FoxgloveHub::FoxgloveHub(FoxgloveHubOptions options, HubSend send)
    : options_(std::move(options)), send_(std::move(send)), channels_(VizChannels()) {
  json list = json::array();
  for (std::size_t i = 0; i < kNumTopics; ++i) {
    const VizChannel& c = channels_[i];
    list.push_back({{"id", i + 1}, {"topic", c.name}, {"encoding", "json"}, {"schemaName", c.schema_name},
                    {"schema", c.schema}, {"schemaEncoding", "jsonschema"}});
  }
  advertise_ = json{{"op", "advertise"}, {"channels", std::move(list)}}.dump(-1, ' ', false, kReplaceInvalidUtf8);
}

void FoxgloveHub::SetPlaybackHandler(std::function<void(const PlaybackCommand&)> handler) {
  std::lock_guard lock(mutex_);
  playback_ = std::move(handler);
}

void FoxgloveHub::SendText(HubClientId client, const std::string& text) {
  counts_.bytes_sent += static_cast<std::int64_t>(text.size());
  send_(client, std::make_shared<const std::string>(text), false);
}

void FoxgloveHub::Status(HubClientId client, int level, const std::string& message) {
  SendText(client, json{{"op", "status"}, {"level", level}, {"message", message}}.dump(-1, ' ', false, kReplaceInvalidUtf8));
}

void FoxgloveHub::Refuse(HubClientId client, const std::string& why) {
  ++counts_.bad_requests;
  Status(client, 2, why);
}

void FoxgloveHub::OnOpen(HubClientId client) {
  std::lock_guard lock(mutex_);
  clients_[client] = Client{};
  const auto session = std::chrono::system_clock::now().time_since_epoch().count();
  json capabilities = json::array();
  if (options_.replay) capabilities.push_back("time");
  SendText(client, json{{"op", "serverInfo"},
                        {"name", options_.server_name},
                        {"capabilities", std::move(capabilities)},
                        {"metadata", {{"mode", options_.replay ? "replay" : "live"}}},
                        {"sessionId", std::to_string(session)}}
                       .dump(-1, ' ', false, kReplaceInvalidUtf8));
  SendText(client, advertise_);
}

void FoxgloveHub::OnClose(HubClientId client) {
  std::lock_guard lock(mutex_);
  clients_.erase(client);
}

void FoxgloveHub::OnBinary(HubClientId client, std::string_view bytes) {
  std::lock_guard lock(mutex_);
  Refuse(client, "binary client messages (client publishing, service calls) are not supported: "
                 "topay-viz is read-only");
}

void FoxgloveHub::OnText(HubClientId client, std::string_view text) {
  const json request = json::parse(text, nullptr, /*allow_exceptions=*/false);
  std::lock_guard lock(mutex_);
  if (!clients_.count(client)) return;
  if (request.is_discarded() || !request.is_object() || !request.contains("op") || !request["op"].is_string()) {
    return Refuse(client, "malformed request: expected a JSON object with a string \"op\"");
  }
  const std::string op = request["op"].get<std::string>();
  if (op == "subscribe") return Subscribe(client, request);
  if (op == "unsubscribe") return Unsubscribe(client, request);
  if (op == "x-topay-playback") return Playback(client, request);
  if (UnsupportedOps().count(op)) return Refuse(client, "op \"" + op + "\" is not supported: topay-viz is read-only");
  Refuse(client, "unknown op \"" + op.substr(0, 64) + "\"");
}

void FoxgloveHub::Subscribe(HubClientId client, const json& request) {
  if (!request.contains("subscriptions") || !request["subscriptions"].is_array()) {
    return Refuse(client, "subscribe: \"subscriptions\" must be an array");
  }
  Client& c = clients_[client];
  for (const json& s : request["subscriptions"]) {
    const std::optional<std::uint32_t> id = FieldUint32(s, "id");
    const std::optional<std::uint32_t> channel = FieldUint32(s, "channelId");
    if (!id || !channel) {
      Refuse(client, "subscribe: each subscription needs integer \"id\" and \"channelId\"");
      continue;
    }
    const std::uint32_t sub_id = id.value_or(0), channel_id = channel.value_or(0);
    if (channel_id < 1 || channel_id > kNumTopics) {
      Refuse(client, "subscribe: no channel " + std::to_string(channel_id));
      continue;
    }
    if (c.subscriptions.count(sub_id)) {
      Refuse(client, "subscribe: subscription id " + std::to_string(sub_id) + " is in use");
      continue;
    }
    if (c.subscriptions.size() >= options_.max_subscriptions) {
      Refuse(client, "subscribe: at most " + std::to_string(options_.max_subscriptions) + " subscriptions");
      continue;
    }
    const Topic topic = static_cast<Topic>(channel_id - 1);
    c.subscriptions[sub_id] = topic;
    constexpr std::size_t kMaxPendingLatched = 4096;  // a client re-subscribing in a loop
    if (channels_[Index(topic)].latched && pending_latched_.size() < kMaxPendingLatched) {
      pending_latched_.push_back({client, sub_id, topic});
    }
  }
}

void FoxgloveHub::Unsubscribe(HubClientId client, const json& request) {
  if (!request.contains("subscriptionIds") || !request["subscriptionIds"].is_array()) {
    return Refuse(client, "unsubscribe: \"subscriptionIds\" must be an array");
  }
  Client& c = clients_[client];
  for (const json& id : request["subscriptionIds"]) {
    const std::optional<std::uint32_t> sub = Uint32Of(id);
    if (!sub || !c.subscriptions.erase(*sub)) Refuse(client, "unsubscribe: no such subscription");
  }
}

void FoxgloveHub::Playback(HubClientId client, const json& request) {
  if (!options_.replay || !playback_) {
    ++counts_.bad_requests;
    return Status(client, 1, "x-topay-playback: this server is live, not a replay");
  }
  PlaybackCommand command;
  const json& c = request.contains("command") ? request["command"] : json();
  if (!c.is_string()) return Refuse(client, "x-topay-playback: \"command\" must be a string");
  command.command = c.get<std::string>();
  const bool seek = command.command == "seek", speed = command.command == "speed";
  if (!seek && !speed && command.command != "play" && command.command != "pause") {
    return Refuse(client, "x-topay-playback: unknown command");
  }
  const char* key = seek ? "t" : "speed";
  if (seek || speed) {
    if (!request.contains(key) || !request[key].is_number()) {
      return Refuse(client, std::string("x-topay-playback: \"") + key + "\" must be a number");
    }
    (seek ? command.t : command.speed) = request[key].get<double>();
  }
  playback_(command);
}

std::shared_ptr<const std::string> FoxgloveHub::DataFrame(std::uint32_t subscription, std::int64_t log_utime,
                                                          const std::string& payload) const {
  auto frame = std::make_shared<std::string>();
  frame->reserve(13 + payload.size());
  frame->push_back(static_cast<char>(kMessageData));
  PutLittleEndian(frame.get(), subscription, 4);
  PutLittleEndian(frame.get(), static_cast<std::uint64_t>(std::max<std::int64_t>(0, log_utime)) * 1000, 8);
  frame->append(payload);
  return frame;
}

void FoxgloveHub::Publish(Topic topic, std::int64_t log_utime, const std::string& payload) {
  std::lock_guard lock(mutex_);
  for (const auto& [client, c] : clients_) {
    for (const auto& [id, subscribed] : c.subscriptions) {
      if (subscribed != topic) continue;
      std::shared_ptr<const std::string> frame = DataFrame(id, log_utime, payload);
      ++counts_.messages_sent;
      counts_.bytes_sent += static_cast<std::int64_t>(frame->size());
      send_(client, std::move(frame), true);
    }
  }
}

void FoxgloveHub::SendTo(const LatchedRequest& request, std::int64_t log_utime, const std::string& payload) {
  std::lock_guard lock(mutex_);
  const auto it = clients_.find(request.client);
  if (it == clients_.end() || !it->second.subscriptions.count(request.subscription)) return;
  std::shared_ptr<const std::string> frame = DataFrame(request.subscription, log_utime, payload);
  ++counts_.messages_sent;
  counts_.bytes_sent += static_cast<std::int64_t>(frame->size());
  send_(request.client, std::move(frame), true);
}

void FoxgloveHub::PublishTime(std::int64_t utime) {
  std::lock_guard lock(mutex_);
  for (const auto& [client, c] : clients_) {
    auto frame = std::make_shared<std::string>();
    frame->push_back(static_cast<char>(kTime));
    PutLittleEndian(frame.get(), static_cast<std::uint64_t>(std::max<std::int64_t>(0, utime)) * 1000, 8);
    counts_.bytes_sent += static_cast<std::int64_t>(frame->size());
    send_(client, std::move(frame), true);
  }
}

std::vector<LatchedRequest> FoxgloveHub::TakePendingLatched() {
  std::lock_guard lock(mutex_);
  return std::exchange(pending_latched_, {});
}

std::vector<LatchedRequest> FoxgloveHub::LatchedSubscriptions() const {
  std::lock_guard lock(mutex_);
  std::vector<LatchedRequest> all;
  for (const auto& [client, c] : clients_) {
    for (const auto& [id, topic] : c.subscriptions) {
      if (channels_[Index(topic)].latched) all.push_back({client, id, topic});
    }
  }
  return all;
}

FoxgloveHubCounts FoxgloveHub::counts() const {
  std::lock_guard lock(mutex_);
  FoxgloveHubCounts c = counts_;
  c.clients = static_cast<std::int64_t>(clients_.size());
  return c;
}

}  // namespace topay::viz
