// The bridge's two new messages (drive_status_t, drive_command_t): full round trip, and the
// hardened, checked decoder refusing truncated buffers and hostile array lengths.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay {
namespace {

template <class Msg>
std::vector<std::uint8_t> Encode(const Msg& msg) {
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  EXPECT_EQ(msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  return bytes;
}

drive_status_t SampleStatus() {
  drive_status_t m{};
  m.utime = 1'700'000'000'123'456;
  m.state = drive_status_t::FAULT;
  m.stop_reason = "drive fault: joint3 (node 3) in Fault, last EMCY 0x2310";
  m.can_url = "socketcan://can0";
  m.bus_state = "error-passive";
  m.frames_sent = 123456;
  m.frames_received = 234567;
  m.error_frames = 3;
  m.bus_off_count = 1;
  m.tx_refused = 17;
  m.frames_malformed = 4;
  m.frames_unknown = 2;
  m.bus_load_percent = 47.5;
  m.command_age_s = 0.012;
  m.commands_received = 999;
  m.commands_rejected = 1;
  m.clamp_count = 55;
  m.command_latency_p99_ms = 0.14;
  m.cycle_jitter_p99_ms = 0.6;
  m.base_mode = 2;
  m.base_fault_bits = 0x0101;
  m.base_faults = "over-current, left motor stall";
  m.base_status_age_s = 0.04;
  m.base_battery_v = 47.9;
  m.num_drives = 7;
  for (int i = 0; i < 7; ++i) {
    m.node_id.push_back(i + 1);
    m.joint_name.push_back("joint" + std::to_string(i + 1));
    m.drive_state.push_back(i == 2 ? "Fault" : "Switch on disabled");
    m.nmt_state.push_back("operational");
    m.statusword.push_back(i == 2 ? 0x0008 : 0x0040);
    m.last_emcy_code.push_back(i == 2 ? 0x2310 : 0);
    m.heartbeat_age_s.push_back(0.01 * i);
  }
  return m;
}

TEST(DriveMessagesTest, StatusRoundTrip) {
  const drive_status_t m = SampleStatus();
  const std::vector<std::uint8_t> bytes = Encode(m);
  std::string error;
  const auto back = CheckedDecode<drive_status_t>(bytes.data(), bytes.size(), &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->state, m.state);
  EXPECT_EQ(back->stop_reason, m.stop_reason);
  EXPECT_EQ(back->bus_state, m.bus_state);
  EXPECT_EQ(back->frames_received, m.frames_received);
  EXPECT_EQ(back->bus_load_percent, m.bus_load_percent);
  EXPECT_EQ(back->base_faults, m.base_faults);
  EXPECT_EQ(back->joint_name, m.joint_name);
  EXPECT_EQ(back->drive_state, m.drive_state);
  EXPECT_EQ(back->statusword, m.statusword);
  EXPECT_EQ(back->last_emcy_code, m.last_emcy_code);
  EXPECT_EQ(back->heartbeat_age_s, m.heartbeat_age_s);
  EXPECT_EQ(channels::DRIVE_STATUS, "DRIVE_STATUS");
}

TEST(DriveMessagesTest, CommandRoundTrip) {
  drive_command_t m{};
  m.utime = 5;
  m.command = drive_command_t::FAULT_RESET;
  m.source = "operator";
  const std::vector<std::uint8_t> bytes = Encode(m);
  const auto back = CheckedDecode<drive_command_t>(bytes.data(), bytes.size(), nullptr);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->command, drive_command_t::FAULT_RESET);
  EXPECT_EQ(back->source, "operator");
  EXPECT_EQ(channels::DRIVE_COMMAND, "DRIVE_COMMAND");
}

TEST(DriveMessagesTest, TruncatedAndHostileBuffersAreRefused) {
  const std::vector<std::uint8_t> bytes = Encode(SampleStatus());
  for (std::size_t size = 0; size < bytes.size(); size += 7) {
    EXPECT_FALSE(CheckedDecode<drive_status_t>(bytes.data(), size, nullptr)) << size;
  }
  // num_drives is the int32 after the fixed fields; find it by its value 7 followed by node id 1.
  std::vector<std::uint8_t> hostile = bytes;
  bool patched = false;
  for (std::size_t i = 8; i + 8 <= hostile.size(); ++i) {
    const std::uint8_t seven[8] = {0, 0, 0, 7, 0, 0, 0, 1};  // big-endian num_drives, node_id[0]
    if (std::memcmp(&hostile[i], seven, 8) == 0) {
      hostile[i] = 0x7F;  // about two billion drives
      patched = true;
      break;
    }
  }
  ASSERT_TRUE(patched);
  EXPECT_FALSE(CheckedDecode<drive_status_t>(hostile.data(), hostile.size(), nullptr));
}

}  // namespace
}  // namespace topay
