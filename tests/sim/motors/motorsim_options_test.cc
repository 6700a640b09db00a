// MotorSimOptions from YAML (sim/motors/motorsim_options.h): the shipped config gives the
// documented defaults; keys are read; errors name the file and the key.

#include "sim/motors/motorsim_options.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/common/config_test_file.h"

namespace topay::sim::motors {
namespace {

std::string ErrorOf(const std::string& yaml) {
  return topay::test::ConfigErrorOf([&] { ParseMotorSimOptions(yaml, "m.yaml"); });
}

TEST(MotorSimOptionsTest, ShippedConfigHasTheDefaults) {
  const MotorSimOptions o = LoadMotorSimOptions(std::string(TOPAY_SOURCE_DIR) + "/config/sim/motorsim.yaml");
  const MotorSimOptions d;
  EXPECT_EQ(o.step_period_s, d.step_period_s);
  EXPECT_EQ(o.base.node_id, d.base.node_id);
  EXPECT_EQ(o.base.geometry.ticks_per_rev, d.base.geometry.ticks_per_rev);
  EXPECT_EQ(o.base.modes.command_timeout_s, d.base.modes.command_timeout_s);
  EXPECT_EQ(o.base.modes.timeout_mode, d.base.modes.timeout_mode);
  EXPECT_EQ(o.base.quick_stop_decel_mps2, d.base.quick_stop_decel_mps2);
  EXPECT_EQ(o.joint_node_ids, d.joint_node_ids);
  EXPECT_EQ(o.drive.producer_heartbeat_ms, d.drive.producer_heartbeat_ms);
  EXPECT_EQ(o.drive.fault_emcy_code, d.drive.fault_emcy_code);
  EXPECT_EQ(o.drive.quick_stop_decel_radps2, d.drive.quick_stop_decel_radps2);
  EXPECT_EQ(o.faults.rx_loss_percent, 0.0);
  EXPECT_TRUE(o.faults.events.empty());
  EXPECT_EQ(o.stalled_plant.stale_after_s, d.stalled_plant.stale_after_s);
  EXPECT_EQ(o.stalled_plant.carry_on_s, d.stalled_plant.carry_on_s);
}

TEST(MotorSimOptionsTest, ReadsKeysAndEvents) {
  const MotorSimOptions o = ParseMotorSimOptions(R"(
base: {node_id: 20, timeout_mode: standby, command_timeout_s: 0.2}
drives: {node_ids: [11, 12, 13, 14, 15, 16, 17], producer_heartbeat_ms: 50}
faults:
  seed: 9
  rx_loss_percent: 5
  events:
    - {kind: bus_off, at_s: 2.0, duration_s: 0.5}
    - {kind: drive_fault, joint: 7, at_s: 1.0, code: 8976}
stalled_plant: {stale_after_s: 0.05, carry_on_s: 0.5}
)", "m.yaml");
  EXPECT_EQ(o.stalled_plant.stale_after_s, 0.05);
  EXPECT_EQ(o.stalled_plant.carry_on_s, 0.5);
  EXPECT_EQ(o.base.node_id, 20);
  EXPECT_EQ(o.base.modes.timeout_mode, base::BaseMode::kStandby);
  EXPECT_EQ(o.base.modes.command_timeout_s, 0.2);
  EXPECT_EQ(o.joint_node_ids.back(), 17);
  EXPECT_EQ(o.drive.producer_heartbeat_ms, 50);
  EXPECT_EQ(o.faults.seed, 9u);
  EXPECT_EQ(o.faults.rx_loss_percent, 5.0);
  ASSERT_EQ(o.faults.events.size(), 2u);
  EXPECT_EQ(o.faults.events[1].kind, FaultKind::kDriveFault);
  EXPECT_EQ(o.faults.events[1].code, 8976);
}

TEST(MotorSimOptionsTest, ErrorsNameTheFileAndKey) {
  EXPECT_NE(ErrorOf("base: {node_idd: 3}").find("m.yaml: base.node_idd"), std::string::npos);
  EXPECT_NE(ErrorOf("base: {timeout_mode: coast}").find("base.timeout_mode"), std::string::npos);
  EXPECT_NE(ErrorOf("base: {node_id: 3}").find("used twice"), std::string::npos);
  EXPECT_NE(ErrorOf("faults: {rx_loss_percent: 120}").find("faults"), std::string::npos);
  EXPECT_NE(ErrorOf("faults: {events: [{kind: meltdown}]}").find("faults.events[0].kind"), std::string::npos);
  EXPECT_NE(ErrorOf("faults: {events: [{kind: drive_fault, joint: 9}]}").find("joint 9"), std::string::npos);
  EXPECT_NE(ErrorOf("drives: {node_ids: [1.5]}").find("drives.node_ids"), std::string::npos);
  EXPECT_NE(ErrorOf("step_period_s: [").find("malformed YAML"), std::string::npos);
  EXPECT_NE(ErrorOf("stalled_plant: {stale_after_s: 0}").find("stalled_plant: stale_after_s must be > 0"),
            std::string::npos);
  EXPECT_NE(ErrorOf("stalled_plant: {carry_on: 1}").find("stalled_plant.carry_on"), std::string::npos);
  EXPECT_EQ(ErrorOf(""), "") << "every key is optional";
}

}  // namespace
}  // namespace topay::sim::motors
