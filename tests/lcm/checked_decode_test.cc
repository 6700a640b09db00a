// topay::CheckedDecode (lcmtypes/include/topay_msgs/checked_decode.h): accepts exactly one
// well-formed message of the expected type and turns everything else into a named error.

#include "topay_msgs/checked_decode.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "sample_messages.h"

namespace topay::test {
namespace {

template <class Msg>
class CheckedDecodeTest : public ::testing::Test {
 protected:
  static std::vector<std::uint8_t> SampleBytes() { return Encode(MessageSample<Msg>::Make()); }

  // Decodes bytes; a message that comes out must re-encode and decode again unchanged.
  static void ExpectFailsOrYieldsMessage(const std::vector<std::uint8_t>& bytes,
                                         const std::string& what) {
    std::string error;
    std::optional<Msg> msg;
    ASSERT_NO_THROW(msg = CheckedDecode<Msg>(bytes.data(), bytes.size(), &error)) << what;
    if (!msg) {
      EXPECT_NE(error.find(Msg::getTypeName()), std::string::npos) << what << ": " << error;
      return;
    }
    const std::vector<std::uint8_t> again = Encode(*msg);
    std::optional<Msg> twice = CheckedDecode<Msg>(again.data(), again.size(), &error);
    ASSERT_TRUE(twice.has_value()) << what << ": " << error;
    EXPECT_EQ(Encode(*twice), again) << what;
  }
};
TYPED_TEST_SUITE(CheckedDecodeTest, AllMessageTypes, MessageTypeName);

TYPED_TEST(CheckedDecodeTest, AcceptsAWholeMessage) {
  using Msg = TypeParam;
  const Msg original = MessageSample<Msg>::Make();
  const std::vector<std::uint8_t> bytes = Encode(original);
  std::string error;
  const std::optional<Msg> decoded = CheckedDecode<Msg>(bytes.data(), bytes.size(), &error);
  ASSERT_TRUE(decoded.has_value()) << error;
  EXPECT_TRUE(error.empty()) << error;
  MessageSample<Msg>::ExpectSame(original, *decoded);
  // The error pointer is optional.
  EXPECT_TRUE(CheckedDecode<Msg>(bytes.data(), bytes.size(), nullptr).has_value());
}

TYPED_TEST(CheckedDecodeTest, RejectsEveryTruncatedPrefix) {
  using Msg = TypeParam;
  const std::vector<std::uint8_t> bytes = this->SampleBytes();
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    const std::vector<std::uint8_t> prefix(bytes.begin(), bytes.begin() + size);
    std::string error;
    EXPECT_FALSE(CheckedDecode<Msg>(prefix.data(), prefix.size(), &error)) << "size " << size;
    EXPECT_NE(error.find(Msg::getTypeName()), std::string::npos) << error;
  }
}

TYPED_TEST(CheckedDecodeTest, RejectsTrailingBytes) {
  using Msg = TypeParam;
  std::vector<std::uint8_t> bytes = this->SampleBytes();
  bytes.push_back(0);
  std::string error;
  EXPECT_FALSE(CheckedDecode<Msg>(bytes.data(), bytes.size(), &error));
  EXPECT_NE(error.find("of " + std::to_string(bytes.size()) + " bytes"), std::string::npos)
      << error;
}

TYPED_TEST(CheckedDecodeTest, RejectsAWrongFingerprint) {
  using Msg = TypeParam;
  for (int bit = 0; bit < 64; ++bit) {
    std::vector<std::uint8_t> bytes = this->SampleBytes();
    bytes[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    std::string error;
    EXPECT_FALSE(CheckedDecode<Msg>(bytes.data(), bytes.size(), &error)) << "bit " << bit;
    EXPECT_NE(error.find("fingerprint"), std::string::npos) << error;
  }
}

TYPED_TEST(CheckedDecodeTest, RejectsEveryOtherTypeOfTheCatalogue) {
  using Msg = TypeParam;
  Catalogue::ForEach([]<class Other>(Other*) {
    if constexpr (!std::is_same_v<Other, Msg>) {
      const std::vector<std::uint8_t> bytes = Encode(MessageSample<Other>::Make());
      std::string error;
      EXPECT_FALSE(CheckedDecode<Msg>(bytes.data(), bytes.size(), &error))
          << Other::getTypeName();
      EXPECT_NE(error.find("fingerprint"), std::string::npos) << error;
    }
  });
}

TYPED_TEST(CheckedDecodeTest, FlippedBytesFailOrYieldAMessage) {
  const std::vector<std::uint8_t> bytes = this->SampleBytes();
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (const std::uint8_t mask : {0xFF, 0x80, 0x01}) {
      std::vector<std::uint8_t> corrupted = bytes;
      corrupted[i] ^= mask;
      this->ExpectFailsOrYieldsMessage(corrupted, "byte " + std::to_string(i));
    }
  }
}

TYPED_TEST(CheckedDecodeTest, HostileLengthsFailOrYieldAMessage) {
  // Every 4-byte window (so every array count and string length field) set to -1 and to
  // 0x7fffffff, big-endian as on the wire.
  const std::vector<std::uint8_t> bytes = this->SampleBytes();
  for (std::size_t i = 0; i + 4 <= bytes.size(); ++i) {
    for (const std::uint32_t value : {0xFFFFFFFFu, 0x7FFFFFFFu}) {
      std::vector<std::uint8_t> corrupted = bytes;
      for (int k = 0; k < 4; ++k) corrupted[i + k] = (value >> (24 - 8 * k)) & 0xFF;
      this->ExpectFailsOrYieldsMessage(corrupted, "offset " + std::to_string(i));
    }
  }
}

TEST(CheckedDecode, RejectsNullAndOversizedBuffers) {
  std::string error;
  EXPECT_FALSE(CheckedDecode<heartbeat_t>(nullptr, 24, &error));
  EXPECT_NE(error.find("heartbeat_t: null buffer"), std::string::npos) << error;

  // The size is checked before any byte is read, so a claim larger than the limit is safe.
  const std::vector<std::uint8_t> bytes = Encode(MessageSample<heartbeat_t>::Make());
  EXPECT_FALSE(CheckedDecode<heartbeat_t>(bytes.data(), kMaxCheckedDecodeBytes + 1, &error));
  EXPECT_NE(error.find("exceeds the limit"), std::string::npos) << error;

  EXPECT_FALSE(CheckedDecode<heartbeat_t>(bytes.data(), 0, &error));
  EXPECT_NE(error.find("too short for the 8-byte fingerprint"), std::string::npos) << error;
}

}  // namespace
}  // namespace topay::test
