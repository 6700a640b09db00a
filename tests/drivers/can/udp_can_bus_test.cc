// The user-space UDP CAN bus, for real: nodes in this test process on loopback multicast inside
// a private network namespace (never the machine's own: skipped with the reason if one cannot
// be made). Each test uses its own port, so tests run in one process do not see each other.
#include "drivers/can/udp_can_bus.h"

#include <arpa/inet.h>
#include <linux/can/error.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "drivers/can/can_url.h"
#include "drivers/can/udp_can_datagram.h"
#include "tests/procs/graph_test_support.h"

namespace topay::can {
namespace {

using topay::test::EnterTestNamespace;

constexpr char kGroup[] = "239.255.1.1";

std::string Url(int port) { return std::string("udp://") + kGroup + ":" + std::to_string(port); }

std::unique_ptr<CanBus> OpenNode(int port, CanBusOptions options = {}) {
  std::string error;
  std::unique_ptr<CanBus> bus = OpenCanBus(Url(port), options, &error);
  EXPECT_NE(bus, nullptr) << error;
  return bus;
}

// Every frame `bus` receives until `timeout_s` passes without one.
std::vector<ReceivedCanFrame> Drain(CanBus& bus, double timeout_s = 0.2) {
  std::vector<ReceivedCanFrame> frames;
  ReceivedCanFrame received;
  while (bus.Receive(timeout_s, &received).ok()) frames.push_back(received);
  return frames;
}

// Sends raw bytes to the group from a plain UDP socket (not a bus node).
void SendRaw(int port, const void* bytes, std::size_t size) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(fd, 0);
  const unsigned char ttl = 0;
  setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof(ttl));
  sockaddr_in group{};
  group.sin_family = AF_INET;
  group.sin_port = htons(port);
  inet_pton(AF_INET, kGroup, &group.sin_addr);
  EXPECT_EQ(sendto(fd, bytes, size, 0, reinterpret_cast<const sockaddr*>(&group), sizeof(group)),
            static_cast<ssize_t>(size));
  close(fd);
}

TEST(UdpCanBusTest, ThreeNodesSeeEveryFrameOfTheOthersInOrderButNotTheirOwn) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19001;
  constexpr int kRounds = 50;
  std::vector<std::unique_ptr<CanBus>> nodes;
  for (int k = 0; k < 3; ++k) nodes.push_back(OpenNode(kPort));
  for (const auto& node : nodes) ASSERT_NE(node, nullptr);

  // Round-robin: node k sends id 0x100 + k with (round, k); the bus order is the send order.
  std::vector<CanFrame> sent;
  for (int round = 0; round < kRounds; ++round) {
    for (int k = 0; k < 3; ++k) {
      const CanFrame frame =
          CanFrame::Standard(0x100 + k, {static_cast<std::uint8_t>(round), static_cast<std::uint8_t>(k)});
      const CanResult result = nodes[k]->Send(frame);
      ASSERT_TRUE(result.ok()) << result.message;
      sent.push_back(frame);
    }
  }
  for (int k = 0; k < 3; ++k) {
    std::vector<CanFrame> expected;
    for (const CanFrame& frame : sent) {
      if (frame.id != static_cast<std::uint32_t>(0x100 + k)) expected.push_back(frame);
    }
    const std::vector<ReceivedCanFrame> got = Drain(*nodes[k]);
    ASSERT_EQ(got.size(), expected.size()) << "node " << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].frame, expected[i]) << "node " << k << " frame " << i << ": " << ToString(got[i].frame);
    }
    EXPECT_EQ(nodes[k]->status().frames_sent, static_cast<std::uint64_t>(kRounds));
    EXPECT_EQ(nodes[k]->status().frames_received, expected.size());
    EXPECT_EQ(nodes[k]->status().lost_frames, 0u);
    EXPECT_EQ(nodes[k]->status().malformed, 0u);
  }
}

