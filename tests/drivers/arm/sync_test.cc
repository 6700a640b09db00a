// SYNC (CiA 301 §7.2.5): with and without counter, malformed frames.
#include "drivers/arm/sync.h"

#include <gtest/gtest.h>

namespace topay::canopen {
namespace {

TEST(SyncTest, RoundTripsWithAndWithoutCounter) {
  const auto plain = EncodeSync({}, nullptr);
  ASSERT_TRUE(plain);
  EXPECT_EQ(can::ToString(*plain), "080#");
  const auto back = DecodeSync(*plain, nullptr);
  ASSERT_TRUE(back);
  EXPECT_FALSE(back->counter.has_value());
  for (int counter : {1, 17, 240}) {
    const auto frame = EncodeSync({counter}, nullptr);
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->dlc, 1);
    const auto decoded = DecodeSync(*frame, nullptr);
    ASSERT_TRUE(decoded);
    EXPECT_EQ(decoded->counter, counter);
  }
}

TEST(SyncTest, CounterWrapsAfter240) {
  EXPECT_EQ(NextSyncCounter(1), 2);
  EXPECT_EQ(NextSyncCounter(240), 1);
}

TEST(SyncTest, MalformedFramesAreRejected) {
  std::string error;
  EXPECT_FALSE(EncodeSync({0}, &error));
  EXPECT_EQ(error, "SYNC: counter 0 is outside 1..240");
  EXPECT_FALSE(EncodeSync({241}, &error));
  EXPECT_FALSE(DecodeSync(can::CanFrame::Standard(0x080, {1, 2}), &error));
  EXPECT_EQ(error, "SYNC frame '080#0102': DLC 2, expected 0..1");
  EXPECT_FALSE(DecodeSync(can::CanFrame::Standard(0x080, {0xF1}), &error));
  EXPECT_EQ(error, "SYNC frame '080#F1': counter 241 is outside 1..240");
  EXPECT_FALSE(DecodeSync(can::CanFrame::Standard(0x081), &error));
  EXPECT_EQ(error, "SYNC frame '081#': id 0x081 is EMCY, expected SYNC");
}

}  // namespace
}  // namespace topay::canopen
