// The start-up SDO writes (docs/cia402.md): contents, order, options.
#include "drivers/arm/startup_sdo.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "drivers/arm/sdo.h"

namespace topay::cia402 {
namespace {

struct Expected {
  std::uint16_t index;
  std::uint8_t subindex;
  std::uint32_t value;
  int size_bytes;
};

// The write to index:subindex in `writes`, null when there is none.
const SdoWrite* FindWrite(const std::vector<SdoWrite>& writes, std::uint16_t index, std::uint8_t subindex) {
  const auto it = std::find_if(writes.begin(), writes.end(), [&](const SdoWrite& w) {
    return w.address.index == index && w.address.subindex == subindex;
  });
  return it == writes.end() ? nullptr : &*it;
}

TEST(StartupSdoTest, DefaultSequenceForNode3) {
  std::string error;
  const auto writes = StartupSdoWrites(3, StartupOptions{}, &error);
  ASSERT_TRUE(writes) << error;
  const Expected expected[] = {
      // RPDO1: controlword + target velocity, synchronous, a 50 ms deadline.
      {0x1400, 1, 0x80000203, 4}, {0x1600, 0, 0, 1}, {0x1600, 1, 0x60400010, 4},
      {0x1600, 2, 0x60FF0020, 4}, {0x1600, 0, 2, 1}, {0x1400, 2, 1, 1}, {0x1400, 5, 50, 2},
      {0x1400, 1, 0x203, 4},
      // RPDO2-4 unused: invalid.
      {0x1401, 1, 0x80000303, 4}, {0x1402, 1, 0x80000403, 4}, {0x1403, 1, 0x80000503, 4},
      // TPDO1: statusword + position actual, every SYNC; TPDO2: velocity actual, every 2nd SYNC.
      {0x1800, 1, 0xC0000183, 4}, {0x1A00, 0, 0, 1}, {0x1A00, 1, 0x60410010, 4},
      {0x1A00, 2, 0x60640020, 4}, {0x1A00, 0, 2, 1}, {0x1800, 2, 1, 1},
      {0x1800, 1, 0x40000183, 4},
      {0x1801, 1, 0xC0000283, 4}, {0x1A01, 0, 0, 1}, {0x1A01, 1, 0x606C0020, 4},
      {0x1A01, 0, 1, 1}, {0x1801, 2, 2, 1}, {0x1801, 1, 0x40000283, 4},
      {0x1802, 1, 0xC0000383, 4}, {0x1803, 1, 0xC0000483, 4},
      // Heartbeats, interpolation period, mode.
      {0x1017, 0, 100, 2}, {0x1016, 1, 0x007F012C, 4}, {0x60C2, 1, 10, 1},
      {0x60C2, 2, 0xFD, 1}, {0x6060, 0, 9, 1}};
  ASSERT_EQ(writes->size(), std::size(expected));
  for (std::size_t i = 0; i < writes->size(); ++i) {
    SCOPED_TRACE("write " + std::to_string(i) + ": " + std::string((*writes)[i].what));
    EXPECT_EQ((*writes)[i].address.index, expected[i].index);
    EXPECT_EQ((*writes)[i].address.subindex, expected[i].subindex);
    EXPECT_EQ((*writes)[i].value, expected[i].value);
    EXPECT_EQ((*writes)[i].size_bytes, expected[i].size_bytes);
    EXPECT_FALSE((*writes)[i].what.empty());
    // Every write encodes as an expedited download request.
    EXPECT_TRUE(canopen::EncodeSdoDownloadRequest(ToDownloadRequest(3, (*writes)[i]), nullptr));
  }
}

TEST(StartupSdoTest, TargetPositionMappedOnRequest) {
  StartupOptions options;
  options.map_target_position = true;
  options.mode_of_operation = mode::kCyclicSynchronousPosition;
  const auto writes = StartupSdoWrites(1, options, nullptr);
  ASSERT_TRUE(writes);
  const SdoWrite* mapped = FindWrite(*writes, 0x1601, 1);
  ASSERT_NE(mapped, nullptr);
  EXPECT_EQ(mapped->value, 0x607A0020u);
  EXPECT_EQ(writes->back().value, 8u);
}

TEST(StartupSdoTest, BadOptionsAreRejected) {
  std::string error;
  EXPECT_FALSE(StartupSdoWrites(0, {}, &error));
  EXPECT_EQ(error, "start-up SDO writes: drive node id 0 is outside 1..127");
  StartupOptions options;
  EXPECT_FALSE(StartupSdoWrites(127, options, &error));
  EXPECT_EQ(error, "start-up SDO writes: the drive and the host share node id 127");
  options.producer_heartbeat_ms = 70000;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  EXPECT_EQ(error, "start-up SDO writes: heartbeat time 70000 ms is outside 0..65535");
  options = {};
  options.tpdo2_every_n_syncs = 241;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  EXPECT_EQ(error, "start-up SDO writes: TPDO2 every 241 SYNCs is outside 1..240");
  options = {};
  options.mode_of_operation = mode::kProfilePosition;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  EXPECT_EQ(error, "start-up SDO writes: mode of operation 1 is not 3, 8 or 9");
  options.mode_of_operation = mode::kCyclicSynchronousPosition;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  options = {};
  options.sync_period_ms = 0;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  options = {};
  options.rpdo_deadline_ms = 65536;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
  EXPECT_EQ(error, "start-up SDO writes: RPDO deadline 65536 ms is outside 0..65535");
  options.rpdo_deadline_ms = -1;
  EXPECT_FALSE(StartupSdoWrites(1, options, &error));
}

TEST(StartupSdoTest, ADeadlineOfZeroIsStillWrittenAndOnlyForRpdo1) {
  StartupOptions options;
  options.rpdo_deadline_ms = 0;  // not monitored: the drive's power-on value 0 is written
  const auto writes = StartupSdoWrites(2, options, nullptr);
  ASSERT_TRUE(writes);
  const SdoWrite* timer = FindWrite(*writes, 0x1400, 5);
  ASSERT_NE(timer, nullptr);
  EXPECT_EQ(timer->value, 0u);
  EXPECT_EQ(timer->size_bytes, 2);
  // Only RPDO1 carries one: the TPDOs' event timers are left alone.
  EXPECT_EQ(std::count_if(writes->begin(), writes->end(), [](const SdoWrite& w) { return w.address.subindex == 5; }), 1);
}

TEST(StartupSdoTest, MappingEntryPacksIndexSubindexAndBits) {
  EXPECT_EQ(PdoMappingEntry({0x6040, 0}, 16), 0x60400010u);
  EXPECT_EQ(PdoMappingEntry({0x2001, 3}, 8), 0x20010308u);
}

}  // namespace
}  // namespace topay::cia402
