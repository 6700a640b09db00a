#pragma once
// Seeded velocity commands for tests and demos: command i of seed S is always the same.

#include <cstdint>

#include "topay/control_command_t.hpp"

namespace topay::pattern {

struct CommandPatternOptions {
  std::uint64_t seed = 1;     ///< the pattern
  int num_joints = 7;         ///< joint rate commands per message
  double max_v_mps = 0.5;     ///< |v| <= this, m/s
  double max_omega_radps = 0.5;  ///< |omega| <= this, rad/s
  double max_qdot_radps = 0.2;   ///< |qdot| <= this, rad/s
};

/// Command `index` of the pattern, stamped `utime` (us since the Unix epoch); trajectory_id is
/// index + 1. Values depend only on (seed, index).
control_command_t PatternCommand(const CommandPatternOptions& options, std::int64_t index,
                                 std::int64_t utime);

}  // namespace topay::pattern
