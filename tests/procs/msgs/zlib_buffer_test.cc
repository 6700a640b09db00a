// ZlibDeflate / ZlibInflateExactly (procs/msgs/zlib_buffer.h): round trips at every level,
// and an inflate that holds the stream to the declared size.

#include "procs/msgs/zlib_buffer.h"

#include <gtest/gtest.h>

namespace topay::msgs {
namespace {

std::vector<std::uint8_t> Bytes(int n) {
  std::vector<std::uint8_t> bytes(n);
  for (int i = 0; i < n; ++i) bytes[i] = static_cast<std::uint8_t>((std::int64_t{i} * i) % 7);  // i * i overflows int beyond 46,340
  return bytes;
}

TEST(ZlibBuffer, RoundTripsAtEveryLevel) {
  for (int n : {0, 1, 1000, 100000}) {
    for (int level = 0; level <= 9; ++level) {
      std::vector<std::uint8_t> back;
      std::string error;
      ASSERT_TRUE(ZlibInflateExactly(ZlibDeflate(Bytes(n), level), n, &back, &error)) << error;
      EXPECT_EQ(back, Bytes(n)) << n << " " << level;
    }
  }
  EXPECT_THROW(ZlibDeflate(Bytes(3), -1), std::invalid_argument);
}

TEST(ZlibBuffer, InflateHoldsTheStreamToTheDeclaredSize) {
  const std::vector<std::uint8_t> stream = ZlibDeflate(Bytes(1000), 6);
  std::vector<std::uint8_t> back;
  std::string error;
  EXPECT_FALSE(ZlibInflateExactly(stream, 999, &back, &error));
  EXPECT_NE(error.find("more than the declared 999"), std::string::npos) << error;
  EXPECT_LE(back.size(), 999u);
  EXPECT_FALSE(ZlibInflateExactly(stream, 1001, &back, &error));
  EXPECT_NE(error.find("inflates to 1000 bytes"), std::string::npos) << error;
  EXPECT_FALSE(ZlibInflateExactly(std::span(stream).first(stream.size() - 3), 1000, &back, &error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  std::vector<std::uint8_t> trailing = stream;
  trailing.push_back(1);
  EXPECT_FALSE(ZlibInflateExactly(trailing, 1000, &back, &error));
  EXPECT_NE(error.find("follow the end"), std::string::npos) << error;
  const std::vector<std::uint8_t> garbage = {1, 2, 3, 4, 5};
  EXPECT_FALSE(ZlibInflateExactly(garbage, 1000, &back, &error));
  EXPECT_NE(error.find("not a valid zlib stream"), std::string::npos) << error;
  EXPECT_FALSE(ZlibInflateExactly({}, 0, &back, &error));
}

}  // namespace
}  // namespace topay::msgs
