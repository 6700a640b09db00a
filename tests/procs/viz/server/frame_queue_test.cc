// The per-client queue: FIFO order, the oldest frames dropped (and counted) beyond the frame
// and byte bounds, a frame larger than the byte bound dropped, the byte count kept exact.
#include "procs/viz/server/frame_queue.h"

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

OutgoingFrame Frame(std::size_t size, char fill = 'x', bool binary = true) {
  return {std::make_shared<const std::string>(size, fill), binary};
}

TEST(FrameQueueTest, PopsInPushOrder) {
  FrameQueue queue;
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.Pop(), std::nullopt);
  EXPECT_EQ(queue.Push(TextFrame("one")), 0u);
  EXPECT_EQ(queue.Push(BinaryFrame("two!")), 0u);
  EXPECT_EQ(queue.frames(), 2u);
  EXPECT_EQ(queue.bytes(), 7u);
  std::optional<OutgoingFrame> first = queue.Pop();
  ASSERT_TRUE(first);
  EXPECT_EQ(*first->bytes, "one");
  EXPECT_FALSE(first->binary);
  std::optional<OutgoingFrame> second = queue.Pop();
  ASSERT_TRUE(second);
  EXPECT_EQ(*second->bytes, "two!");
  EXPECT_TRUE(second->binary);
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.bytes(), 0u);
  EXPECT_EQ(queue.pushed(), 2u);
  EXPECT_EQ(queue.dropped(), 0u);
}

TEST(FrameQueueTest, DropsTheOldestBeyondTheFrameBound) {
  FrameQueue queue({3, 1 << 20});
  for (char c : std::string("abcde")) queue.Push(Frame(1, c));
  EXPECT_EQ(queue.frames(), 3u);
  EXPECT_EQ(queue.dropped(), 2u);
  EXPECT_EQ(*queue.Pop()->bytes, "c");
  EXPECT_EQ(*queue.Pop()->bytes, "d");
  EXPECT_EQ(*queue.Pop()->bytes, "e");
}

TEST(FrameQueueTest, DropsTheOldestBeyondTheByteBound) {
  FrameQueue queue({100, 10});
  EXPECT_EQ(queue.Push(Frame(4, 'a')), 0u);
  EXPECT_EQ(queue.Push(Frame(4, 'b')), 0u);
  EXPECT_EQ(queue.Push(Frame(6, 'c')), 1u);  // 4 + 4 + 6 > 10: a goes; 4 + 6 == 10 fits
  EXPECT_EQ(queue.bytes(), 10u);
  EXPECT_EQ(queue.Push(Frame(5, 'd')), 2u);  // b goes, then 6 + 5 > 10: c goes too
  EXPECT_EQ(queue.bytes(), 5u);
  EXPECT_EQ(queue.peak_bytes(), 10u);
  EXPECT_EQ(*queue.Pop()->bytes, "ddddd");
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.dropped(), 3u);
}

TEST(FrameQueueTest, AFrameLargerThanTheByteBoundIsDroppedAlone) {
  FrameQueue queue({100, 10});
  queue.Push(Frame(3, 'a'));
  EXPECT_EQ(queue.Push(Frame(11, 'b')), 1u);
  EXPECT_EQ(queue.frames(), 1u);  // the queued frame stays
  EXPECT_EQ(*queue.Pop()->bytes, "aaa");
  EXPECT_EQ(queue.dropped(), 1u);
  EXPECT_EQ(queue.pushed(), 2u);
}

TEST(FrameQueueTest, NeverExceedsItsBoundsUnderAFlood) {
  FrameQueue queue({50, 1000});
  for (int i = 0; i < 10000; ++i) {
    queue.Push(Frame(static_cast<std::size_t>(i % 97), 'z'));
    ASSERT_LE(queue.frames(), 50u);
    ASSERT_LE(queue.bytes(), 1000u);
    if (i % 7 == 0) queue.Pop();
  }
  EXPECT_LE(queue.peak_bytes(), 1000u);
  EXPECT_GT(queue.dropped(), 0u);
  std::size_t bytes = 0;
  while (std::optional<OutgoingFrame> frame = queue.Pop()) bytes += frame->size();
  EXPECT_EQ(queue.bytes(), 0u);
  EXPECT_GT(bytes, 0u);
}

TEST(FrameQueueTest, ClearEmptiesWithoutCountingDrops) {
  FrameQueue queue;
  queue.Push(TextFrame("a"));
  queue.Push(TextFrame("b"));
  queue.Clear();
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.bytes(), 0u);
  EXPECT_EQ(queue.dropped(), 0u);
}

TEST(FrameQueueTest, ZeroBoundsAreRaisedToOne) {
  FrameQueue queue({0, 0});
  EXPECT_EQ(queue.options().max_frames, 1u);
  EXPECT_EQ(queue.options().max_bytes, 1u);
  queue.Push(Frame(1, 'a'));
  queue.Push(Frame(1, 'b'));
  EXPECT_EQ(queue.frames(), 1u);
  EXPECT_EQ(*queue.Pop()->bytes, "b");
}

}  // namespace
}  // namespace topay::viz
