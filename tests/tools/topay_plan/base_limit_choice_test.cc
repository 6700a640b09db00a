#include "tools/topay_plan/base_limit_choice.h"

#include <gtest/gtest.h>

namespace topay::plan {
namespace {

TEST(BaseLimitChoiceTest, BenchmarkLimitsAreThePapersSimulationOnes) {
  const BaseLimits limits = BenchmarkBaseLimits();
  EXPECT_EQ(limits.v_max_mps, 1.0);
  EXPECT_EQ(limits.a_max_mps2, 0.8);
  EXPECT_EQ(limits.omega_max_radps, 1.25);
  EXPECT_EQ(limits.beta_max_radps2, 1.0);
}

TEST(BaseLimitChoiceTest, RobotChoiceTakesTheModelsLimits) {
  RobotModel model;
  model.base_limits.omega_max_radps = 0.9;
  model.base_limits.v_max_mps = 0.7;
  EXPECT_EQ(ChooseBaseLimits(BaseLimitChoice::kRobot, model).omega_max_radps, 0.9);
  EXPECT_EQ(ChooseBaseLimits(BaseLimitChoice::kRobot, model).v_max_mps, 0.7);
  EXPECT_EQ(ChooseBaseLimits(BaseLimitChoice::kBenchmark, model).omega_max_radps, 1.25);
}

TEST(BaseLimitChoiceTest, NamesRoundTripAndOthersAreRefused) {
  for (BaseLimitChoice choice : {BaseLimitChoice::kBenchmark, BaseLimitChoice::kRobot}) {
    EXPECT_EQ(ParseBaseLimitChoice(BaseLimitChoiceName(choice)), choice);
  }
  EXPECT_EQ(BaseLimitChoiceName(BaseLimitChoice::kBenchmark), "benchmark");
  EXPECT_FALSE(ParseBaseLimitChoice("paper").has_value());
  EXPECT_FALSE(ParseBaseLimitChoice("").has_value());
  EXPECT_NE(BaseLimitChoiceDescription(BaseLimitChoice::kRobot).find("robot config"),
            std::string_view::npos);
}

}  // namespace
}  // namespace topay::plan
