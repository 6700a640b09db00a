// EventRing: order, insertion at any position, wrap-around, eviction of the oldest.

#include "core/estimation/event_ring.h"

#include <vector>

#include <gtest/gtest.h>

namespace topay {
namespace {

std::vector<int> Contents(const EventRing<int>& ring) {
  std::vector<int> out;
  for (int i = 0; i < ring.size(); ++i) out.push_back(ring[i]);
  return out;
}

TEST(EstimatorEventRing, KeepsOrderAcrossWrapAroundAndInsertions) {
  EventRing<int> ring(4);
  EXPECT_TRUE(ring.empty());
  ring.PushBack(1);
  ring.PushBack(2);
  ring.PushBack(4);
  ring.Insert(2, 3);
  EXPECT_TRUE(ring.full());
  EXPECT_EQ(Contents(ring), (std::vector<int>{1, 2, 3, 4}));
  ring.PopFront();
  ring.PopFront();
  ring.PushBack(6);  // wraps around the storage
  ring.Insert(0, 0);
  EXPECT_EQ(Contents(ring), (std::vector<int>{0, 3, 4, 6}));
  ring.PopFront();
  ring.Insert(2, 5);
  EXPECT_EQ(Contents(ring), (std::vector<int>{3, 4, 5, 6}));
  EXPECT_EQ(ring.back(), 6);
  ring.Clear();
  EXPECT_EQ(ring.size(), 0);
  EXPECT_EQ(ring.capacity(), 4);
}

}  // namespace
}  // namespace topay
