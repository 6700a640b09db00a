#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/planner/whole_body_plan_result.h"

namespace topay::bench {

/// Why a benchmark task failed, one category per failed record, from the plan's own statuses
/// (PlanStatus and, for front-end failures, FrontEndStatus; PlanInScene's exact start and
/// target check reports through the same statuses).
enum class FailureCategory {
  kNone,               ///< "": a success.
  kStartRefused,       ///< "start_refused": FrontEndStatus::kStartInvalid.
  kNoGoal,             ///< "no_goal": FrontEndStatus::kNoGoal (no goal state for the target).
  kNoBasePath,         ///< "no_base_path": FrontEndStatus::kNoBasePath.
  kNoArmPath,          ///< "no_arm_path": FrontEndStatus::kNoArmPath.
  kOptimizerFailed,    ///< "optimizer_failed": kOptimizationFailed, no optimizer success.
  /// "validator_rejected": kOptimizationFailed, and at least one optimizer success was
  /// rejected by the independent validator.
  kValidatorRejected,
  /// "time_limit": PlanStatus::kTimeLimit, or a validated plan slower than the limit.
  kTimeLimit,
  kGenerationFailed,   ///< "generation_failed": the task could not be generated.
  kOther,              ///< "other": invalid input, cancelled, any other front-end status.
};

/// Every failure category (kNone excluded), in enum order: the order of the tallies.
inline constexpr std::array<FailureCategory, 9> kFailureCategories = {
    FailureCategory::kStartRefused,     FailureCategory::kNoGoal,
    FailureCategory::kNoBasePath,       FailureCategory::kNoArmPath,
    FailureCategory::kOptimizerFailed,  FailureCategory::kValidatorRejected,
    FailureCategory::kTimeLimit,        FailureCategory::kGenerationFailed,
    FailureCategory::kOther};

/// The key names above ("" for kNone).
std::string_view FailureCategoryName(FailureCategory category);
/// Words for the report: "start refused", "no goal", "no base path", "no arm path",
/// "optimizer failed", "validator rejected", "time limit", "generation failed", "other".
std::string_view FailureCategoryWords(FailureCategory category);
/// Inverse of FailureCategoryName ("" gives kNone); nullopt for anything else.
std::optional<FailureCategory> ParseFailureCategory(std::string_view name);

/// The category of a plan as WholeBodyPlanner returned it (kNone for a success; the bench's
/// late successes are FillOutcome's business, bench_record.h).
FailureCategory ClassifyPlanFailure(const WholeBodyPlanResult& plan);

/// Failed records per category, indexed like kFailureCategories.
struct FailureTally {
  std::array<int, kFailureCategories.size()> counts{};

  void Add(FailureCategory category);
  int Count(FailureCategory category) const;
  int Total() const;
  /// "3 start refused, 1 no goal" (non-zero categories in order), "none" without failures.
  std::string Text() const;
};

}  // namespace topay::bench
