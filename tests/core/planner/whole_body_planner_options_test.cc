#include "core/planner/whole_body_planner_options.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(RetryRoundFrontEndTest, RoundZeroIsTheConfiguredFrontEnd) {
  FrontEndOptions front_end;
  front_end.rrt.max_iterations = 5000;
  const FrontEndOptions round0 = RetryRoundFrontEnd(front_end, PlanRetryOptions{}, 0);
  EXPECT_EQ(round0.seed, front_end.seed);
  EXPECT_EQ(round0.ik.seed, front_end.ik.seed);
  EXPECT_EQ(round0.rrt.time_budget_s, front_end.rrt.time_budget_s);
  EXPECT_EQ(round0.rrt.max_iterations, front_end.rrt.max_iterations);
}

TEST(RetryRoundFrontEndTest, LaterRoundsGetOtherSeedsAndALargerArmBudget) {
  FrontEndOptions front_end;
  front_end.rrt.time_budget_s = 0.25;
  front_end.rrt.max_iterations = 5000;
  PlanRetryOptions retry;
  retry.arm_budget_growth = 2.0;
  const FrontEndOptions round1 = RetryRoundFrontEnd(front_end, retry, 1);
  const FrontEndOptions round2 = RetryRoundFrontEnd(front_end, retry, 2);
  EXPECT_NE(round1.seed, front_end.seed);
  EXPECT_NE(round2.seed, round1.seed);
  EXPECT_NE(round1.ik.seed, front_end.ik.seed);
  EXPECT_NE(round2.ik.seed, round1.ik.seed);
  EXPECT_DOUBLE_EQ(round1.rrt.time_budget_s, 0.5);
  EXPECT_DOUBLE_EQ(round2.rrt.time_budget_s, 1.0);
  EXPECT_EQ(round1.rrt.max_iterations, 10000);
  EXPECT_EQ(round2.rrt.max_iterations, 20000);
  // No cap stays no cap; an unbounded budget stays unbounded.
  front_end.rrt.max_iterations = 0;
  front_end.rrt.time_budget_s = std::numeric_limits<double>::infinity();
  const FrontEndOptions unbounded = RetryRoundFrontEnd(front_end, retry, 2);
  EXPECT_EQ(unbounded.rrt.max_iterations, 0);
  EXPECT_TRUE(std::isinf(unbounded.rrt.time_budget_s));
  // Growth 1: every round the same budget.
  retry.arm_budget_growth = 1.0;
  front_end.rrt.time_budget_s = 0.25;
  EXPECT_EQ(RetryRoundFrontEnd(front_end, retry, 2).rrt.time_budget_s, 0.25);
}

TEST(WholeBodyPlannerOptionsTest, WarmStartSlowdownOutsideZeroToOneIsRejectedByName) {
  WholeBodyPlannerOptions options;
  options.retry.warm_start_slowdown = 1.0;
  EXPECT_NO_THROW(CheckWholeBodyPlannerOptions(options));
  for (const double bad : {0.0, 1.5, -0.5, std::nan("")}) {
    options.retry.warm_start_slowdown = bad;
    try {
      CheckWholeBodyPlannerOptions(options);
      FAIL() << "no throw for " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("warm_start_slowdown"), std::string::npos)
          << e.what();
    }
  }
}

TEST(WholeBodyPlannerOptionsTest, ArmBudgetGrowthBelowOneIsRejectedByName) {
  WholeBodyPlannerOptions options;
  EXPECT_NO_THROW(CheckWholeBodyPlannerOptions(options));
  for (const double bad : {0.5, std::nan(""), std::numeric_limits<double>::infinity()}) {
    options.retry.arm_budget_growth = bad;
    try {
      CheckWholeBodyPlannerOptions(options);
      FAIL() << "no throw for " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("arm_budget_growth"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace topay
