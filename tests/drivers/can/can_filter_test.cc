// Receive filters: SocketCAN's id/mask rule, as the UDP bus applies it in user space.
#include "drivers/can/can_filter.h"

#include <gtest/gtest.h>

namespace topay::can {
namespace {

TEST(CanFilterTest, StandardExactMatch) {
  const CanFilter filter = CanFilter::Standard(0x123);
  EXPECT_TRUE(Matches(filter, CanFrame::Standard(0x123)));
  EXPECT_FALSE(Matches(filter, CanFrame::Standard(0x124)));
  EXPECT_FALSE(Matches(filter, CanFrame::Extended(0x123)));  // extended frames never pass
  EXPECT_TRUE(Matches(filter, CanFrame::Remote(0x123)));     // RTR not in the mask
}

TEST(CanFilterTest, MaskSelectsARange) {
  // CANopen style: function code 0x180 (TPDO1) of any node: ids 0x180..0x1FF.
  const CanFilter filter = CanFilter::Standard(0x180, 0x780);
  EXPECT_TRUE(Matches(filter, CanFrame::Standard(0x181)));
  EXPECT_TRUE(Matches(filter, CanFrame::Standard(0x1FF)));
  EXPECT_FALSE(Matches(filter, CanFrame::Standard(0x201)));
}

TEST(CanFilterTest, ExtendedMatch) {
  const CanFilter filter = CanFilter::Extended(0x12345600, 0x1FFFFF00);
  EXPECT_TRUE(Matches(filter, CanFrame::Extended(0x123456AB)));
  EXPECT_FALSE(Matches(filter, CanFrame::Extended(0x123457AB)));
  EXPECT_FALSE(Matches(filter, CanFrame::Standard(0x0)));
}

TEST(CanFilterTest, InvertedFilterAndRawMask) {
  const CanFilter not_123{0x123 | CAN_INV_FILTER, CAN_SFF_MASK};
  EXPECT_FALSE(Matches(not_123, CanFrame::Standard(0x123)));
  EXPECT_TRUE(Matches(not_123, CanFrame::Standard(0x124)));
  const CanFilter all{0, 0};
  EXPECT_TRUE(Matches(all, CanFrame::Extended(0x1FFFFFFF)));
  EXPECT_EQ(ToString(CanFilter::Standard(0x123)), "123:800007FF");
  EXPECT_EQ(ToString(not_123), "123~7FF");
}

TEST(CanFilterTest, ListSemantics) {
  EXPECT_TRUE(PassesFilters({}, CanFrame::Standard(0x555)));  // empty: everything
  const std::vector<CanFilter> filters = {CanFilter::Standard(0x100), CanFilter::Standard(0x200)};
  EXPECT_TRUE(PassesFilters(filters, CanFrame::Standard(0x100)));
  EXPECT_TRUE(PassesFilters(filters, CanFrame::Standard(0x200)));
  EXPECT_FALSE(PassesFilters(filters, CanFrame::Standard(0x300)));
  CanFrame error_frame;
  error_frame.error = true;
  error_frame.id = 0x40;
  EXPECT_TRUE(PassesFilters(filters, error_frame));  // error frames are not id-filtered
}

}  // namespace
}  // namespace topay::can
