// topay-canbridge's options: the shipped config is the documented defaults; errors name the
// file and the key.
#include "procs/canbridge/canbridge_options.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "tests/common/config_test_file.h"

namespace topay::canbridge {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  return topay::test::WriteTestFile("procs/canbridge_options", name, text);
}

std::string ErrorOf(const std::string& text) {
  return topay::test::ConfigErrorOf([&] { LoadCanbridgeOptions(Write("bad.yaml", text)); });
}

TEST(CanbridgeOptionsTest, ShippedConfigIsTheDefaults) {
  const CanbridgeOptions o = LoadCanbridgeOptions(std::string(TOPAY_SOURCE_DIR) + "/config/canbridge/canbridge.yaml");
  const CanbridgeOptions d;
  EXPECT_EQ(o.can_url, d.can_url);
  EXPECT_EQ(o.cycle_period_s, d.cycle_period_s);
  EXPECT_EQ(o.command_timeout_s, d.command_timeout_s);
  EXPECT_EQ(o.recovery_hold_s, d.recovery_hold_s);
  EXPECT_EQ(o.bit_rate_bps, d.bit_rate_bps);
  EXPECT_EQ(o.base.node_id, d.base.node_id);
  EXPECT_EQ(o.base.status_timeout_s, d.base.status_timeout_s);
  EXPECT_EQ(o.base.geometry.wheel_radius_m, d.base.geometry.wheel_radius_m);
  EXPECT_EQ(o.drives.node_ids, d.drives.node_ids);
  EXPECT_EQ(o.drives.heartbeat_timeout_s, d.drives.heartbeat_timeout_s);
  EXPECT_EQ(o.drives.startup.consumer_heartbeat_ms, d.drives.startup.consumer_heartbeat_ms);
  EXPECT_EQ(o.drives.startup.rpdo_deadline_ms, d.drives.startup.rpdo_deadline_ms);
  EXPECT_EQ(o.drives.sdo_attempts, d.drives.sdo_attempts);
  EXPECT_EQ(o.auto_reset_communication_faults, d.auto_reset_communication_faults);
  EXPECT_EQ(o.max_auto_resets_per_minute, d.max_auto_resets_per_minute);
}

TEST(CanbridgeOptionsTest, ReadsValues) {
  const CanbridgeOptions o = LoadCanbridgeOptions(
      Write("good.yaml", "can_url: socketcan://can0\ncommand_timeout_s: 0.05\nbase: {node_id: 20}\n"
                         "drives: {node_ids: [11, 12, 13, 14, 15, 16, 17], pdo_timeout_s: 0, rpdo_deadline_ms: 0}\n"));
  EXPECT_EQ(o.can_url, "socketcan://can0");
  EXPECT_EQ(o.command_timeout_s, 0.05);
  EXPECT_EQ(o.base.node_id, 20);
  EXPECT_EQ(o.drives.node_ids.front(), 11);
  EXPECT_EQ(o.drives.pdo_timeout_s, 0.0);
  EXPECT_EQ(o.drives.startup.rpdo_deadline_ms, 0);
}

TEST(CanbridgeOptionsTest, ErrorsNameTheFileAndKey) {
  EXPECT_NE(ErrorOf("comand_timeout_s: 1\n").find("comand_timeout_s"), std::string::npos);
  EXPECT_NE(ErrorOf("comand_timeout_s: 1\n").find("bad.yaml"), std::string::npos);
  EXPECT_NE(ErrorOf("command_timeout_s: 0.001\n").find("command_timeout_s"), std::string::npos);
  EXPECT_NE(ErrorOf("max_auto_resets_per_minute: -1\n").find("max_auto_resets_per_minute"), std::string::npos);
  EXPECT_NE(ErrorOf("auto_reset_communication_faults: maybe\n").find("auto_reset_communication_faults"),
            std::string::npos);
  EXPECT_NE(ErrorOf("base: {node_id: 3}\n").find("drives.node_ids"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {node_ids: [1, 1, 2, 3, 4, 5, 6]}\n").find("appears twice"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {node_ids: [1.5]}\n").find("drives.node_ids"), std::string::npos);
  // A whole number far outside int was converted to int first (undefined behaviour; the error
  // then named whatever int came out): the error names the value given (config_yaml fuzz
  // target, tests/fuzz/regressions/config_yaml/canbridge_node_id_range).
  EXPECT_NE(ErrorOf("drives: {node_ids: [1e300]}\n").find("drives.node_ids: node id 1e+300 is outside 1..127"),
            std::string::npos);
  EXPECT_NE(ErrorOf("drives: {node_ids: [-4294967297]}\n").find("node id -4294967297 is outside"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {node_ids: [0]}\n").find("node id 0 is outside 1..127"), std::string::npos);
  EXPECT_NE(ErrorOf("base: {wheel_radius_m: -1}\n").find("base"), std::string::npos);
  // An RPDO deadline shorter than 3 CAN cycles (5 ms each) or beyond the uint16 event timer.
  EXPECT_NE(ErrorOf("drives: {rpdo_deadline_ms: 10}\n").find("drives.rpdo_deadline_ms"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {rpdo_deadline_ms: 65536}\n").find("drives.rpdo_deadline_ms"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {rpdo_deadline_ms: -5}\n").find("drives.rpdo_deadline_ms"), std::string::npos);
}

}  // namespace
}  // namespace topay::canbridge
