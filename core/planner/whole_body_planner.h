#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/trajectory_back_end.h"
#include "core/planner/round_time.h"
#include "core/planner/whole_body_plan_result.h"
#include "core/planner/whole_body_planner_options.h"
#include "core/planning/front_end.h"
#include "core/planning/lead_in.h"
#include "core/robot/moving_state.h"
#include "core/robot/kinematics.h"
#include "core/validate/trajectory_validator.h"

namespace topay {

/// TopAY (paper Sec. III): from a start state and an end-effector target to a validated
/// whole-body trajectory.
///  1. Front end (core/planning/front_end.h): whole-body paths in several homotopy classes.
///  2. Back end: every path (up to max_candidates, shortest first) is optimized on its own
///     worker by the back end options.optimizer chooses (MakeTrajectoryBackEnd: arc
///     length-yaw or the flatness baseline, core/optimization/trajectory_back_end.h); an
///     optimizer success is then checked by the independent validator against the exact
///     scene (core/validate). A start or goal that the fields reject but the exact scene
///     accepts is planned for (the front end's exact zones, with the validator's exact
///     checker and margins); the back end relaxes its margins over the path's first and last
///     states that needed it (TrajectoryProblem::exact_prefix_states). After the first
///     validated success
///     the others get early_termination_window_s, then they are cancelled; the shortest
///     validated trajectory wins. options.sequential: one after another, no early stop.
///  3. Retry rounds (options.retry, ours): a round that ends without a validated trajectory
///     (no goal, no base or arm path, no optimizer success the validator accepts) is followed
///     by another with other seeds, and after a validator rejection with wider clearance
///     margins, while the time limit leaves room; a round that may be followed by another
///     uses at most a share of the time left.
/// A success is only ever a trajectory the validator accepted.
///
/// The kinematics and the fields must outlive this object; the scene is copied (by the
/// validator). Plan is const and may run from several threads.
class WholeBodyPlanner {
 public:
  /// Throws std::invalid_argument for options out of range (naming them).
  WholeBodyPlanner(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                   const SignedDistanceField3& arm_field, const Scene& scene,
                   WholeBodyPlannerOptions options = {});

  /// Never throws for bad input; failures come back with status and reason. `hint`: a
  /// whole-body goal state tried first by the front end. `stop`: the caller's cancellation.
  WholeBodyPlanResult Plan(const WholeBodyState& start, const Eigen::Isometry3d& X_WE_goal,
                           const std::optional<WholeBodyState>& hint = std::nullopt,
                           std::stop_token stop = {}) const;

  /// Plan with the time limit ending at min(now + options().time_limit_s, deadline): for a
  /// caller whose own work before the plan counts against the limit (PlanInScene).
  /// The limit bounds every stage: the front end and the optimizers poll the plan's stop
  /// every iteration, the validator before every sample (a validation cut short is a
  /// failure). A plan the limit ends has status kTimeLimit and says in which stage
  /// (stopped_stage, and the reason's "time limit ... reached during ...").
  WholeBodyPlanResult PlanBy(std::chrono::steady_clock::time_point deadline,
                             const WholeBodyState& start, const Eigen::Isometry3d& X_WE_goal,
                             const std::optional<WholeBodyState>& hint = std::nullopt,
                             std::stop_token stop = {}) const;

  /// Plan from a moving start (issue 18): the trajectory starts C2-continuously with
  /// `start` (x, y, yaw, q and v, omega, a, beta, qd, qdd at t = 0; arc length-yaw back end
  /// only, the flatness baseline refuses it). When |v| >= options().lead_in.min_speed_mps
  /// the whole-body path begins with the braking lead-in along the current heading
  /// (MakeLeadIn) and the front end plans from its end; if the lead-in collides the plan
  /// fails at once (kFrontEndFailed, front end kStartInvalid, reason "moving start: ...")
  /// and the caller keeps its stopping trajectory. The validator also checks the rates at
  /// t = 0 (TrajectoryValidator::Validate with a MovingState). Rest rates: exactly Plan.
  WholeBodyPlanResult Plan(const MovingState& start, const Eigen::Isometry3d& X_WE_goal,
                           const std::optional<WholeBodyState>& hint = std::nullopt,
                           std::stop_token stop = {}) const;
  WholeBodyPlanResult PlanBy(std::chrono::steady_clock::time_point deadline,
                             const MovingState& start, const Eigen::Isometry3d& X_WE_goal,
                             const std::optional<WholeBodyState>& hint = std::nullopt,
                             std::stop_token stop = {}) const;

  const WholeBodyPlannerOptions& options() const { return options_; }
  const BaseLimits& base_limits() const { return base_limits_; }
  /// The first round's front end (PlanRetryOptions: later rounds differ only in their seeds).
  const FrontEnd& front_end() const { return *rounds_.front(); }
  const TrajectoryValidator& validator() const { return validator_; }

 private:
  // A round's time: `stop` ends it (the plan's stop forwards to it), at round_end at the
  // latest (RoundShareEnd; plan_end for the last round) unless the round keeps the plan's
  // time once its front end is done (RoundKeepsThePlanTime).
  struct RoundTime {
    std::stop_source* stop = nullptr;
    RoundClock::time_point round_end;
    RoundClock::time_point plan_end;
  };
  // One round: the front end of round `round`, then the back end of margin level `level`;
  // `time.stop` ends the round, `plan_stop` (the plan's) also a validation under way.
  // The front end plans from the lead-in's end; its paths get the lead-in prepended
  // (lead_in_exact: some lead-in state passed only the exact check).
  WholeBodyPlanResult PlanRound(int round, int level, const MovingState& start,
                                const LeadIn& lead_in, bool lead_in_exact,
                                const Eigen::Isometry3d& X_WE_goal,
                                const std::optional<WholeBodyState>& hint, const RoundTime& time,
                                std::stop_token plan_stop) const;
  void OptimizeCandidates(const TrajectoryBackEnd& back_end, const MovingState& start,
                          const Eigen::Isometry3d& X_WE_goal, std::stop_token round_stop,
                          std::stop_token plan_stop, WholeBodyPlanResult* result) const;
  void RunCandidate(const TrajectoryBackEnd& back_end, const TrajectoryProblem& problem,
                    const FrontEndPath& path, std::stop_token stop, std::stop_token plan_stop,
                    CandidateReport* report) const;
  // The final result's status and reason from its last round.
  void Conclude(bool time_limit_hit, std::stop_token stop, const WholeBodyState& start,
                const Eigen::Isometry3d& X_WE_goal, WholeBodyPlanResult* result) const;

  WholeBodyPlannerOptions options_;
  BaseLimits base_limits_;
  TrajectoryValidator validator_;  // before the front ends, which use its exact checker
  /// Round r's front end (seeds derived from r; PlanRetryOptions).
  std::vector<std::unique_ptr<const FrontEnd>> rounds_;
  /// Back end at margin level k: clearance margins + k x retry.clearance_step_m.
  std::vector<std::unique_ptr<const TrajectoryBackEnd>> back_ends_;
  /// The same with the warm start slowed by retry.warm_start_slowdown: later rounds from a
  /// start at rest (empty if the slowdown is 1 or there is one round).
  std::vector<std::unique_ptr<const TrajectoryBackEnd>> slow_back_ends_;
};

/// "time limit 3.000 s reached during <stage>: ", the prefix of a kTimeLimit plan's reason.
std::string TimeLimitPrefix(double time_limit_s, PlanStage stage);

}  // namespace topay
