// Typed subscriptions of the process library (ProcessLoop::Subscribe): on every channel of the
// catalogue, malformed, truncated, oversized and wrong-type payloads are counted and logged,
// never reach the handler, and the loop goes on to deliver the next good message.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "../../lcm/sample_messages.h"
#include "procs/runtime/process_loop.h"
#include "topay/graph_status_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::procs {
namespace {

using test::Encode;
using test::MessageSample;

// The channel of each catalogue type that has one (whole_body_state_t has none).
template <class Msg> std::string_view ChannelOf();
template <> std::string_view ChannelOf<base_pose_t>() { return channels::BASE_POSE; }
template <> std::string_view ChannelOf<base_velocity_t>() { return channels::BASE_VELOCITY; }
template <> std::string_view ChannelOf<joint_state_t>() { return channels::JOINT_STATE; }
template <> std::string_view ChannelOf<robot_state_t>() { return channels::ROBOT_STATE; }
template <> std::string_view ChannelOf<point_cloud_t>() { return channels::POINT_CLOUD; }
template <> std::string_view ChannelOf<map_update_t>() { return channels::MAP_UPDATE; }
template <> std::string_view ChannelOf<goal_t>() { return channels::GOAL; }
template <> std::string_view ChannelOf<poly_trajectory_t>() { return channels::TRAJECTORY; }
template <> std::string_view ChannelOf<control_command_t>() { return channels::CONTROL_COMMAND; }
template <> std::string_view ChannelOf<planner_status_t>() { return channels::PLANNER_STATUS; }
template <> std::string_view ChannelOf<heartbeat_t>() { return channels::HEARTBEAT; }
template <> std::string_view ChannelOf<graph_status_t>() { return channels::GRAPH_STATUS; }
template <> std::string_view ChannelOf<tracker_status_t>() { return channels::TRACKER_STATUS; }

template <class Msg>
class CheckedSubscription : public testing::Test {};
using ChannelTypes = testing::Types<base_pose_t, base_velocity_t, joint_state_t, robot_state_t, point_cloud_t,
                                    map_update_t, goal_t, poly_trajectory_t, control_command_t, planner_status_t,
                                    heartbeat_t, graph_status_t, tracker_status_t>;
TYPED_TEST_SUITE(CheckedSubscription, ChannelTypes, test::MessageTypeName);

// Every bad payload for Msg: garbage, truncated, trailing bytes, huge, and another type.
template <class Msg>
std::vector<std::vector<std::uint8_t>> BadPayloads() {
  const std::vector<std::uint8_t> good = Encode(MessageSample<Msg>::Make());
  std::vector<std::vector<std::uint8_t>> bad;
  std::mt19937 rng(7);
  std::vector<std::uint8_t> garbage(200);
  for (auto& b : garbage) b = static_cast<std::uint8_t>(rng());
  bad.push_back(garbage);                                        // malformed
  bad.push_back({});                                             // empty
  bad.emplace_back(good.begin(), good.end() - 1);                // truncated by one byte
  bad.emplace_back(good.begin(), good.begin() + good.size() / 2);  // truncated by half
  std::vector<std::uint8_t> trailing = good;
  trailing.push_back(0);
  bad.push_back(trailing);                                       // oversized by one byte
  std::vector<std::uint8_t> huge = good;
  huge.resize(4 << 20, 0xff);
  bad.push_back(huge);                                           // oversized, 4 MB
  if constexpr (std::is_same_v<Msg, heartbeat_t>) {
    bad.push_back(Encode(MessageSample<robot_state_t>::Make()));  // wrong type
  } else {
    bad.push_back(Encode(MessageSample<heartbeat_t>::Make()));
  }
  std::vector<std::uint8_t> flipped = good;
  for (std::size_t i = 8; i < flipped.size(); i += 3) flipped[i] ^= 0xa5;
  bad.push_back(flipped);  // corrupted after a right fingerprint (may still decode: not counted)
  return bad;
}

TYPED_TEST(CheckedSubscription, CountsAndDropsBadPayloadsAndKeepsGoing) {
  using Msg = TypeParam;
  ProcessOptions options;
  options.name = "subscriber";
  options.lcm_url = "memq://";
  ProcessLoop loop(options);
  const std::string channel(ChannelOf<Msg>());
  int delivered = 0;
  loop.Subscribe<Msg>(channel, [&](const Msg& msg) {
    ++delivered;
  });
  const std::vector<std::vector<std::uint8_t>> bad = BadPayloads<Msg>();
  for (const auto& payload : bad) {
    loop.lcm().publish(channel, payload.data(), static_cast<unsigned>(payload.size()));
  }
  const Msg good = MessageSample<Msg>::Make();
  loop.lcm().publish(channel, &good);
  while (loop.lcm().handleTimeout(0) > 0) {
  }
  const ChannelCounts& counts = loop.stats().Of(channel);
  EXPECT_EQ(counts.received, static_cast<std::int64_t>(bad.size()) + 1);
  // The flipped payload may or may not decode; everything else must be refused.
  EXPECT_GE(counts.malformed, static_cast<std::int64_t>(bad.size()) - 1);
  EXPECT_EQ(counts.malformed + delivered, counts.received);
  EXPECT_GE(delivered, 1);  // the good message after the bad ones
  EXPECT_EQ(loop.stats().total_malformed(), counts.malformed);
}

}  // namespace
}  // namespace topay::procs
