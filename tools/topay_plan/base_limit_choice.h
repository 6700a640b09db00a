#pragma once

#include <optional>
#include <string_view>

#include "core/robot/robot_model.h"

namespace topay::plan {

/// Which base limits a plan uses.
enum class BaseLimitChoice {
  /// The authors' simulation benchmark (their code): v_max 1.0 m/s, a_max 0.8 m/s^2,
  /// omega_max 1.25 rad/s, beta_max 1.0 rad/s^2, so durations compare with the paper's.
  kBenchmark,
  /// The robot config's own (config/robot/topay_mm.yaml: the real robot's omega_max 0.9).
  kRobot,
  /// The planner YAML's `planner.base_limits` (config/planner/topay.yaml).
  kConfig,
};

/// "benchmark", "robot" or "config".
std::string_view BaseLimitChoiceName(BaseLimitChoice choice);
/// Inverse of BaseLimitChoiceName; nullopt for anything else.
std::optional<BaseLimitChoice> ParseBaseLimitChoice(std::string_view name);

/// The paper's simulation benchmark limits (see kBenchmark).
BaseLimits BenchmarkBaseLimits();

/// The limits of `choice` for a robot model; `configured`: the planner YAML's
/// planner.base_limits (unset if it has none). Throws tools::UsageError for kConfig
/// without configured limits.
BaseLimits ChooseBaseLimits(BaseLimitChoice choice, const RobotModel& model,
                            const std::optional<BaseLimits>& configured = std::nullopt);

/// The choice in force: the flag's when given; else kConfig when the planner YAML sets
/// planner.base_limits; else kBenchmark (the tools' default, so durations compare with the
/// paper's).
BaseLimitChoice BaseLimitChoiceInForce(const std::optional<BaseLimitChoice>& flag,
                                       const std::optional<BaseLimits>& configured);

/// One line saying which limits these are, e.g. "the paper's simulation benchmark limits
/// (the authors' simulation benchmark)", "the robot config's limits" or "the planner config's limits".
std::string_view BaseLimitChoiceDescription(BaseLimitChoice choice);

}  // namespace topay::plan
