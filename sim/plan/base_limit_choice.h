#pragma once

#include <optional>
#include <string_view>

#include "core/robot/robot_model.h"

namespace topay::plan {

/// Which base limits a plan uses.
enum class BaseLimitChoice {
  /// The authors' simulation benchmark (facts sheet): v_max 1.0 m/s, a_max 0.8 m/s^2,
  /// omega_max 1.25 rad/s, beta_max 1.0 rad/s^2, so durations compare with the paper's.
  kBenchmark,
  /// The robot config's own (config/robot/topay_mm.yaml: the real robot's omega_max 0.9).
  kRobot,
};

/// "benchmark" or "robot".
std::string_view BaseLimitChoiceName(BaseLimitChoice choice);
/// Inverse of BaseLimitChoiceName; nullopt for anything else.
std::optional<BaseLimitChoice> ParseBaseLimitChoice(std::string_view name);

/// The paper's simulation benchmark limits (see kBenchmark).
BaseLimits BenchmarkBaseLimits();

/// The limits of `choice` for a robot model.
BaseLimits ChooseBaseLimits(BaseLimitChoice choice, const RobotModel& model);

/// One line saying which limits these are, e.g. "the paper's simulation benchmark limits
/// (facts sheet)" or "the robot config's limits".
std::string_view BaseLimitChoiceDescription(BaseLimitChoice choice);

}  // namespace topay::plan
