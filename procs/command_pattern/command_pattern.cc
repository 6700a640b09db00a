#include "procs/command_pattern/command_pattern.h"

#include <random>

namespace topay::pattern {

control_command_t PatternCommand(const CommandPatternOptions& options, std::int64_t index,
                                 std::int64_t utime) {
  // One generator per command, seeded from (seed, index): no state between commands.
  std::seed_seq seq{static_cast<std::uint32_t>(options.seed), static_cast<std::uint32_t>(options.seed >> 32),
                    static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  control_command_t cmd;
  cmd.utime = utime;
  cmd.trajectory_id = index + 1;
  cmd.v_mps = options.max_v_mps * unit(rng);
  cmd.omega_radps = options.max_omega_radps * unit(rng);
  cmd.num_joints = options.num_joints;
  for (int j = 0; j < options.num_joints; ++j) cmd.qdot_radps.push_back(options.max_qdot_radps * unit(rng));
  cmd.gripper = 0.5 * (1.0 + unit(rng));
  return cmd;
}

}  // namespace topay::pattern
