#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/stopwatch.h"
#include "core/robot/kinematics.h"
#include "core/robot/self_collision.h"
#include "core/robot/whole_body_state.h"

namespace topay {

class Rng;

/// Environment clearance of a whole-body state in metres: > 0 free, <= 0 in collision. The
/// caller wires it to a scene or distance-field check. A null function means free space.
using StateClearanceFn = std::function<double(const WholeBodyState&)>;

/// Options of WholeBodyIk (Ceres style: every field has a documented default).
struct WholeBodyIkOptions {
  // ---- Search breadth -------------------------------------------------------------------
  /// Base poses sampled around the target (the hint's base pose comes on top). 0: only the
  /// hint is tried.
  int max_base_candidates = 16;
  /// Arm IK attempts per base pose (the first from the hint's joints when there is one, the
  /// rest from random joint configurations). Stops at the first valid solution per base.
  int restarts_per_base = 4;
  /// The search stops once this many distinct solutions are found.
  int max_solutions = 6;

  // ---- Damped least squares -------------------------------------------------------------
  /// Iterations of one DLS run (arm-only stage; the whole-body polish gets as many again).
  int max_dls_iterations = 60;
  /// Damping of the DLS step (Levenberg-Marquardt after Sugihara 2011, see whole_body_ik.cc):
  /// lambda^2 = error_damping_gain * |e|^2 + damping_bias (e: 6-D pose error, m and rad), so
  /// steps far from the target are short and steps near it are Gauss-Newton steps.
  double error_damping_gain = 0.5;
  double damping_bias = 1e-3;
  /// Largest change of any joint in one iteration.
  double max_joint_step_rad = 0.25;
  /// Largest base translation / rotation in one whole-body polish iteration.
  double max_base_step_m = 0.05;
  double max_base_step_rad = 0.1;
  /// After an arm-only run misses the tolerance, continue with the base free (x, y, yaw move
  /// too) when the remaining error is below polish_start_error (|e| of the 6-D error, m/rad).
  bool whole_body_polish = true;
  double polish_start_error = 0.15;

  // ---- Acceptance (1 mm / 0.01 rad) -------------------------------------------------
  double position_tolerance_m = 1e-3;
  double orientation_tolerance_rad = 1e-2;
  /// DLS iterates until the error is below this fraction of the tolerances (a margin, so the
  /// reported solutions are well inside them).
  double convergence_fraction = 0.1;
  /// Required environment clearance: a solution needs clearance(state) > min_clearance_m.
  double min_clearance_m = 0.0;
  /// Required self-collision distance: the smallest of SelfCollision::MinDistance and the
  /// spheres' ChassisMargins must be > this. Note: on the TopAY model link 1's lowest sphere
  /// sits a constant 5 mm above the chassis top, so a value >= 0.005 rejects every state.
  double min_self_distance_m = 0.0;

  // ---- Base placement -------------------------------------------------------------------
  /// Band of horizontal distances from the shoulder to the target's wrist centre in which
  /// base poses are sampled. Left at 0, derived from the model (see WholeBodyIk): min =
  /// 0.2 * reach, max = stretch_fraction * reach, where reach is the largest shoulder-to-wrist
  /// distance; at a height difference dz the max shrinks to sqrt(max^2 - dz^2).
  double reach_min_m = 0.0;
  double reach_max_m = 0.0;
  double stretch_fraction = 0.9;
  /// The base faces the target: its yaw is the bearing from the shoulder to the target's
  /// wrist centre plus a uniform offset in [-yaw_spread_rad, yaw_spread_rad].
  double yaw_spread_rad = 1.2;

  // ---- Ranking (cheapest first) ---------------------------------------------------------
  /// cost = |p_B - p_B,ref| + yaw_travel_weight_m_per_rad * |yaw - yaw_ref| (0 without a
  ///        reference) + clearance_weight * max(0, clearance_saturation_m - clearance).
  double yaw_travel_weight_m_per_rad = 0.3;
  double clearance_weight = 1.0;
  double clearance_saturation_m = 0.3;
  /// Two solutions are duplicates when base x, y differ by less than duplicate_distance_m,
  /// yaw and every joint by less than duplicate_angle_rad; the cheaper one is kept.
  double duplicate_distance_m = 0.05;
  double duplicate_angle_rad = 0.05;

