// Seeded commands (procs/command_pattern/command_pattern.h): a function of (seed, index) only.

#include "procs/command_pattern/command_pattern.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::pattern {
namespace {

TEST(CommandPattern, DependsOnlyOnSeedAndIndex) {
  CommandPatternOptions options;
  options.seed = 5;
  const control_command_t a = PatternCommand(options, 17, 100);
  const control_command_t b = PatternCommand(options, 17, 999);
  EXPECT_EQ(a.v_mps, b.v_mps);
  EXPECT_EQ(a.qdot_radps, b.qdot_radps);
  EXPECT_EQ(a.trajectory_id, 18);
  EXPECT_EQ(b.utime, 999);
  EXPECT_NE(PatternCommand(options, 18, 100).v_mps, a.v_mps);
  options.seed = 6;
  EXPECT_NE(PatternCommand(options, 17, 100).v_mps, a.v_mps);
}

TEST(CommandPattern, StaysWithinItsBounds) {
  CommandPatternOptions options;
  for (int i = 0; i < 200; ++i) {
    const control_command_t cmd = PatternCommand(options, i, 0);
    EXPECT_LE(std::abs(cmd.v_mps), options.max_v_mps);
    EXPECT_LE(std::abs(cmd.omega_radps), options.max_omega_radps);
    ASSERT_EQ(cmd.num_joints, 7);
    ASSERT_EQ(cmd.qdot_radps.size(), 7u);
    for (const double q : cmd.qdot_radps) EXPECT_LE(std::abs(q), options.max_qdot_radps);
    EXPECT_GE(cmd.gripper, 0.0);
    EXPECT_LE(cmd.gripper, 1.0);
  }
}

}  // namespace
}  // namespace topay::pattern
