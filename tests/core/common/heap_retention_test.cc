#include "core/common/heap_retention.h"

#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/sanitizer_build.h"

namespace topay {
namespace {

TEST(HeapRetentionTest, AcceptsThePlannerSettingAndRejectsOversizedOnes) {
  if (testing::kAddressSanitizerBuild || testing::kThreadSanitizerBuild) {
    GTEST_SKIP() << "built with a sanitizer: its allocator replaces glibc's, mallopt has no effect";
  }
#if defined(__GLIBC__)
  EXPECT_TRUE(RetainFreedHeapMemory());
  EXPECT_FALSE(RetainFreedHeapMemory(std::size_t{1} << 40));  // beyond mallopt's int
  // Allocation still works after the change (large and small blocks).
  std::vector<float> big(std::size_t{4} << 20, 1.0f);
  std::vector<int> small(16, 2);
  EXPECT_EQ(big.back() + small.front(), 3.0f);
#else
  GTEST_SKIP() << "not glibc: RetainFreedHeapMemory has no setting to change";
#endif
}

}  // namespace
}  // namespace topay