  // ---- Budget ---------------------------------------------------------------------------
  /// Seed of the Rng drawing base poses and restarts: same seed, same result (as long as the
  /// wall-clock budget does not cut the search short).
  std::uint64_t seed = 1;
  /// Wall-clock budget of one Solve; +infinity disables it (deterministic results).
  double time_budget_s = 0.2;
  /// Total DLS iterations of one Solve over all candidates and restarts.
  int max_total_iterations = 20000;
};

/// Throws std::invalid_argument naming the first option out of range (the WholeBodyIk
/// constructor calls it; the planner YAML loader too).
void CheckWholeBodyIkOptions(const WholeBodyIkOptions& options);

struct WholeBodyIkQuery {
  /// Tried first (as is, then as the seed of an arm-only and a whole-body DLS run).
  std::optional<WholeBodyState> hint;
  /// The robot's current base pose [x_m, y_m, yaw_rad]: ranking by base travel from it, and
  /// the first sampled base pose lies on the line from the target towards it.
  std::optional<Eigen::Vector3d> reference_base;
  /// The robot's current whole-body state: tried after the hint with the base where it stands
  /// (one arm-only DLS run from its joints; no whole-body polish), so that a robot within reach
  /// of the target can finish with the arm alone (a stop next to its goal, finding 29). Such a
  /// solution keeps the base pose exactly (IkSolution::base_stays).
  std::optional<WholeBodyState> standing;
  /// The robot's current joints: every solution's revolute joints are turned by whole turns to
  /// lie nearest them (NearestJointTurns: the same pose, the least joint travel; finding 29's
  /// third case), so that duplicates on other turns are removed too.
  std::optional<Eigen::VectorXd> reference_q_rad;
};

struct IkSolution {
  WholeBodyState state;
  double position_error_m = 0.0;      ///< |p_WE(state) - p_WE,target|.
  double orientation_error_rad = 0.0; ///< Angle of R_WE,target * R_WE(state)^T.
  double clearance_m = std::numeric_limits<double>::infinity();  ///< Environment.
  /// Smallest self-collision pair distance and sphere margin above the chassis top (m).
  double self_distance_m = std::numeric_limits<double>::infinity();
  double cost = 0.0;                  ///< Ranking cost (see WholeBodyIkOptions).
  bool from_hint = false;             ///< Found from the query's hint.
  bool base_stays = false;            ///< Found from the query's standing state, its base.
};

struct WholeBodyIkResult {
  /// Valid solutions, cheapest first, duplicates removed. Empty on failure.
  std::vector<IkSolution> solutions;
  /// Empty when solutions were found; otherwise why not (bad input, out of reach, or the
  /// search's rejection counts).
  std::string failure_reason;

  // ---- Statistics -----------------------------------------------------------------------
  int base_candidates_tried = 0;
  int dls_runs = 0;
  int total_iterations = 0;
  int rejected_not_converged = 0;
  int rejected_self_collision = 0;
  int rejected_clearance = 0;
  int duplicates_removed = 0;
  bool hint_used = false;        ///< The hint was valid and at least one solution came from it.
  bool budget_exhausted = false; ///< Stopped by the time or iteration budget.
  double solve_time_s = 0.0;
  /// Derived reach (see WholeBodyIkOptions::reach_min_m) used for this solve.
  double reach_min_m = 0.0;
  double reach_max_m = 0.0;

  bool success() const { return !solutions.empty(); }
};

/// Whole-body inverse kinematics of the mobile manipulator for an end-effector SE(3) target.
///
/// Method:
///  1. Validate the target (finite, orthonormal rotation) and the hint; reject targets whose
///     wrist centre is out of reach of the shoulder at any base pose (vertical check).
///  2. The hint, when given: accepted as is if valid; otherwise it seeds an arm-only DLS run at
///     its base pose and a whole-body polish.
///  3. Base candidates: the shoulder S is placed on a circle of horizontal radius rho (in the
///     reach band) around the target's wrist centre W, at bearings spread evenly around W
///     (starting from the reference base's side, then alternating left and right) with random
///     jitter; the base yaw faces W (plus a random offset); the base position follows from S.
///  4. At each candidate: arm-only damped least squares on the 6-D pose error (rotation vector
///     of R_target R^T, position difference), joints clamped to their limits with a
///     limit-aware step (joints pushing into a limit drop out of the step), random restarts;
///     optionally a whole-body polish (base x, y, yaw free) when the arm alone got close.
///  5. Accept: within the tolerances, within joint limits, no self-collision and the arm
///     above the chassis (SelfCollision), environment clearance > min; rank; de-duplicate.
///
/// The wrist centre W is derived from the model: the intersection point of the last two joint
/// axes (fixed in the end-effector frame; for an SRS arm the spherical wrist's centre), or the
/// end-effector origin if they do not intersect. The shoulder S is the last joint origin (from
/// the root) that lies on every preceding joint axis, so it is fixed in the base frame; the
/// reach is the sum of the link offsets from S to W (a triangle-inequality bound).
///
/// The Kinematics (and its model) must outlive this object.
class WholeBodyIk {
 public:
  /// Throws std::invalid_argument for an option out of its range (naming it) or a model
  /// without an end effector or joint limits.
  WholeBodyIk(const Kinematics& kinematics, WholeBodyIkOptions options = {});

