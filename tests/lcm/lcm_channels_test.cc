// Channel names (lcmtypes/include/topay_msgs/channels.h) and one real publish/subscribe round
// trip through LCM's in-process memq:// provider.

#include "topay_msgs/channels.h"

#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include <cctype>
#include <optional>
#include <set>
#include <string>

#include "sample_messages.h"
#include "topay_msgs/checked_decode.h"

namespace topay::test {
namespace {

TEST(LcmChannels, AreDistinctUpperCaseNames) {
  std::set<std::string_view> seen;
  for (const std::string_view channel : channels::kAll) {
    EXPECT_FALSE(channel.empty());
    EXPECT_TRUE(seen.insert(channel).second) << "duplicate " << channel;
    for (const char c : channel) {
      EXPECT_TRUE(std::isupper(static_cast<unsigned char>(c)) || c == '_') << channel;
    }
  }
  EXPECT_EQ(seen.size(), channels::kAll.size());
}

// Receives one channel both decoded by LCM (typed handler) and raw (for CheckedDecode).
class RobotStateReceiver {
 public:
  void OnTyped(const lcm::ReceiveBuffer*, const std::string& channel, const robot_state_t* msg) {
    typed_channel = channel;
    typed = *msg;
  }
  void OnRaw(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    raw = CheckedDecode<robot_state_t>(rbuf->data, rbuf->data_size, &raw_error);
  }

  std::string typed_channel;
  std::optional<robot_state_t> typed;
  std::optional<robot_state_t> raw;
  std::string raw_error;
};

TEST(LcmChannels, RobotStateRoundTripsThroughMemq) {
  lcm::LCM bus("memq://");
  ASSERT_TRUE(bus.good());
  RobotStateReceiver receiver;
  const std::string channel(channels::ROBOT_STATE);
  bus.subscribe(channel, &RobotStateReceiver::OnTyped, &receiver);
  bus.subscribe(channel, &RobotStateReceiver::OnRaw, &receiver);
  // A message on another channel must not reach the robot-state handlers.
  const heartbeat_t heartbeat = MessageSample<heartbeat_t>::Make();
  ASSERT_EQ(bus.publish(std::string(channels::HEARTBEAT), &heartbeat), 0);

  const robot_state_t sent = MessageSample<robot_state_t>::Make();
  ASSERT_EQ(bus.publish(channel, &sent), 0);
  for (int i = 0; i < 2 && !receiver.typed; ++i) ASSERT_GE(bus.handleTimeout(1000), 0);

  ASSERT_TRUE(receiver.typed.has_value());
  EXPECT_EQ(receiver.typed_channel, channel);
  MessageSample<robot_state_t>::ExpectSame(sent, *receiver.typed);
  ASSERT_TRUE(receiver.raw.has_value()) << receiver.raw_error;
  MessageSample<robot_state_t>::ExpectSame(sent, *receiver.raw);
}

}  // namespace
}  // namespace topay::test
