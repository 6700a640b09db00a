#include "sim/plan/base_limit_choice.h"

namespace topay::plan {

std::string_view BaseLimitChoiceName(BaseLimitChoice choice) {
  return choice == BaseLimitChoice::kBenchmark ? "benchmark" : "robot";
}

std::optional<BaseLimitChoice> ParseBaseLimitChoice(std::string_view name) {
  if (name == "benchmark") return BaseLimitChoice::kBenchmark;
  if (name == "robot") return BaseLimitChoice::kRobot;
  return std::nullopt;
}

BaseLimits BenchmarkBaseLimits() {
  BaseLimits limits;
  limits.v_max_mps = 1.0;
  limits.a_max_mps2 = 0.8;
  limits.omega_max_radps = 1.25;
  limits.beta_max_radps2 = 1.0;
  return limits;
}

BaseLimits ChooseBaseLimits(BaseLimitChoice choice, const RobotModel& model) {
  return choice == BaseLimitChoice::kBenchmark ? BenchmarkBaseLimits() : model.base_limits;
}

std::string_view BaseLimitChoiceDescription(BaseLimitChoice choice) {
  return choice == BaseLimitChoice::kBenchmark
             ? "the paper's simulation benchmark limits (facts sheet; --base-limits robot for "
               "the robot config's)"
             : "the robot config's limits (--base-limits benchmark for the paper's simulation "
               "benchmark)";
}

}  // namespace topay::plan