  /// Thread-safe (const, scratch is per call) when `clearance` is.
  WholeBodyIkResult Solve(const Eigen::Isometry3d& X_WE_target, const StateClearanceFn& clearance,
                          const WholeBodyIkQuery& query = {}) const;

  const WholeBodyIkOptions& options() const { return options_; }
  /// Shoulder S in the base frame B (fixed), wrist centre W in the end-effector frame E (fixed),
  /// and the largest |p_SW| (m).
  const Eigen::Vector3d& p_BS() const { return p_BS_; }
  const Eigen::Vector3d& p_EW() const { return p_EW_; }
  double shoulder_to_wrist_reach_m() const { return reach_m_; }

 private:
  struct Workspace;
  struct DlsOutcome;
  enum class IkSeed { kSearch, kHint, kStanding };  ///< Where an attempt started.

  void DeriveReachGeometry();
  double SelfDistance(Workspace* ws) const;
  std::string CheckQuery(const WholeBodyIkQuery& query) const;
  std::vector<Eigen::Vector3d> SampleBasePoses(const Eigen::Vector3d& p_WW, double rho_lo_m,
                                               double rho_hi_m, const WholeBodyIkQuery& query,
                                               Rng* rng) const;
  /// FK of ws->state into ws->cache and the pose error into ws->error.
  DlsOutcome Evaluate(const Eigen::Isometry3d& X_WE_target, Workspace* ws) const;
  void ComputeStep(bool move_base, Workspace* ws) const;
  void ApplyStep(Workspace* ws) const;
  DlsOutcome RunDls(const Eigen::Isometry3d& X_WE_target, bool move_base, Workspace* ws) const;
  /// Arm-only DLS from ws->state, then the whole-body polish if enabled and close.
  DlsOutcome Attempt(const Eigen::Isometry3d& X_WE_target, WholeBodyIkResult* result,
                     Workspace* ws) const;
  /// Checks a DLS outcome (ws->cache/state current) and adds it to result->solutions.
  bool Accept(const DlsOutcome& outcome, const StateClearanceFn& clearance,
              const WholeBodyIkQuery& query, IkSeed seed, Workspace* ws,
              WholeBodyIkResult* result) const;
  double RankCost(const IkSolution& solution, const WholeBodyIkQuery& query) const;

  // The steps of Solve.
  /// The band of horizontal shoulder-to-wrist-centre distances for the wrist centre p_WW:
  /// result->reach_min_m / reach_max_m and the sampling ring [*rho_lo, *rho_hi]; the failure
  /// if the target is out of reach, else "".
  std::string ReachBand(const Eigen::Vector3d& p_WW, WholeBodyIkResult* result, double* rho_lo,
                        double* rho_hi) const;
  /// The hint as is (clamped to the joint limits), else as the seed of one attempt.
  void TryHint(const Eigen::Isometry3d& X_WE_target, const StateClearanceFn& clearance,
               const WholeBodyIkQuery& query, Workspace* ws, WholeBodyIkResult* result) const;
  /// The standing state's joints as the seed of one arm-only run, its base fixed.
  void TryStanding(const Eigen::Isometry3d& X_WE_target, const StateClearanceFn& clearance,
                   const WholeBodyIkQuery& query, Workspace* ws, WholeBodyIkResult* result) const;
  /// Base candidates on the ring around p_WW, restarts_per_base attempts at each, until
  /// max_solutions or the budget.
  void SearchBases(const Eigen::Isometry3d& X_WE_target, const Eigen::Vector3d& p_WW,
                   double rho_lo, double rho_hi, const StateClearanceFn& clearance,
                   const WholeBodyIkQuery& query, const Stopwatch& watch, Workspace* ws,
                   WholeBodyIkResult* result) const;
  /// True (and result->budget_exhausted set) once the iterations or the time budget are used.
  bool OutOfBudget(const Stopwatch& watch, const Workspace& ws, WholeBodyIkResult* result) const;
  /// The failure reason when no solution was accepted: the counts of what was rejected.
  std::string DescribeNoSolution(const WholeBodyIkResult& result) const;
  bool IsDuplicate(const IkSolution& a, const IkSolution& b) const;

  const Kinematics& kinematics_;
  WholeBodyIkOptions options_;
  SelfCollision self_collision_;
  Eigen::Vector3d p_BS_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_EW_ = Eigen::Vector3d::Zero();
  double reach_m_ = 0.0;
};

}  // namespace topay
