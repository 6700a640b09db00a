// The Foxglove protocol layer (procs/viz/foxglove_hub.h) against a recording transport:
// serverInfo and advertise, subscriptions, message data frames byte by byte, latched
// requests, replay commands, and hostile client messages.

#include "procs/viz/foxglove_hub.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <random>

namespace topay::viz {
namespace {

using nlohmann::json;

struct Sent {
  HubClientId client;
  std::string bytes;
  bool binary;
};

class HubTest : public ::testing::Test {
 protected:
  explicit HubTest(bool replay = false)
      : hub_({.server_name = "test", .replay = replay},
             [this](HubClientId c, std::shared_ptr<const std::string> b, bool binary) {
               sent_.push_back({c, *b, binary});
             }) {}

  std::vector<json> TextsTo(HubClientId client) const {
    std::vector<json> out;
    for (const Sent& s : sent_) {
      if (s.client == client && !s.binary) out.push_back(json::parse(s.bytes));
    }
    return out;
  }
  json LastStatus(HubClientId client) const {
    const std::vector<json> texts = TextsTo(client);
    for (auto it = texts.rbegin(); it != texts.rend(); ++it) {
      if ((*it)["op"] == "status") return *it;
    }
    return json();
  }
  void Subscribe(HubClientId client, std::uint32_t id, Topic topic) {
    hub_.OnText(client, json{{"op", "subscribe"},
                             {"subscriptions", {{{"id", id}, {"channelId", Index(topic) + 1}}}}}.dump());
  }

  FoxgloveHub hub_;
  std::vector<Sent> sent_;
};

std::uint64_t LittleEndian(const std::string& bytes, std::size_t at, int size) {
  std::uint64_t v = 0;
  for (int i = size - 1; i >= 0; --i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

TEST_F(HubTest, GreetsAClientWithServerInfoAndEveryChannel) {
  hub_.OnOpen(1);
  const std::vector<json> texts = TextsTo(1);
  ASSERT_EQ(texts.size(), 2u);
  EXPECT_EQ(texts[0]["op"], "serverInfo");
  EXPECT_EQ(texts[0]["name"], "test");
  EXPECT_TRUE(texts[0]["capabilities"].empty());  // live: no time, no publishing
  EXPECT_EQ(texts[1]["op"], "advertise");
  const json& channels = texts[1]["channels"];
  ASSERT_EQ(channels.size(), kNumTopics);
  std::set<std::string> topics;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    EXPECT_EQ(channels[i]["id"], i + 1);
    EXPECT_EQ(channels[i]["encoding"], "json");
    EXPECT_EQ(channels[i]["schemaEncoding"], "jsonschema");
    const json schema = json::parse(channels[i]["schema"].get<std::string>());  // a JSON schema
    EXPECT_EQ(schema["type"], "object") << channels[i]["topic"];
    EXPECT_TRUE(topics.insert(channels[i]["topic"].get<std::string>()).second);
  }
  EXPECT_TRUE(topics.count("/robot/state") && topics.count("/map/blocks") && topics.count("/lidar/scan"));
}

TEST_F(HubTest, SendsMessageDataFramesOnlyToSubscribers) {
  hub_.OnOpen(1);
  hub_.OnOpen(2);
  Subscribe(1, 42, Topic::kRobotState);
  sent_.clear();
  hub_.Publish(Topic::kRobotState, 1'700'000'000'123'456, R"({"x_m":1})");
  hub_.Publish(Topic::kScan, 1'700'000'000'200'000, R"({"count":0})");  // nobody subscribed
  ASSERT_EQ(sent_.size(), 1u);
  const Sent& frame = sent_[0];
  EXPECT_EQ(frame.client, 1u);
  EXPECT_TRUE(frame.binary);
  ASSERT_EQ(frame.bytes.size(), 13u + 9u);
  EXPECT_EQ(static_cast<std::uint8_t>(frame.bytes[0]), 0x01);          // message data
  EXPECT_EQ(LittleEndian(frame.bytes, 1, 4), 42u);                      // subscription id
  EXPECT_EQ(LittleEndian(frame.bytes, 5, 8), 1'700'000'000'123'456'000ull);  // log time, ns
  EXPECT_EQ(frame.bytes.substr(13), R"({"x_m":1})");
  hub_.OnText(1, R"({"op":"unsubscribe","subscriptionIds":[42]})");
  sent_.clear();
  hub_.Publish(Topic::kRobotState, 1, "{}");
  EXPECT_TRUE(sent_.empty());
  EXPECT_EQ(hub_.counts().messages_sent, 1);
}

TEST_F(HubTest, QueuesLatchedRequestsForNewSubscriptionsOfLatchedChannels) {
  hub_.OnOpen(1);
  Subscribe(1, 1, Topic::kMapBlocks);
  Subscribe(1, 2, Topic::kPlotSample);  // not latched
  const std::vector<LatchedRequest> pending = hub_.TakePendingLatched();
  ASSERT_EQ(pending.size(), 1u);
  EXPECT_EQ(pending[0].client, 1u);
  EXPECT_EQ(pending[0].subscription, 1u);
  EXPECT_EQ(pending[0].topic, Topic::kMapBlocks);
  EXPECT_TRUE(hub_.TakePendingLatched().empty());
  sent_.clear();
  hub_.SendTo(pending[0], 5, "{}");
  ASSERT_EQ(sent_.size(), 1u);
  EXPECT_EQ(LittleEndian(sent_[0].bytes, 1, 4), 1u);
  hub_.OnClose(1);
  sent_.clear();
  hub_.SendTo(pending[0], 5, "{}");  // gone meanwhile: nothing
  EXPECT_TRUE(sent_.empty());
  EXPECT_EQ(hub_.LatchedSubscriptions().size(), 0u);
}

TEST_F(HubTest, RefusesBadSubscriptionsWithAStatusEach) {
  hub_.OnOpen(1);
  Subscribe(1, 7, Topic::kGoal);
  Subscribe(1, 7, Topic::kScan);  // id in use
  EXPECT_EQ(LastStatus(1)["level"], 2);
  EXPECT_NE(LastStatus(1)["message"].get<std::string>().find("in use"), std::string::npos);
  hub_.OnText(1, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":999}]})");
  EXPECT_NE(LastStatus(1)["message"].get<std::string>().find("no channel 999"), std::string::npos);
  hub_.OnText(1, R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1},{"id":2}]})");
  hub_.OnText(1, R"({"op":"subscribe","subscriptions":[{"id":1e30,"channelId":1}]})");
  hub_.OnText(1, R"({"op":"subscribe","subscriptions":"all"})");
  EXPECT_EQ(hub_.counts().bad_requests, 6);
  EXPECT_EQ(hub_.LatchedSubscriptions().size(), 1u);  // only the first
}

TEST_F(HubTest, IsReadOnly) {
  hub_.OnOpen(1);
  hub_.OnText(1, R"({"op":"advertise","channels":[{"id":1,"topic":"CONTROL_COMMAND","encoding":"json"}]})");
  EXPECT_NE(LastStatus(1)["message"].get<std::string>().find("read-only"), std::string::npos);
  hub_.OnBinary(1, std::string("\x01\x01\x00\x00\x00{}", 7));  // client message data
  EXPECT_NE(LastStatus(1)["message"].get<std::string>().find("read-only"), std::string::npos);
  hub_.OnText(1, R"({"op":"setParameters","parameters":[]})");
  EXPECT_EQ(hub_.counts().bad_requests, 3);
}

TEST_F(HubTest, AnswersReplayCommandsOnALiveServerWithAWarning) {
  hub_.OnOpen(1);
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"pause"})");
  EXPECT_EQ(LastStatus(1)["level"], 1);
}

