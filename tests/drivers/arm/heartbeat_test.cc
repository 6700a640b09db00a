// Heartbeat and boot-up (CiA 301 §7.2.8.3.2-3): codec and consumer timing.
#include "drivers/arm/heartbeat.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(HeartbeatTest, EveryStateRoundTrips) {
  const std::pair<NmtState, std::uint8_t> states[] = {{NmtState::kBootUp, 0x00},
                                                      {NmtState::kStopped, 0x04},
                                                      {NmtState::kOperational, 0x05},
                                                      {NmtState::kPreOperational, 0x7F}};
  for (const auto& [state, byte] : states) {
    const auto frame = EncodeHeartbeat({7, state}, nullptr);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->id, 0x707u);
    EXPECT_EQ(frame->dlc, 1);
    EXPECT_EQ(frame->data[0], byte);
    const auto back = DecodeHeartbeat(*frame, nullptr);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->node_id, 7);
    EXPECT_EQ(back->state, state);
  }
}

TEST(HeartbeatTest, MalformedFramesAreRejected) {
  std::string error;
  EXPECT_FALSE(EncodeHeartbeat({0, NmtState::kOperational}, &error));
  EXPECT_EQ(error, "heartbeat: node id 0 is outside 1..127");
  EXPECT_FALSE(EncodeHeartbeat({128, NmtState::kOperational}, &error));
  EXPECT_FALSE(DecodeHeartbeat(can::CanFrame::Standard(0x701), &error));
  EXPECT_EQ(error, "heartbeat frame '701#': DLC 0, expected 1");
  EXPECT_FALSE(DecodeHeartbeat(can::CanFrame::Standard(0x701, {0x85}), &error));
  EXPECT_EQ(error, "heartbeat frame '701#85': unknown NMT state 133");
  EXPECT_FALSE(DecodeHeartbeat(can::CanFrame::Standard(0x700, {0x05}), &error));
  EXPECT_EQ(error,
            "heartbeat frame '700#05': COB-ID 0x700 (heartbeat) has node id 0, outside 1..127");
  EXPECT_FALSE(DecodeHeartbeat(can::CanFrame::Standard(0x781, {0x05}), &error));
  EXPECT_NE(error.find("not a CANopen object"), std::string::npos);
}

TEST(HeartbeatTest, ProducerIsDueEveryPeriod) {
  HeartbeatProducer producer(0.1);
  EXPECT_TRUE(producer.IsDue(5.0));  // the first at once
  producer.OnSent(5.0);
  EXPECT_FALSE(producer.IsDue(5.05));
  EXPECT_TRUE(producer.IsDue(5.1));
  producer.OnSent(5.1);
  EXPECT_FALSE(producer.IsDue(5.15));
  HeartbeatProducer disabled(0.0);
  EXPECT_FALSE(disabled.IsDue(0.0));
}

TEST(HeartbeatTest, ConsumerDetectsALostProducer) {
  HeartbeatConsumer consumer(0.3);
  EXPECT_FALSE(consumer.IsLost(10.0));  // not started before the first heartbeat
  EXPECT_FALSE(consumer.last_state());
  consumer.OnHeartbeat(NmtState::kBootUp, 1.0);
  EXPECT_TRUE(consumer.rebooted());
  consumer.OnHeartbeat(NmtState::kOperational, 1.1);
  EXPECT_FALSE(consumer.rebooted());
  EXPECT_EQ(consumer.last_state(), NmtState::kOperational);
  EXPECT_FALSE(consumer.IsLost(1.4));
  EXPECT_TRUE(consumer.IsLost(1.41));
  consumer.OnHeartbeat(NmtState::kOperational, 1.5);
  EXPECT_FALSE(consumer.IsLost(1.6));
  HeartbeatConsumer disabled(0.0);
  disabled.OnHeartbeat(NmtState::kOperational, 0.0);
  EXPECT_FALSE(disabled.IsLost(100.0));
}

}  // namespace
}  // namespace topay::canopen
