#include "tools/topay_bench/failure_category.h"

#include <numeric>
#include <utility>

namespace topay::bench {
namespace {

struct Names {
  FailureCategory category;
  std::string_view key;
  std::string_view words;
};

constexpr std::array<Names, 10> kNames{{
    {FailureCategory::kNone, "", "none"},
    {FailureCategory::kStartRefused, "start_refused", "start refused"},
    {FailureCategory::kNoGoal, "no_goal", "no goal"},
    {FailureCategory::kNoBasePath, "no_base_path", "no base path"},
    {FailureCategory::kNoArmPath, "no_arm_path", "no arm path"},
    {FailureCategory::kOptimizerFailed, "optimizer_failed", "optimizer failed"},
    {FailureCategory::kValidatorRejected, "validator_rejected", "validator rejected"},
    {FailureCategory::kTimeLimit, "time_limit", "time limit"},
    {FailureCategory::kGenerationFailed, "generation_failed", "generation failed"},
    {FailureCategory::kOther, "other", "other"},
}};

const Names& NamesOf(FailureCategory category) {
  for (const Names& names : kNames) {
    if (names.category == category) return names;
  }
  return kNames.back();
}

std::size_t IndexOf(FailureCategory category) {
  for (std::size_t i = 0; i < kFailureCategories.size(); ++i) {
    if (kFailureCategories[i] == category) return i;
  }
  return kFailureCategories.size() - 1;  // kOther
}

FailureCategory FrontEndCategory(FrontEndStatus status) {
  switch (status) {
    case FrontEndStatus::kStartInvalid:
      return FailureCategory::kStartRefused;
    case FrontEndStatus::kNoGoal:
      return FailureCategory::kNoGoal;
    case FrontEndStatus::kNoBasePath:
      return FailureCategory::kNoBasePath;
    case FrontEndStatus::kNoArmPath:
      return FailureCategory::kNoArmPath;
    default:
      return FailureCategory::kOther;
  }
}

}  // namespace

std::string_view FailureCategoryName(FailureCategory category) { return NamesOf(category).key; }

std::string_view FailureCategoryWords(FailureCategory category) {
  return NamesOf(category).words;
}

std::optional<FailureCategory> ParseFailureCategory(std::string_view name) {
  for (const Names& names : kNames) {
    if (names.key == name) return names.category;
  }
  return std::nullopt;
}

FailureCategory ClassifyPlanFailure(const WholeBodyPlanResult& plan) {
  switch (plan.status) {
    case PlanStatus::kSuccess:
      return FailureCategory::kNone;
    case PlanStatus::kFrontEndFailed:
      return FrontEndCategory(plan.front_end.status);
    case PlanStatus::kOptimizationFailed:
      for (const CandidateReport& candidate : plan.candidates) {
        if (candidate.validation.has_value() && !candidate.validation->ok) {
          return FailureCategory::kValidatorRejected;
        }
      }
      return FailureCategory::kOptimizerFailed;
    case PlanStatus::kTimeLimit:
      return FailureCategory::kTimeLimit;
    default:
      return FailureCategory::kOther;
  }
}

void FailureTally::Add(FailureCategory category) {
  if (category != FailureCategory::kNone) ++counts[IndexOf(category)];
}

int FailureTally::Count(FailureCategory category) const {
  return category == FailureCategory::kNone ? 0 : counts[IndexOf(category)];
}

int FailureTally::Total() const { return std::accumulate(counts.begin(), counts.end(), 0); }

std::string FailureTally::Text() const {
  std::string text;
  for (std::size_t i = 0; i < kFailureCategories.size(); ++i) {
    if (counts[i] == 0) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(counts[i]) + " " +
            std::string(FailureCategoryWords(kFailureCategories[i]));
  }
  return text.empty() ? "none" : text;
}

}  // namespace topay::bench
