// Every message of the catalogue (lcmtypes/*.lcm) survives encode -> decode with all fields
// intact, and encoding refuses a buffer that is too small.

#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <vector>

#include "sample_messages.h"

namespace topay::test {
namespace {

template <class Msg>
class MessageRoundTrip : public ::testing::Test {};
TYPED_TEST_SUITE(MessageRoundTrip, AllMessageTypes, MessageTypeName);

TYPED_TEST(MessageRoundTrip, DecodesEveryFieldBack) {
  using Msg = TypeParam;
  const Msg original = MessageSample<Msg>::Make();
  const std::vector<std::uint8_t> bytes = Encode(original);

  Msg decoded;
  const int read = decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size()));
  ASSERT_EQ(read, static_cast<int>(bytes.size()));
  MessageSample<Msg>::ExpectSame(original, decoded);
}

TYPED_TEST(MessageRoundTrip, DecodingOverwritesAnEarlierMessage) {
  using Msg = TypeParam;
  const Msg original = MessageSample<Msg>::Make();
  const std::vector<std::uint8_t> bytes = Encode(original);
  Msg reused = original;
  ASSERT_GT(reused.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  Msg again;
  ASSERT_GT(again.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  // Decoding twice into one object gives the same as decoding once (no appending to arrays).
  ASSERT_GT(again.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  MessageSample<Msg>::ExpectSame(reused, again);
  MessageSample<Msg>::ExpectSame(original, again);
}

TYPED_TEST(MessageRoundTrip, EncodingIntoTooSmallBufferFails) {
  using Msg = TypeParam;
  const Msg original = MessageSample<Msg>::Make();
  const int size = original.getEncodedSize();
  std::vector<std::uint8_t> buffer(size);
  for (int maxlen = 0; maxlen < size; ++maxlen) {
    EXPECT_LT(original.encode(buffer.data(), 0, maxlen), 0) << "maxlen " << maxlen;
  }
}

TYPED_TEST(MessageRoundTrip, FingerprintsDifferBetweenTypes) {
  using Msg = TypeParam;
  // Every other type's fingerprint differs from this one's (else decoding could mix them up).
  int others = 0;
  Catalogue::ForEach([&]<class Other>(Other*) {
    if constexpr (!std::is_same_v<Other, Msg>) {
      EXPECT_NE(Other::getHash(), Msg::getHash()) << Other::getTypeName();
      ++others;
    }
  });
  EXPECT_EQ(others, Catalogue::kSize - 1);
}

}  // namespace
}  // namespace topay::test
