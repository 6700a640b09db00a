#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/optimization/back_end_summary.h"
#include "core/planning/front_end_result.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"
#include "core/validate/validation_report.h"

namespace topay {

enum class PlanStatus {
  kSuccess,             ///< A trajectory passed the independent validator.
  kInvalidInput,        ///< NaN, wrong joint count, bad pose (front end's check).
  kFrontEndFailed,      ///< No whole-body path (start invalid, no goal, no base/arm path).
  kOptimizationFailed,  ///< Paths, but no optimized trajectory passed the validator.
  kTimeLimit,           ///< The time limit ended the plan before any validated trajectory.
  kCancelled,           ///< The caller's stop ended the plan first.
};
std::string_view ToString(PlanStatus status);

/// The stages of one plan, in order (the first two only in PlanInScene, which builds the
/// fields itself).
enum class PlanStage {
  kNone,          ///< Not stopped.
  kStartCheck,    ///< Exact start and target check against the scene's boxes.
  kMapBuilding,   ///< The distance fields (BuildSceneDistanceFields).
  kFrontEnd,      ///< Goal candidates, base paths, arm RRT* (core/planning/front_end.h).
  kOptimization,  ///< The candidates' trajectory optimizations.
  kValidation,    ///< The independent validator on an optimizer success.
};
std::string_view ToString(PlanStage stage);

/// One front-end path through the back end.
struct CandidateReport {
  int path_index = -1;   ///< Into WholeBodyPlanResult::front_end.paths.
  bool started = false;  ///< False: cancelled (early termination or time limit) while queued.
  BackEndSummary optimization;
  /// The validator's verdict, when the optimizer reported success.
  std::optional<ValidationReport> validation;
  double wall_ms = 0.0;  ///< Optimization + validation.

  bool validated() const { return validation.has_value() && validation->ok; }
};

/// Wall-clock timings (ms) of one plan, as topay-plan prints them.
struct PlanTimings {
  double search_ms = 0.0;        ///< Goal candidates (IK) + topological base paths.
  double sampling_ms = 0.0;      ///< DiscreteSE2 + the parallel arm RRT* stage.
  double front_end_ms = 0.0;     ///< The whole front end.
  double optimization_ms = 0.0;  ///< From the end of the front end to the first validated
                                 ///< success (or to the end of the stage if none).
  double wait_ms = 0.0;          ///< From the first validated success to the stage's end.
  double total_ms = 0.0;
  /// PlanInScene only (0 otherwise): the exact start and target check and the field build,
  /// both inside total_ms and the time limit.
  double start_check_ms = 0.0;
  double map_ms = 0.0;
};

/// What WholeBodyPlanner::Plan returns.
struct WholeBodyPlanResult {
  PlanStatus status = PlanStatus::kInvalidInput;
  std::string failure_reason;  ///< Empty on success.
  FrontEndResult front_end;
  std::vector<CandidateReport> candidates;  ///< In front-end path order.
  int chosen = -1;  ///< Into candidates: the shortest validated trajectory (-1: none).
  /// The chosen trajectory, rebuilt (arc length-yaw parameterisation only).
  std::optional<ArcYawTrajectory> trajectory;
  /// The chosen trajectory as samples, for either parameterisation (the flatness baseline
  /// too): what the validator checked.
  std::optional<SampledTrajectory> sampled;
  PlanTimings timings;
  /// For kTimeLimit and kCancelled: the stage the stop ended (the time limit bounds every
  /// stage: each polls the plan's stop and returns within a short step of it).
  PlanStage stopped_stage = PlanStage::kNone;
  /// Planning rounds run (PlanRetryOptions): 1 unless a round without a validated trajectory
  /// was followed by another. front_end and candidates are the last round's; timings add
  /// every round's up.
  int rounds = 1;
  /// The last round's back-end margin level (earlier rounds with a validator rejection).
  int margin_level = 0;
  /// The earlier rounds' failures, "round 1: no_base_path; round 2: 1 x ..." (empty if one).
  std::string earlier_rounds;

  bool success() const { return status == PlanStatus::kSuccess; }
  const CandidateReport* chosen_candidate() const {
    return chosen >= 0 ? &candidates[chosen] : nullptr;
  }
  /// Readable multi-line summary: status, reason, stage times, candidates, and for the chosen
  /// trajectory its duration, minimum clearance and worst constraint ratio.
  std::string Report() const;
};

}  // namespace topay