TEST(UdpCanBusTest, ReceiveOwnFramesIsAnOption) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19002;
  CanBusOptions own;
  own.receive_own_frames = true;
  std::unique_ptr<CanBus> a = OpenNode(kPort, own);
  std::unique_ptr<CanBus> b = OpenNode(kPort);
  ASSERT_TRUE(a && b);
  ASSERT_TRUE(a->Send(CanFrame::Standard(0x1, {1})).ok());
  ASSERT_TRUE(b->Send(CanFrame::Standard(0x2, {2})).ok());
  const std::vector<ReceivedCanFrame> at_a = Drain(*a);
  ASSERT_EQ(at_a.size(), 2u);
  EXPECT_EQ(at_a[0].frame, CanFrame::Standard(0x1, {1}));
  EXPECT_EQ(at_a[1].frame, CanFrame::Standard(0x2, {2}));
  const std::vector<ReceivedCanFrame> at_b = Drain(*b);
  ASSERT_EQ(at_b.size(), 1u);
  EXPECT_EQ(at_b[0].frame, CanFrame::Standard(0x1, {1}));
}

TEST(UdpCanBusTest, FiltersSelectFramesLikeSocketCan) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19003;
  CanBusOptions options;
  options.filters = {CanFilter::Standard(0x180, 0x780), CanFilter::Extended(0x1234)};
  std::unique_ptr<CanBus> receiver = OpenNode(kPort, options);
  std::unique_ptr<CanBus> sender = OpenNode(kPort);
  ASSERT_TRUE(receiver && sender);
  const std::vector<CanFrame> frames = {CanFrame::Standard(0x181), CanFrame::Standard(0x201),
                                        CanFrame::Extended(0x1234), CanFrame::Extended(0x181),
                                        CanFrame::Standard(0x1FF, {7}), CanFrame::Extended(0x1235)};
  for (const CanFrame& frame : frames) ASSERT_TRUE(sender->Send(frame).ok());
  const std::vector<ReceivedCanFrame> got = Drain(*receiver);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].frame, CanFrame::Standard(0x181));
  EXPECT_EQ(got[1].frame, CanFrame::Extended(0x1234));
  EXPECT_EQ(got[2].frame, CanFrame::Standard(0x1FF, {7}));
}

TEST(UdpCanBusTest, MalformedDatagramsAreDroppedAndCounted) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19004;
  std::unique_ptr<CanBus> receiver = OpenNode(kPort);
  std::unique_ptr<CanBus> sender = OpenNode(kPort);
  ASSERT_TRUE(receiver && sender);
  const char garbage[] = "hello";
  SendRaw(kPort, garbage, 5);
  auto bad_dlc = EncodeUdpCanDatagram({0xABCD, 0, CanFrame::Standard(0x10, {1})});
  bad_dlc[20] = 9;
  SendRaw(kPort, bad_dlc.data(), bad_dlc.size());
  std::vector<std::uint8_t> too_long(100, 0xFF);
  SendRaw(kPort, too_long.data(), too_long.size());
  ASSERT_TRUE(sender->Send(CanFrame::Standard(0x321, {3, 2, 1})).ok());

  const std::vector<ReceivedCanFrame> got = Drain(*receiver);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame, CanFrame::Standard(0x321, {3, 2, 1}));
  EXPECT_EQ(receiver->status().malformed, 3u);
  EXPECT_NE(receiver->status().last_error.find("size 100 bytes, expected 32"), std::string::npos)
      << receiver->status().last_error;
  EXPECT_EQ(Drain(*sender).size(), 0u);
  EXPECT_EQ(sender->status().malformed, 3u);  // every node sees (and drops) them
}

TEST(UdpCanBusTest, SequenceGapsCountAsLostFrames) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19005;
  std::unique_ptr<CanBus> receiver = OpenNode(kPort);
  ASSERT_TRUE(receiver);
  for (const std::uint32_t sequence : {10u, 11u, 15u, 16u}) {  // 12, 13, 14 lost
    const auto bytes = EncodeUdpCanDatagram({0x5EED, sequence, CanFrame::Standard(0x7)});
    SendRaw(kPort, bytes.data(), bytes.size());
  }
  EXPECT_EQ(Drain(*receiver).size(), 4u);
  EXPECT_EQ(receiver->status().lost_frames, 3u);
}

TEST(UdpCanBusTest, ReceiveBufferOverflowShowsAsLostFrames) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19008;
  constexpr int kFrames = 200;
  CanBusOptions small;
  small.receive_buffer_bytes = 1;  // the kernel's minimum: a few datagrams
  std::unique_ptr<CanBus> receiver = OpenNode(kPort, small);
  std::unique_ptr<CanBus> sender = OpenNode(kPort);
  ASSERT_TRUE(receiver && sender);
  for (int i = 0; i < kFrames; ++i) ASSERT_TRUE(sender->Send(CanFrame::Standard(0x10)).ok());
  const std::size_t kept = Drain(*receiver).size();
  ASSERT_LT(kept, static_cast<std::size_t>(kFrames));
  EXPECT_EQ(receiver->status().lost_frames, 0u);  // not known until the sender's next frame
  ASSERT_TRUE(sender->Send(CanFrame::Standard(0x11)).ok());
  const std::vector<ReceivedCanFrame> next = Drain(*receiver);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].frame, CanFrame::Standard(0x11));
  EXPECT_EQ(receiver->status().lost_frames, kFrames - kept);
}

