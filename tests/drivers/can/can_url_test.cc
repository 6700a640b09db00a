// CAN bus URLs: socketcan://IFACE and udp://GROUP:PORT, good and bad. Nothing is opened here
// except through a bad URL or bad options (which fail before any socket exists).
#include "drivers/can/can_url.h"

#include <gtest/gtest.h>

#include <string>

namespace topay::can {
namespace {

TEST(CanUrlTest, ParsesSocketCan) {
  std::string error;
  const std::optional<CanUrl> url = ParseCanUrl("socketcan://can0", &error);
  ASSERT_TRUE(url) << error;
  EXPECT_EQ(url->scheme, CanUrl::Scheme::kSocketCan);
  EXPECT_EQ(url->interface, "can0");
  EXPECT_EQ(url->ToString(), "socketcan://can0");
  EXPECT_TRUE(ParseCanUrl("socketcan://vcan0", &error));
  EXPECT_TRUE(ParseCanUrl("socketcan://abcdefghijklmno", &error));  // 15 characters
}

TEST(CanUrlTest, ParsesUdp) {
  std::string error;
  const std::optional<CanUrl> url = ParseCanUrl("udp://239.255.1.1:9000", &error);
  ASSERT_TRUE(url) << error;
  EXPECT_EQ(url->scheme, CanUrl::Scheme::kUdp);
  EXPECT_EQ(url->group, "239.255.1.1");
  EXPECT_EQ(url->port, 9000);
  EXPECT_EQ(url->ToString(), "udp://239.255.1.1:9000");
  EXPECT_TRUE(ParseCanUrl("udp://224.0.0.1:1", &error));
  EXPECT_TRUE(ParseCanUrl("udp://239.255.255.255:65535", &error));
}

std::string ErrorOf(const char* text) {
  std::string error;
  EXPECT_FALSE(ParseCanUrl(text, &error)) << text;
  return error;
}

TEST(CanUrlTest, BadUrlsNameTheBadPart) {
  EXPECT_EQ(ErrorOf("can0"), "can0: unknown scheme: expected socketcan://IFACE or udp://GROUP:PORT");
  EXPECT_EQ(ErrorOf("tcp://1.2.3.4:5"), "tcp://1.2.3.4:5: unknown scheme: expected socketcan://IFACE or udp://GROUP:PORT");
  EXPECT_EQ(ErrorOf("socketcan://"), "socketcan://: no interface name after socketcan:// (e.g. socketcan://can0)");
  EXPECT_EQ(ErrorOf("socketcan://abcdefghijklmnop"),
            "socketcan://abcdefghijklmnop: interface name 'abcdefghijklmnop' is longer than 15 characters");
  EXPECT_EQ(ErrorOf("socketcan://can 0"), "socketcan://can 0: interface name 'can 0' has a bad character ' '");
  EXPECT_EQ(ErrorOf("socketcan://can0/x"), "socketcan://can0/x: interface name 'can0/x' has a bad character '/'");
  EXPECT_EQ(ErrorOf("udp://"), "udp://: expected udp://GROUP:PORT, e.g. udp://239.255.1.1:9000");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1"), "udp://239.255.1.1: expected udp://GROUP:PORT, e.g. udp://239.255.1.1:9000");
  EXPECT_EQ(ErrorOf("udp://10.0.0.1:9000"),
            "udp://10.0.0.1:9000: group 10.0.0.1 is not an IPv4 multicast address (224.0.0.0/4)");
  EXPECT_EQ(ErrorOf("udp://localhost:9000"),
            "udp://localhost:9000: group 'localhost' is not an IPv4 address (dotted quad)");
  EXPECT_EQ(ErrorOf("udp://239.255.1:9000"),
            "udp://239.255.1:9000: group '239.255.1' is not an IPv4 address (dotted quad)");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1:"), "udp://239.255.1.1:: no port after ':' (1-65535)");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1:0"), "udp://239.255.1.1:0: port 0 is outside 1-65535");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1:65536"), "udp://239.255.1.1:65536: port 65536 is outside 1-65535");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1:9x"), "udp://239.255.1.1:9x: port '9x' is not a number");
  EXPECT_EQ(ErrorOf("udp://239.255.1.1:-1"), "udp://239.255.1.1:-1: port '-1' is not a number");
}

// Found by the can_text fuzz target (tests/fuzz/regressions/can_text/udp_group_with_nul): the
// group went to inet_pton as a C string, so a NUL ended it early and whatever followed was kept
// in the accepted group.
TEST(CanUrlTest, GroupWithAnEmbeddedNulIsRefused) {
  using namespace std::string_literals;
  const std::string text = "udp://239.255.1.1\0junk:9000"s;
  std::string error;
  EXPECT_FALSE(ParseCanUrl(text, &error));
  EXPECT_NE(error.find("is not an IPv4 address (dotted quad)"), std::string::npos) << error;
  EXPECT_FALSE(ParseCanUrl("udp://239.255.1.1\0:9000"s, &error));
  EXPECT_FALSE(ParseCanUrl("udp:// 239.255.1.1:9000", &error));
  EXPECT_TRUE(ParseCanUrl("udp://239.255.1.10:9000", &error)) << error;
}

TEST(CanUrlTest, OpenCanBusReportsBadUrlsAndOptions) {
  std::string error;
  EXPECT_EQ(OpenCanBus("udp://10.0.0.1:9000", {}, &error), nullptr);
  EXPECT_EQ(error, "udp://10.0.0.1:9000: group 10.0.0.1 is not an IPv4 multicast address (224.0.0.0/4)");
  CanBusOptions options;
  options.receive_buffer_bytes = -1;
  EXPECT_EQ(OpenCanBus("udp://239.255.1.1:9000", options, &error), nullptr);
  EXPECT_EQ(error, "udp://239.255.1.1:9000: CanBusOptions.receive_buffer_bytes must be >= 0, got -1");
}

}  // namespace
}  // namespace topay::can
