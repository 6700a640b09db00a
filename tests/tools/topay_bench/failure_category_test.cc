#include "tools/topay_bench/failure_category.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace topay::bench {
namespace {

WholeBodyPlanResult FrontEndFailure(FrontEndStatus status) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kFrontEndFailed;
  plan.front_end.status = status;
  return plan;
}

TEST(FailureCategoryTest, NamesAreUniqueAndParseBack) {
  std::set<std::string> names;
  for (const FailureCategory category : kFailureCategories) {
    const std::string name(FailureCategoryName(category));
    EXPECT_FALSE(name.empty());
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_EQ(ParseFailureCategory(name), category);
    EXPECT_NE(FailureCategoryWords(category), "none");
  }
  EXPECT_EQ(ParseFailureCategory(""), FailureCategory::kNone);
  EXPECT_FALSE(ParseFailureCategory("refused").has_value());
  EXPECT_EQ(FailureCategoryWords(FailureCategory::kStartRefused), "start refused");
}

TEST(FailureCategoryTest, FrontEndStatusesGiveTheirCategories) {
  EXPECT_EQ(ClassifyPlanFailure(FrontEndFailure(FrontEndStatus::kStartInvalid)),
            FailureCategory::kStartRefused);
  EXPECT_EQ(ClassifyPlanFailure(FrontEndFailure(FrontEndStatus::kNoGoal)),
            FailureCategory::kNoGoal);
  EXPECT_EQ(ClassifyPlanFailure(FrontEndFailure(FrontEndStatus::kNoBasePath)),
            FailureCategory::kNoBasePath);
  EXPECT_EQ(ClassifyPlanFailure(FrontEndFailure(FrontEndStatus::kNoArmPath)),
            FailureCategory::kNoArmPath);
  EXPECT_EQ(ClassifyPlanFailure(FrontEndFailure(FrontEndStatus::kCancelled)),
            FailureCategory::kOther);
}

TEST(FailureCategoryTest, PlanStatusesGiveTheirCategories) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kSuccess;
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kNone);
  plan.status = PlanStatus::kTimeLimit;
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kTimeLimit);
  plan.status = PlanStatus::kInvalidInput;
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kOther);
  plan.status = PlanStatus::kCancelled;
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kOther);
  // Optimization failed: no optimizer success, or one the validator rejected.
  plan.status = PlanStatus::kOptimizationFailed;
  plan.candidates.resize(2);
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kOptimizerFailed);
  ValidationReport rejected;
  rejected.ok = false;
  plan.candidates[1].validation = rejected;
  EXPECT_EQ(ClassifyPlanFailure(plan), FailureCategory::kValidatorRejected);
}

TEST(FailureCategoryTest, TallyCountsAndSaysSoInWords) {
  FailureTally tally;
  EXPECT_EQ(tally.Total(), 0);
  EXPECT_EQ(tally.Text(), "none");
  for (const FailureCategory c :
       {FailureCategory::kNoGoal, FailureCategory::kStartRefused, FailureCategory::kStartRefused,
        FailureCategory::kNone, FailureCategory::kStartRefused, FailureCategory::kTimeLimit}) {
    tally.Add(c);
  }
  EXPECT_EQ(tally.Count(FailureCategory::kStartRefused), 3);
  EXPECT_EQ(tally.Count(FailureCategory::kNoGoal), 1);
  EXPECT_EQ(tally.Count(FailureCategory::kNone), 0);  // successes are not counted
  EXPECT_EQ(tally.Total(), 5);
  EXPECT_EQ(tally.Text(), "3 start refused, 1 no goal, 1 time limit");
}

}  // namespace
}  // namespace topay::bench