TEST(UdpCanBusTest, ErrorFramesDriveTheBusState) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19006;
  std::unique_ptr<CanBus> node = OpenNode(kPort);
  CanBusOptions recorder_options;
  recorder_options.deliver_error_frames = true;
  std::unique_ptr<CanBus> recorder = OpenNode(kPort, recorder_options);
  std::unique_ptr<CanBus> simulator = OpenNode(kPort);
  ASSERT_TRUE(node && recorder && simulator);

  ASSERT_TRUE(simulator->Send(MakeCanErrorFrame(0, CAN_ERR_CRTL_TX_PASSIVE)).ok());
  ASSERT_TRUE(simulator->Send(MakeCanErrorFrame(CAN_ERR_BUSOFF)).ok());
  EXPECT_EQ(Drain(*node).size(), 0u);  // error frames are not delivered by default...
  EXPECT_EQ(node->status().state, CanBusState::kBusOff);  // ...but they set the state
  EXPECT_EQ(node->status().error_frames, 2u);
  EXPECT_EQ(node->status().bus_off_count, 1u);
  EXPECT_EQ(node->status().last_error, "bus-off");
  const std::vector<ReceivedCanFrame> recorded = Drain(*recorder);
  ASSERT_EQ(recorded.size(), 2u);
  EXPECT_TRUE(recorded[1].frame.error);
  EXPECT_EQ(recorder->status().state, CanBusState::kBusOff);

  const CanResult refused = node->Send(CanFrame::Standard(0x1));
  EXPECT_EQ(refused.code, CanResult::Code::kBusOff);  // a bus-off node does not transmit
  EXPECT_EQ(refused.message, Url(kPort) + ": bus-off, waiting for a restart (CAN_ERR_RESTARTED)");

  ASSERT_TRUE(simulator->Send(MakeCanErrorFrame(CAN_ERR_RESTARTED)).ok());
  Drain(*node);
  EXPECT_EQ(node->status().state, CanBusState::kErrorActive);
  EXPECT_TRUE(node->Send(CanFrame::Standard(0x1)).ok());
}

TEST(UdpCanBusTest, KernelTimestampsTimeoutsAndReopen) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  constexpr int kPort = 19007;
  std::unique_ptr<CanBus> a = OpenNode(kPort);
  std::unique_ptr<CanBus> b = OpenNode(kPort);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->url(), Url(kPort));
  EXPECT_GE(a->fd(), 0);

  ReceivedCanFrame received;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(b->Receive(0.05, &received).code, CanResult::Code::kTimeout);
  const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(waited_s, 0.045);
  EXPECT_LT(waited_s, 1.0);

  const std::int64_t before_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::system_clock::now().time_since_epoch()).count();
  ASSERT_TRUE(a->Send(CanFrame::Standard(0x55, {0x55})).ok());
  ASSERT_TRUE(b->Receive(1.0, &received).ok());
  EXPECT_TRUE(received.kernel_timestamp);
  EXPECT_GE(received.timestamp_ns, before_ns - 1'000'000);  // realtime clock, as candump's
  EXPECT_LT(received.timestamp_ns, before_ns + 1'000'000'000);

  ASSERT_TRUE(b->Reopen().ok());
  EXPECT_EQ(b->status().reopen_count, 1u);
  ASSERT_TRUE(a->Send(CanFrame::Standard(0x56)).ok());
  ASSERT_TRUE(b->Receive(1.0, &received).ok());
  EXPECT_EQ(received.frame, CanFrame::Standard(0x56));

  CanFrame invalid = CanFrame::Standard(0x1);
  invalid.dlc = 9;
  const CanResult result = a->Send(invalid);
  EXPECT_EQ(result.code, CanResult::Code::kInvalidFrame);
  EXPECT_EQ(result.message, "invalid frame: DLC 9 is above 8");
}

}  // namespace
}  // namespace topay::can