class ReplayHubTest : public HubTest {
 protected:
  ReplayHubTest() : HubTest(true) {}
};

TEST_F(ReplayHubTest, ForwardsWellFormedReplayCommands) {
  std::vector<PlaybackCommand> commands;
  hub_.SetPlaybackHandler([&](const PlaybackCommand& c) { commands.push_back(c); });
  hub_.OnOpen(1);
  EXPECT_EQ(TextsTo(1)[0]["capabilities"], json::array({"time"}));
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"seek","t":1700000001.5})");
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"speed","speed":4})");
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"play"})");
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"seek"})");           // no t
  hub_.OnText(1, R"({"op":"x-topay-playback","command":"rewind-forever"})");
  hub_.OnText(1, R"({"op":"x-topay-playback","command":7})");
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0].command, "seek");
  EXPECT_DOUBLE_EQ(commands[0].t, 1700000001.5);
  EXPECT_DOUBLE_EQ(commands[1].speed, 4.0);
  EXPECT_EQ(commands[2].command, "play");
  EXPECT_EQ(hub_.counts().bad_requests, 3);
  sent_.clear();
  hub_.PublishTime(1'700'000'001'000'000);
  ASSERT_EQ(sent_.size(), 1u);
  EXPECT_EQ(static_cast<std::uint8_t>(sent_[0].bytes[0]), 0x02);
  EXPECT_EQ(LittleEndian(sent_[0].bytes, 1, 8), 1'700'000'001'000'000'000ull);
}

TEST_F(HubTest, SurvivesHostileText) {
  hub_.OnOpen(1);
  hub_.OnText(2, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");  // never opened
  std::mt19937 rng(3);
  std::vector<std::string> hostile = {"", "{", "null", "[]", "42", R"({"op":5})", R"({"op":"subscribe"})",
                                      std::string(60000, '['), std::string(60000, '{'),
                                      std::string("{\"op\":\"subscribe\"\0}", 19),
                                      R"({"op":"unsubscribe","subscriptionIds":[1,2,"x",{}]})"};
  for (int i = 0; i < 200; ++i) {
    std::string garbage(rng() % 300, '\0');
    for (char& c : garbage) c = static_cast<char>(rng());
    hostile.push_back(garbage);
  }
  for (const std::string& text : hostile) hub_.OnText(1, text);
  EXPECT_GE(hub_.counts().bad_requests, static_cast<std::int64_t>(hostile.size()));
  EXPECT_EQ(hub_.counts().clients, 1);
  Subscribe(1, 9, Topic::kGoal);  // and it still works
  sent_.clear();
  hub_.Publish(Topic::kGoal, 1, "{}");
  EXPECT_EQ(sent_.size(), 1u);
}

}  // namespace
}  // namespace topay::viz
