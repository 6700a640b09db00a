#include "tools/topay_plan/base_limit_choice.h"

#include "tools/common/usage_error.h"

namespace topay::plan {

std::string_view BaseLimitChoiceName(BaseLimitChoice choice) {
  switch (choice) {
    case BaseLimitChoice::kBenchmark: return "benchmark";
    case BaseLimitChoice::kRobot: return "robot";
    case BaseLimitChoice::kConfig: return "config";
  }
  return "benchmark";
}

std::optional<BaseLimitChoice> ParseBaseLimitChoice(std::string_view name) {
  if (name == "benchmark") return BaseLimitChoice::kBenchmark;
  if (name == "robot") return BaseLimitChoice::kRobot;
  if (name == "config") return BaseLimitChoice::kConfig;
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

BaseLimits ChooseBaseLimits(BaseLimitChoice choice, const RobotModel& model,
                            const std::optional<BaseLimits>& configured) {
  switch (choice) {
    case BaseLimitChoice::kBenchmark: return BenchmarkBaseLimits();
    case BaseLimitChoice::kRobot: return model.base_limits;
    case BaseLimitChoice::kConfig:
      if (!configured) {
        throw tools::UsageError(
            "--base-limits config: the planner YAML sets no planner.base_limits");
      }
      return *configured;
  }
  return BenchmarkBaseLimits();
}

BaseLimitChoice BaseLimitChoiceInForce(const std::optional<BaseLimitChoice>& flag,
                                       const std::optional<BaseLimits>& configured) {
  if (flag) return *flag;
  return configured ? BaseLimitChoice::kConfig : BaseLimitChoice::kBenchmark;
}

std::string_view BaseLimitChoiceDescription(BaseLimitChoice choice) {
  switch (choice) {
    case BaseLimitChoice::kBenchmark:
      return "the paper's simulation benchmark limits (the authors' simulation benchmark; --base-limits robot for "
             "the robot config's)";
    case BaseLimitChoice::kRobot:
      return "the robot config's limits (--base-limits benchmark for the paper's simulation "
             "benchmark)";
    case BaseLimitChoice::kConfig:
      return "the planner config's limits (planner.base_limits; --base-limits overrides them)";
  }
  return "";
}

}  // namespace topay::plan
