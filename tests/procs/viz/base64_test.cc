// Base64 of bytes and of little-endian 16-bit arrays (procs/viz/base64.h).

#include "procs/viz/base64.h"

#include <gtest/gtest.h>

#include <random>

namespace topay::viz {
namespace {

std::vector<std::uint8_t> Bytes(std::string_view text) { return {text.begin(), text.end()}; }

TEST(Base64, MatchesTheRfcVectors) {
  EXPECT_EQ(Base64Encode(Bytes("")), "");
  EXPECT_EQ(Base64Encode(Bytes("f")), "Zg==");
  EXPECT_EQ(Base64Encode(Bytes("fo")), "Zm8=");
  EXPECT_EQ(Base64Encode(Bytes("foo")), "Zm9v");
  EXPECT_EQ(Base64Encode(Bytes("foob")), "Zm9vYg==");
  EXPECT_EQ(Base64Encode(Bytes("fooba")), "Zm9vYmE=");
  EXPECT_EQ(Base64Encode(Bytes("foobar")), "Zm9vYmFy");
}

TEST(Base64, RoundTripsRandomBytes) {
  std::mt19937 rng(7);
  for (int n = 0; n < 200; ++n) {
    std::vector<std::uint8_t> bytes(n);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    const std::optional<std::vector<std::uint8_t>> back = Base64Decode(Base64Encode(bytes));
    ASSERT_TRUE(back.has_value()) << n;
    EXPECT_EQ(*back, bytes) << n;
  }
}

TEST(Base64, RejectsWhatIsNotPaddedBase64) {
  EXPECT_FALSE(Base64Decode("Zg=").has_value());     // not a multiple of 4
  EXPECT_FALSE(Base64Decode("Z!==").has_value());    // not in the alphabet
  EXPECT_FALSE(Base64Decode("Zg=a").has_value());    // padding then a digit
}

TEST(Base64, CarriesSixteenBitValuesLittleEndian) {
  const std::vector<std::uint16_t> u = {0x0102, 0xfffe, 0};
  const std::vector<std::uint8_t> bytes = *Base64Decode(Base64OfUint16(u));
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0x02, 0x01, 0xfe, 0xff, 0, 0}));
  const std::vector<std::int16_t> s = {-2, 300};
  EXPECT_EQ(*Base64Decode(Base64OfInt16(s)), (std::vector<std::uint8_t>{0xfe, 0xff, 0x2c, 0x01}));
}

}  // namespace
}  // namespace topay::viz
