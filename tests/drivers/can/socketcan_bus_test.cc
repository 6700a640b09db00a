// The SocketCAN backend. These machines' kernel has no AF_CAN: opening fails with a clear
// error (tested), and the tests on a real socket are SKIPPED with the reason. With AF_CAN and a
// vcan0 interface (a guest kernel, docs/can.md) they run.
#include "drivers/can/socketcan_bus.h"

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/can_url.h"
#include "drivers/can/candump_log.h"

namespace topay::can {
namespace {

// Empty when this kernel has AF_CAN, else why not.
std::string NoAfCanReason() {
  const int fd = socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd >= 0) {
    close(fd);
    return "";
  }
  return std::string("socket(PF_CAN, SOCK_RAW, CAN_RAW): ") + std::strerror(errno);
}

// Empty when real-socket tests can run on vcan0, else why not (for GTEST_SKIP).
std::string NoVcanReason() {
  const std::string no_af_can = NoAfCanReason();
  if (!no_af_can.empty()) return "AF_CAN not supported by this kernel (" + no_af_can + "); run in a guest kernel with vcan0";
  if (if_nametoindex("vcan0") == 0) return "no vcan0 interface (ip link add dev vcan0 type vcan; ip link set up vcan0)";
  return "";
}

TEST(SocketCanBusTest, OpeningWithoutAfCanGivesAClearError) {
  if (NoAfCanReason().empty()) GTEST_SKIP() << "this kernel has AF_CAN: the error path cannot be seen here";
  std::string error;
  EXPECT_EQ(OpenCanBus("socketcan://can0", {}, &error), nullptr);
  EXPECT_EQ(error.rfind("socketcan://can0: AF_CAN not supported by this kernel (socket(PF_CAN, SOCK_RAW, CAN_RAW): ", 0), 0u)
      << error;
  EXPECT_NE(error.find("use a kernel with CAN support (modules can, can_raw) or a udp:// bus"), std::string::npos) << error;
}

TEST(SocketCanBusTest, MissingInterfaceIsNamed) {
  if (!NoAfCanReason().empty()) GTEST_SKIP() << "AF_CAN not supported by this kernel (" << NoAfCanReason() << ")";
  std::string error;
  EXPECT_EQ(OpenCanBus("socketcan://nosuchcan9", {}, &error), nullptr);
  EXPECT_NE(error.find("no CAN interface 'nosuchcan9'"), std::string::npos) << error;
}

TEST(SocketCanBusTest, KernelFilterListAndErrnoMapping) {
  const std::vector<struct can_filter> filters = ToKernelFilters({CanFilter::Standard(0x123), CanFilter::Extended(0x5)});
  ASSERT_EQ(filters.size(), 2u);
  EXPECT_EQ(filters[0].can_id, 0x123u);
  EXPECT_EQ(filters[0].can_mask, CAN_SFF_MASK | CAN_EFF_FLAG);
  EXPECT_EQ(filters[1].can_id, 0x5u | CAN_EFF_FLAG);
  EXPECT_EQ(SendErrorCode(ENOBUFS), CanResult::Code::kTxQueueFull);
  EXPECT_EQ(SendErrorCode(EAGAIN), CanResult::Code::kTxQueueFull);
  EXPECT_EQ(SendErrorCode(ENETDOWN), CanResult::Code::kInterfaceDown);
  EXPECT_EQ(SendErrorCode(ENODEV), CanResult::Code::kInterfaceDown);
  EXPECT_EQ(SendErrorCode(EIO), CanResult::Code::kIoError);
}

std::unique_ptr<CanBus> OpenVcan(const CanBusOptions& options = {}) {
  std::string error;
  std::unique_ptr<CanBus> bus = OpenCanBus("socketcan://vcan0", options, &error);
  EXPECT_NE(bus, nullptr) << error;
  return bus;
}

TEST(SocketCanBusTest, FramesBetweenTwoSocketsWithKernelTimestamps) {
  const std::string why = NoVcanReason();
  if (!why.empty()) GTEST_SKIP() << why;
  std::unique_ptr<CanBus> a = OpenVcan();
  std::unique_ptr<CanBus> b = OpenVcan();
  ASSERT_TRUE(a && b);
  for (const CanFrame& frame : {CanFrame::Standard(0x123, {0xDE, 0xAD}), CanFrame::Extended(0x12345678, {1}),
                                CanFrame::Remote(0x7FF, 2)}) {
    ASSERT_TRUE(a->Send(frame).ok());
    ReceivedCanFrame received;
    const CanResult result = b->Receive(1.0, &received);
    ASSERT_TRUE(result.ok()) << result.message;
    EXPECT_EQ(received.frame, frame);
    EXPECT_TRUE(received.kernel_timestamp);
  }
  ReceivedCanFrame own;
  EXPECT_EQ(a->Receive(0.05, &own).code, CanResult::Code::kTimeout);  // not its own frames
}

TEST(SocketCanBusTest, KernelFiltersAndReopen) {
  const std::string why = NoVcanReason();
  if (!why.empty()) GTEST_SKIP() << why;
  CanBusOptions options;
  options.filters = {CanFilter::Standard(0x200)};
  std::unique_ptr<CanBus> receiver = OpenVcan(options);
  std::unique_ptr<CanBus> sender = OpenVcan();
  ASSERT_TRUE(receiver && sender);
  ASSERT_TRUE(sender->Send(CanFrame::Standard(0x100)).ok());
  ASSERT_TRUE(sender->Send(CanFrame::Standard(0x200, {2})).ok());
  ReceivedCanFrame received;
  ASSERT_TRUE(receiver->Receive(1.0, &received).ok());
  EXPECT_EQ(received.frame, CanFrame::Standard(0x200, {2}));
  ASSERT_TRUE(receiver->Reopen().ok());
  ASSERT_TRUE(sender->Send(CanFrame::Standard(0x200, {3})).ok());
  ASSERT_TRUE(receiver->Receive(1.0, &received).ok());
  EXPECT_EQ(received.frame, CanFrame::Standard(0x200, {3}));
  const CanResult error_frame = sender->Send(MakeCanErrorFrame(CAN_ERR_BUSOFF));
  EXPECT_EQ(error_frame.code, CanResult::Code::kInvalidFrame);
}

// can-utils on the same vcan0: candump -L records what our socket sends (read back with our
// candump parser), and our socket receives what cansend puts on the bus.
TEST(SocketCanBusTest, CanUtilsSeeOurFramesAndWeSeeTheirs) {
  const std::string why = NoVcanReason();
  if (!why.empty()) GTEST_SKIP() << why;
  if (std::system("command -v candump >/dev/null && command -v cansend >/dev/null") != 0)
    GTEST_SKIP() << "can-utils (candump, cansend) not installed: make deps installs it";
  std::unique_ptr<CanBus> bus = OpenVcan();
  ASSERT_TRUE(bus);
  const std::string log = "/tmp/socketcan_bus_test_candump.log";
  std::remove(log.c_str());
  ASSERT_EQ(std::system(("stdbuf -oL candump -L vcan0 > " + log + " & echo $! > " + log + ".pid").c_str()), 0);
  // Probe frames until candump records one (its socket is bound: a slow guest takes a while).
  const CanFrame probe = CanFrame::Standard(0x7FF, {0xAA});
  const auto lines = [&log] {
    std::ifstream in(log);
    std::vector<CandumpRecord> records;
    std::string error;
    ReadCandumpLog(in, &records, &error);
    return records;
  };
  for (int i = 0; i < 100 && lines().empty(); ++i) {
    ASSERT_TRUE(bus->Send(probe).ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_FALSE(lines().empty()) << "candump recorded nothing in 10 s";
  const std::vector<CanFrame> sent = {CanFrame::Standard(0x181, {1, 2, 3, 4, 5, 6, 7, 8}),
                                      CanFrame::Extended(0x1ABCDEF0, {0x55}), CanFrame::Standard(0x80)};
  for (const CanFrame& frame : sent) ASSERT_TRUE(bus->Send(frame).ok());
  for (int i = 0; i < 100 && (lines().empty() || lines().back().frame != sent.back()); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::system(("kill $(cat " + log + ".pid)").c_str());
  std::vector<CandumpRecord> records = lines();
  while (!records.empty() && records.front().frame == probe) records.erase(records.begin());
  ASSERT_EQ(records.size(), sent.size());
  for (size_t i = 0; i < sent.size(); ++i) {
    EXPECT_EQ(records[i].interface, "vcan0");
    EXPECT_EQ(records[i].frame, sent[i]) << i;
  }
  ASSERT_EQ(std::system("cansend vcan0 201#0A0B0C0D00000102"), 0);
  ReceivedCanFrame received;
  const CanResult result = bus->Receive(2.0, &received);
  ASSERT_TRUE(result.ok()) << result.message;
  EXPECT_EQ(received.frame, CanFrame::Standard(0x201, {0x0A, 0x0B, 0x0C, 0x0D, 0, 0, 1, 2}));
}

}  // namespace
}  // namespace topay::can
