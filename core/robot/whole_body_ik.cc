#include "core/robot/whole_body_ik.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "core/common/angles.h"
#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/robot/joint_turns.h"

namespace topay {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

constexpr double kOnAxisTolerance_m = 1e-9;
constexpr double kAxesIntersectTolerance_m = 1e-6;
constexpr double kOrthonormalTolerance = 1e-6;

/// Distance of point p from the line through o along unit direction a.
double DistanceToLine(const Eigen::Vector3d& p, const Eigen::Vector3d& o,
                      const Eigen::Vector3d& a) {
  return (p - o).cross(a).norm();
}

/// The 6-D pose error e = [log(R_t R^T); p_t - p] in W, matching the row order of
/// Kinematics::EndEffectorJacobian (angular first). log is the rotation vector (angle * axis).
void PoseError(const Eigen::Isometry3d& X_WE_target, const Eigen::Isometry3d& X_WE,
               Vector6d* e) {
  const Eigen::AngleAxisd R_err(X_WE_target.linear() * X_WE.linear().transpose());
  e->head<3>() = R_err.angle() * R_err.axis();
  e->tail<3>() = X_WE_target.translation() - X_WE.translation();
}

bool IsValidPose(const Eigen::Isometry3d& X, std::string* why) {
  if (!X.matrix().allFinite()) {
    *why = "target pose contains NaN or infinity";
    return false;
  }
  const Eigen::RowVector4d last_row = X.matrix().row(3);
  if ((last_row - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > kOrthonormalTolerance) {
    *why = "target pose's last row is not [0 0 0 1]";
    return false;
  }
  const Eigen::Matrix3d R = X.linear();
  const double orthonormality = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (orthonormality > kOrthonormalTolerance || R.determinant() < 0.0) {
    std::ostringstream out;
    out << "target rotation is not a proper rotation (|R^T R - I| = " << orthonormality
        << ", det = " << R.determinant() << ")";
    *why = out.str();
    return false;
  }
  return true;
}



/// The intersection of the lines o1 + s a1 and o2 + t a2 (unit axes): the midpoint of their
/// closest points (e.g. Eberly, "Distance between lines", the standard 2x2 normal
/// equations), if the lines are not parallel and pass within kAxesIntersectTolerance_m.
bool AxesIntersection(const Eigen::Vector3d& o1, const Eigen::Vector3d& a1,
                      const Eigen::Vector3d& o2, const Eigen::Vector3d& a2,
                      Eigen::Vector3d* point) {
  const double b = a1.dot(a2);
  const double denom = 1.0 - b * b;
  if (!(denom > 1e-9)) return false;
  const Eigen::Vector3d r = o1 - o2;
  const double d = a1.dot(r), e = a2.dot(r);
  const double s = (b * e - d) / denom;  // along line 1
  const double t = (e - b * d) / denom;  // along line 2
  const Eigen::Vector3d c1 = o1 + s * a1, c2 = o2 + t * a2;
  if (!((c1 - c2).norm() < kAxesIntersectTolerance_m)) return false;
  *point = 0.5 * (c1 + c2);
  return true;
}

}  // namespace

void CheckWholeBodyIkOptions(const WholeBodyIkOptions& o) {
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) {
      throw std::invalid_argument(std::string("WholeBodyIkOptions::") + field + " must be " +
                                  rule);
    }
  };
  require(o.max_base_candidates >= 0, "max_base_candidates", ">= 0");
  require(o.restarts_per_base >= 1, "restarts_per_base", ">= 1");
  require(o.max_solutions >= 1, "max_solutions", ">= 1");
  require(o.max_dls_iterations >= 1, "max_dls_iterations", ">= 1");
  require(o.error_damping_gain >= 0.0, "error_damping_gain", ">= 0");
  require(o.damping_bias > 0.0, "damping_bias", "> 0 (keeps J J^T + lambda^2 I invertible)");
  require(o.max_joint_step_rad > 0.0, "max_joint_step_rad", "> 0");
  require(o.max_base_step_m > 0.0, "max_base_step_m", "> 0");
  require(o.max_base_step_rad > 0.0, "max_base_step_rad", "> 0");
  require(o.polish_start_error >= 0.0, "polish_start_error", ">= 0");
  require(o.position_tolerance_m > 0.0, "position_tolerance_m", "> 0");
  require(o.orientation_tolerance_rad > 0.0, "orientation_tolerance_rad", "> 0");
  require(o.convergence_fraction >= 0.0 && o.convergence_fraction <= 1.0,
          "convergence_fraction", "in [0, 1]");
  require(!std::isnan(o.min_clearance_m), "min_clearance_m", "a number");
  require(!std::isnan(o.min_self_distance_m), "min_self_distance_m", "a number");
  require(o.reach_min_m >= 0.0 && o.reach_max_m >= 0.0, "reach_min_m/reach_max_m", ">= 0");
  require(o.reach_max_m == 0.0 || o.reach_min_m <= o.reach_max_m, "reach_min_m",
          "<= reach_max_m");
  require(o.stretch_fraction > 0.0 && o.stretch_fraction <= 1.0, "stretch_fraction",
          "in (0, 1]");
  require(o.yaw_spread_rad >= 0.0, "yaw_spread_rad", ">= 0");
  require(o.yaw_travel_weight_m_per_rad >= 0.0 && o.clearance_weight >= 0.0 &&
              o.clearance_saturation_m >= 0.0,
          "yaw_travel_weight_m_per_rad/clearance_weight/clearance_saturation_m", ">= 0");
  require(o.duplicate_distance_m >= 0.0 && o.duplicate_angle_rad >= 0.0,
          "duplicate_distance_m/duplicate_angle_rad", ">= 0");
  require(o.time_budget_s > 0.0, "time_budget_s", "> 0 (+infinity: no limit)");
  require(o.max_total_iterations >= 0, "max_total_iterations", ">= 0");
}

/// Per-Solve scratch: sized once, then the DLS iterations never allocate.
struct WholeBodyIk::Workspace {
  explicit Workspace(const Kinematics& kinematics)
      : cache(kinematics.MakeCache()),
        J(6, kinematics.num_states()),
        J_active(6, kinematics.num_states()),
        step(kinematics.num_states()),
        active(kinematics.num_states()),
        chassis_margins_m(kinematics.model().spheres.size()) {
    state.q_rad = Eigen::VectorXd::Zero(kinematics.num_joints());
  }
  KinematicsCache cache;
  Eigen::MatrixXd J;         ///< 6 x (3+N) end-effector Jacobian.
  Eigen::MatrixXd J_active;  ///< J with the columns of inactive coordinates zeroed.
  Eigen::VectorXd step;      ///< dz, 3+N.
  Eigen::VectorXd active;    ///< 1 for a coordinate that moves in this step, else 0.
  Eigen::VectorXd chassis_margins_m;  ///< One per collision sphere.
  WholeBodyState state;      ///< The iterate.
  Vector6d error;
  Rng rng{1};
  int iterations_left = 0;
};

/// Outcome of one DLS run on ws.state.
struct WholeBodyIk::DlsOutcome {
  double position_error_m = std::numeric_limits<double>::infinity();
  double orientation_error_rad = std::numeric_limits<double>::infinity();
  bool converged = false;  ///< Within the tolerances.
  /// |[position error, orientation error]|, metres and radians mixed (1 rad ~ 1 m): only for
  /// progress tests and the polish threshold.
  double ErrorNorm() const {
    return std::hypot(position_error_m, orientation_error_rad);
  }
};

WholeBodyIk::WholeBodyIk(const Kinematics& kinematics, WholeBodyIkOptions options)
    : kinematics_(kinematics), options_(options), self_collision_(kinematics) {
  CheckWholeBodyIkOptions(options_);
  const RobotModel& model = kinematics.model();
  if (model.end_effector_link < 0) {
    throw std::invalid_argument("WholeBodyIk: the robot model has no end-effector link");
  }
  if (model.joint_limits.q_min_rad.size() != model.num_joints() ||
      model.joint_limits.q_max_rad.size() != model.num_joints()) {
    throw std::invalid_argument("WholeBodyIk: joint position limits missing from the model");
  }
  DeriveReachGeometry();
}

void WholeBodyIk::DeriveReachGeometry() {
  const RobotModel& model = kinematics_.model();
  // Movable links on the path root -> end-effector link, root first.
  std::vector<int> chain;
  for (int link = model.end_effector_link; link >= 0; link = model.links[link].parent) {
    if (model.links[link].q_index >= 0) chain.push_back(link);
  }
  std::reverse(chain.begin(), chain.end());
  const int n = static_cast<int>(chain.size());
  if (n == 0) throw std::invalid_argument("WholeBodyIk: no movable joint moves the end effector");

  // Geometry at q = 0 with the base at the world origin: X_WL = X_BL.
  WholeBodyState zero;
  zero.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(zero, &cache);
  auto origin = [&](int i) -> Eigen::Vector3d { return cache.X_WL[chain[i]].translation(); };
  auto axis = [&](int i) -> Eigen::Vector3d {
    return cache.X_WL[chain[i]].linear() * model.links[chain[i]].axis_J.normalized();
  };
  auto revolute = [&](int i) { return model.links[chain[i]].joint_type == JointType::kRevolute; };

  // Wrist centre: intersection of the last two revolute axes (closest points of two lines,
  // e.g. Eberly, "Distance between lines", the standard 2x2 normal equations).
  Eigen::Vector3d p_BW = cache.X_WE.translation();
  int last_rigid_with_wrist = n - 1;  // chain index whose frame the wrist point is fixed in
  if (n >= 2 && revolute(n - 1) && revolute(n - 2) &&
      AxesIntersection(origin(n - 2), axis(n - 2), origin(n - 1), axis(n - 1), &p_BW)) {
    last_rigid_with_wrist = n - 3;  // fixed in the frame before joint n-2 moves it
  }
  p_EW_ = cache.X_WE.inverse() * p_BW;

  // Shoulder: the last joint origin lying on every preceding joint axis (fixed in B).
  int k = 0;
  for (int j = 1; j < n && j <= std::max(last_rigid_with_wrist, 0); ++j) {
    bool on_all_axes = revolute(j - 1);
    for (int i = 0; i < j && on_all_axes; ++i) {
      on_all_axes = revolute(i) &&
                    DistanceToLine(origin(j), origin(i), axis(i)) < kOnAxisTolerance_m;
    }
    if (!on_all_axes) break;
    k = j;
  }
  p_BS_ = origin(k);

  // Reach: triangle inequality over points consecutive pairs of which are fixed in one frame.
  reach_m_ = 0.0;
  Eigen::Vector3d previous = p_BS_;
  for (int i = k + 1; i <= last_rigid_with_wrist; ++i) {
    reach_m_ += (origin(i) - previous).norm();
    previous = origin(i);
  }
  reach_m_ += (p_BW - previous).norm();
  for (int i = k; i < n; ++i) {  // a prismatic joint adds its stroke
    if (!revolute(i)) {
      const int q = model.links[chain[i]].q_index;
      reach_m_ += std::max(std::abs(model.joint_limits.q_min_rad(q)),
                           std::abs(model.joint_limits.q_max_rad(q)));
    }
  }
}

double WholeBodyIk::SelfDistance(Workspace* ws) const {
  // Smallest of the sphere-pair distances and the spheres' margins above the chassis top.
  self_collision_.ChassisMargins(ws->cache, ws->chassis_margins_m);
  const double chassis_margin_m = ws->chassis_margins_m.size() > 0
                                      ? ws->chassis_margins_m.minCoeff()
                                      : std::numeric_limits<double>::infinity();
  return std::min(self_collision_.MinDistance(ws->cache), chassis_margin_m);
}

WholeBodyIk::DlsOutcome WholeBodyIk::Evaluate(const Eigen::Isometry3d& X_WE_target,
                                              Workspace* ws) const {
  kinematics_.Update(ws->state, &ws->cache);
  PoseError(X_WE_target, ws->cache.X_WE, &ws->error);
  DlsOutcome outcome;
  outcome.orientation_error_rad = ws->error.head<3>().norm();
  outcome.position_error_m = ws->error.tail<3>().norm();
  outcome.converged = outcome.position_error_m <= options_.position_tolerance_m &&
                      outcome.orientation_error_rad <= options_.orientation_tolerance_rad;
  return outcome;
}

void WholeBodyIk::ComputeStep(bool move_base, Workspace* ws) const {
  const RobotModel& model = kinematics_.model();
  const int num_joints = model.num_joints();
  kinematics_.EndEffectorJacobian(ws->cache, ws->J);
  // Levenberg-Marquardt damping after Sugihara, "Solvability-unconcerned inverse kinematics by
  // the Levenberg-Marquardt method", IEEE T-RO 27(5), 2011: W_N = E I + w_bias I with
  // E = 0.5 e^T e (gain 0.5 there), so the step shrinks far from the target and becomes a
  // Gauss-Newton step near it.
  const double lambda_sq = options_.error_damping_gain * ws->error.squaredNorm() +
                           options_.damping_bias;
  ws->active.head<3>().setConstant(move_base ? 1.0 : 0.0);
  ws->active.tail(num_joints).setOnes();
  // Limit-aware step: a joint at a limit whose step pushes it further out drops out and the
  // step is recomputed (at most twice: once per newly blocked set).
  for (int pass = 0; pass < 3; ++pass) {
    ws->J_active = ws->J * ws->active.asDiagonal();
    // Damped least squares (Wampler 1986; Buss, "Introduction to inverse kinematics with
    // Jacobian transpose, pseudoinverse and damped least squares methods", 2004):
    //   dz = J^T (J J^T + lambda^2 I)^-1 e   (6 x 6 solve, equal to (J^T J + lambda^2 I)^-1 J^T e).
    Matrix6d A = ws->J_active.lazyProduct(ws->J_active.transpose());
    A.diagonal().array() += lambda_sq;
    const Vector6d y = A.llt().solve(ws->error);
    ws->step.noalias() = ws->J_active.transpose() * y;
    bool blocked_new = false;
    for (int j = 0; j < num_joints; ++j) {
      const double q = ws->state.q_rad(j);
      const double dq = ws->step(3 + j);
      const bool at_min = q <= model.joint_limits.q_min_rad(j) && dq < 0.0;
      const bool at_max = q >= model.joint_limits.q_max_rad(j) && dq > 0.0;
      if (ws->active(3 + j) > 0.0 && (at_min || at_max)) {
        ws->active(3 + j) = 0.0;
        blocked_new = true;
      }
    }
    if (!blocked_new) break;
  }
  // Step limits: scale the whole step (keeps its direction).
  double scale = 1.0;
  const double max_dq = ws->step.tail(num_joints).cwiseAbs().maxCoeff();
  if (max_dq > options_.max_joint_step_rad) scale = options_.max_joint_step_rad / max_dq;
  if (move_base) {
    const double dxy = ws->step.head<2>().norm();
    if (dxy * scale > options_.max_base_step_m) scale = options_.max_base_step_m / dxy;
    const double dyaw = std::abs(ws->step(2));
    if (dyaw * scale > options_.max_base_step_rad) scale = options_.max_base_step_rad / dyaw;
  }
  ws->step *= scale;
}

void WholeBodyIk::ApplyStep(Workspace* ws) const {
  const JointLimits& limits = kinematics_.model().joint_limits;
  ws->state.x_m += ws->step(0);
  ws->state.y_m += ws->step(1);
  ws->state.yaw_rad = WrapAngle(ws->state.yaw_rad + ws->step(2));
  ws->state.q_rad += ws->step.tail(ws->state.q_rad.size());
  ws->state.q_rad = ws->state.q_rad.cwiseMax(limits.q_min_rad).cwiseMin(limits.q_max_rad);
}

WholeBodyIk::DlsOutcome WholeBodyIk::RunDls(const Eigen::Isometry3d& X_WE_target, bool move_base,
                                            Workspace* ws) const {
  const double position_goal = options_.convergence_fraction * options_.position_tolerance_m;
  const double orientation_goal =
      options_.convergence_fraction * options_.orientation_tolerance_rad;
  constexpr int kStallIterations = 8;  // no 1 % improvement in this many: give up
  DlsOutcome outcome = Evaluate(X_WE_target, ws);
  double best = outcome.ErrorNorm();
  int since_improvement = 0;
  for (int it = 0; it < options_.max_dls_iterations && ws->iterations_left > 0; ++it) {
    if (outcome.position_error_m <= position_goal &&
        outcome.orientation_error_rad <= orientation_goal) {
      break;
    }
    ComputeStep(move_base, ws);
    ApplyStep(ws);
    --ws->iterations_left;
    outcome = Evaluate(X_WE_target, ws);
    if (outcome.ErrorNorm() < 0.99 * best) {
      best = outcome.ErrorNorm();
      since_improvement = 0;
    } else if (++since_improvement >= kStallIterations) {
      break;
    }
  }
  return outcome;
}

bool WholeBodyIk::IsDuplicate(const IkSolution& a, const IkSolution& b) const {
  const double d = options_.duplicate_distance_m, r = options_.duplicate_angle_rad;
  return std::abs(a.state.x_m - b.state.x_m) < d && std::abs(a.state.y_m - b.state.y_m) < d &&
         std::abs(WrapAngle(a.state.yaw_rad - b.state.yaw_rad)) < r &&
         (a.state.q_rad - b.state.q_rad).cwiseAbs().maxCoeff() < r;
}

double WholeBodyIk::RankCost(const IkSolution& solution, const WholeBodyIkQuery& query) const {
  double cost = 0.0;
  if (query.reference_base) {
    const Eigen::Vector3d& ref = *query.reference_base;
    cost += std::hypot(solution.state.x_m - ref.x(), solution.state.y_m - ref.y()) +
            options_.yaw_travel_weight_m_per_rad *
                std::abs(WrapAngle(solution.state.yaw_rad - ref.z()));
  }
  if (std::isfinite(solution.clearance_m)) {
    cost += options_.clearance_weight *
            std::max(0.0, options_.clearance_saturation_m - solution.clearance_m);
  }
  return cost;
}

bool WholeBodyIk::Accept(const DlsOutcome& outcome, const StateClearanceFn& clearance,
                         const WholeBodyIkQuery& query, IkSeed seed, Workspace* ws,
                         WholeBodyIkResult* result) const {
  if (!outcome.converged) {
    ++result->rejected_not_converged;
    return false;
  }
  // ws->cache holds the kinematics of ws->state (Evaluate ran last).
  IkSolution solution;
  solution.self_distance_m = SelfDistance(ws);
  if (!(solution.self_distance_m > options_.min_self_distance_m)) {
    ++result->rejected_self_collision;
    return false;
  }
  solution.clearance_m = clearance ? clearance(ws->state) : std::numeric_limits<double>::infinity();
  if (!(solution.clearance_m > options_.min_clearance_m)) {  // NaN clearance is rejected too
    ++result->rejected_clearance;
    return false;
  }
  solution.state = ws->state;
  if (query.reference_q_rad) {
    solution.state.q_rad = NearestJointTurns(kinematics_.model(), solution.state.q_rad, *query.reference_q_rad);
  }
  solution.position_error_m = outcome.position_error_m;
  solution.orientation_error_rad = outcome.orientation_error_rad;
  solution.from_hint = seed == IkSeed::kHint;
  solution.base_stays = seed == IkSeed::kStanding;
  solution.cost = RankCost(solution, query);
  for (IkSolution& kept : result->solutions) {
    if (IsDuplicate(kept, solution)) {
      ++result->duplicates_removed;
      if (solution.cost < kept.cost) kept = std::move(solution);
      return true;
    }
  }
  result->solutions.push_back(std::move(solution));
  return true;
}

WholeBodyIk::DlsOutcome WholeBodyIk::Attempt(const Eigen::Isometry3d& X_WE_target,
                                             WholeBodyIkResult* result, Workspace* ws) const {
  ++result->dls_runs;
  DlsOutcome outcome = RunDls(X_WE_target, /*move_base=*/false, ws);
  if (!outcome.converged && options_.whole_body_polish &&
      outcome.ErrorNorm() < options_.polish_start_error) {
    ++result->dls_runs;
    outcome = RunDls(X_WE_target, /*move_base=*/true, ws);
  }
  return outcome;
}

std::vector<Eigen::Vector3d> WholeBodyIk::SampleBasePoses(const Eigen::Vector3d& p_WW,
                                                          double rho_lo_m, double rho_hi_m,
                                                          const WholeBodyIkQuery& query,
                                                          Rng* rng) const {
  const int n = std::max(options_.max_base_candidates, 0);
  std::vector<Eigen::Vector3d> bases;
  bases.reserve(n);
  if (n == 0) return bases;
  const bool has_reference = query.reference_base.has_value();
  // Bearing (from W) of the first candidate: towards the reference base, else random.
  const double bearing0 =
      has_reference ? std::atan2(query.reference_base->y() - p_WW.y(),
                                 query.reference_base->x() - p_WW.x())
                    : rng->Uniform(-std::numbers::pi, std::numbers::pi);
  const double spacing = 2.0 * std::numbers::pi / n;
  const Eigen::Vector2d p_BS_xy = p_BS_.head<2>();
  for (int k = 0; k < n; ++k) {
    const bool exact = k == 0 && has_reference;  // straight on the reference's side
    const int ring_step = (k + 1) / 2;
    const double side = (k % 2 == 1) ? 1.0 : -1.0;
    double bearing = bearing0 + side * ring_step * spacing;
    double rho = 0.0, yaw_offset = 0.0;
    if (exact) {
      const double d_ref = (query.reference_base->head<2>() - p_WW.head<2>()).norm();
      rho = std::clamp(d_ref, rho_lo_m, rho_hi_m);
    } else {
      bearing += rng->Uniform(-0.5, 0.5) * spacing;
      rho = rng->Uniform(rho_lo_m, rho_hi_m);
      yaw_offset = rng->Uniform(-options_.yaw_spread_rad, options_.yaw_spread_rad);
    }
    // Shoulder on the circle around W; the base faces W: yaw = bearing + pi (+ offset).
    const Eigen::Vector2d p_WS_xy =
        p_WW.head<2>() + rho * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    const double yaw = WrapAngle(bearing + std::numbers::pi + yaw_offset);
    // p_WS = p_WB + R_WB p_BS  =>  p_WB = p_WS - R_WB p_BS.
    const Eigen::Vector2d p_WB_xy = p_WS_xy - Eigen::Rotation2Dd(yaw) * p_BS_xy;
    bases.emplace_back(p_WB_xy.x(), p_WB_xy.y(), yaw);
  }
  return bases;
}

std::string WholeBodyIk::CheckQuery(const WholeBodyIkQuery& query) const {
  // Something of the query with `joints` joints (the hint, the standing state, the reference
  // joints), named `what`, finite or not.
  const auto check = [this](bool given, Eigen::Index joints, bool finite, const std::string& what) -> std::string {
    if (!given) return "";
    if (joints != kinematics_.num_joints()) {
      return what + " has " + std::to_string(joints) + " joints, the robot " + std::to_string(kinematics_.num_joints());
    }
    return finite ? "" : what + " contains NaN or infinity";
  };
  const auto& hint = query.hint;
  const auto& standing = query.standing;
  const auto& reference_q = query.reference_q_rad;
  for (const std::string& why :
       {check(hint.has_value(), hint ? hint->num_joints() : 0, hint && hint->IsFinite(), "hint"),
        check(standing.has_value(), standing ? standing->num_joints() : 0, standing && standing->IsFinite(),
              "standing state"),
        check(reference_q.has_value(), reference_q ? reference_q->size() : 0, reference_q && reference_q->allFinite(),
              "reference joint vector")}) {
    if (!why.empty()) return why;
  }
  if (query.reference_base && !query.reference_base->allFinite()) {
    return "reference base pose contains NaN or infinity";
  }
  return "";
}

WholeBodyIkResult WholeBodyIk::Solve(const Eigen::Isometry3d& X_WE_target,
                                     const StateClearanceFn& clearance,
                                     const WholeBodyIkQuery& query) const {
  const Stopwatch watch;
  WholeBodyIkResult result;
  auto finish = [&](std::string failure) {
    if (result.solutions.empty()) result.failure_reason = std::move(failure);
    std::stable_sort(result.solutions.begin(), result.solutions.end(),
                     [](const IkSolution& a, const IkSolution& b) { return a.cost < b.cost; });
    result.solve_time_s = watch.ElapsedS();
    return result;
  };

  std::string why;
  if (!IsValidPose(X_WE_target, &why)) return finish("bad input: " + why);
  why = CheckQuery(query);
  if (!why.empty()) return finish("bad input: " + why);

  const Eigen::Vector3d p_WW = X_WE_target * p_EW_;
  double rho_lo = 0.0, rho_hi = 0.0;
  why = ReachBand(p_WW, &result, &rho_lo, &rho_hi);
  if (!why.empty()) return finish(why);

  Workspace ws(kinematics_);
  ws.rng = Rng(options_.seed);
  ws.iterations_left = options_.max_total_iterations;
  // 1. The hint: as is, else as a seed.
  if (query.hint) TryHint(X_WE_target, clearance, query, &ws, &result);
  if (query.standing) TryStanding(X_WE_target, clearance, query, &ws, &result);
  // 2. Base candidates around the target, restarts at each.
  SearchBases(X_WE_target, p_WW, rho_lo, rho_hi, clearance, query, watch, &ws, &result);
  result.total_iterations = options_.max_total_iterations - ws.iterations_left;
  return finish(DescribeNoSolution(result));
}

std::string WholeBodyIk::ReachBand(const Eigen::Vector3d& p_WW, WholeBodyIkResult* result,
                                   double* rho_lo, double* rho_hi) const {
  // Reach band for the shoulder-to-wrist-centre horizontal distance.
  const double dz = p_WW.z() - p_BS_.z();
  result->reach_max_m =
      options_.reach_max_m > 0.0 ? options_.reach_max_m : options_.stretch_fraction * reach_m_;
  result->reach_min_m = options_.reach_min_m > 0.0 ? options_.reach_min_m : 0.2 * reach_m_;
  if (std::abs(dz) >= reach_m_) {
    std::ostringstream out;
    out << "target out of reach: its wrist centre is " << dz
        << " m above the shoulder, the arm reaches " << reach_m_ << " m";
    return out.str();
  }
  *rho_hi = std::sqrt(std::max(result->reach_max_m * result->reach_max_m - dz * dz, 0.0));
  if (*rho_hi <= 0.0) *rho_hi = 0.5 * std::sqrt(reach_m_ * reach_m_ - dz * dz);
  *rho_lo = std::min(result->reach_min_m, 0.5 * *rho_hi);
  return "";
}

void WholeBodyIk::TryHint(const Eigen::Isometry3d& X_WE_target, const StateClearanceFn& clearance,
                          const WholeBodyIkQuery& query, Workspace* ws,
                          WholeBodyIkResult* result) const {
  ws->state = *query.hint;
  ws->state.yaw_rad = WrapAngle(ws->state.yaw_rad);
  const JointLimits& limits = kinematics_.model().joint_limits;
  const bool within_limits = (ws->state.q_rad.array() >= limits.q_min_rad.array()).all() &&
                             (ws->state.q_rad.array() <= limits.q_max_rad.array()).all();
  DlsOutcome outcome = Evaluate(X_WE_target, ws);
  if (!within_limits) {
    ws->state.q_rad = ws->state.q_rad.cwiseMax(limits.q_min_rad).cwiseMin(limits.q_max_rad);
    outcome = Evaluate(X_WE_target, ws);
  }
  bool accepted = outcome.converged &&
                  Accept(outcome, clearance, query, IkSeed::kHint, ws, result);
  if (!accepted) {
    outcome = Attempt(X_WE_target, result, ws);
    accepted = Accept(outcome, clearance, query, IkSeed::kHint, ws, result);
  }
  result->hint_used = accepted;
}

void WholeBodyIk::TryStanding(const Eigen::Isometry3d& X_WE_target,
                              const StateClearanceFn& clearance, const WholeBodyIkQuery& query,
                              Workspace* ws, WholeBodyIkResult* result) const {
  ws->state = *query.standing;
  const JointLimits& limits = kinematics_.model().joint_limits;
  ws->state.q_rad = ws->state.q_rad.cwiseMax(limits.q_min_rad).cwiseMin(limits.q_max_rad);
  ++result->dls_runs;
  const DlsOutcome outcome = RunDls(X_WE_target, /*move_base=*/false, ws);
  // The DLS keeps the base; the unwrapped yaw of the standing state is kept as well.
  Accept(outcome, clearance, query, IkSeed::kStanding, ws, result);
}

bool WholeBodyIk::OutOfBudget(const Stopwatch& watch, const Workspace& ws,
                              WholeBodyIkResult* result) const {
  if (ws.iterations_left <= 0 || watch.ElapsedS() > options_.time_budget_s) {
    result->budget_exhausted = true;
  }
  return result->budget_exhausted;
}

void WholeBodyIk::SearchBases(const Eigen::Isometry3d& X_WE_target, const Eigen::Vector3d& p_WW,
                              double rho_lo, double rho_hi, const StateClearanceFn& clearance,
                              const WholeBodyIkQuery& query, const Stopwatch& watch,
                              Workspace* ws, WholeBodyIkResult* result) const {
  const std::vector<Eigen::Vector3d> bases =
      SampleBasePoses(p_WW, rho_lo, rho_hi, query, &ws->rng);
  const JointLimits& limits = kinematics_.model().joint_limits;
  for (const Eigen::Vector3d& base : bases) {
    if (static_cast<int>(result->solutions.size()) >= options_.max_solutions ||
        OutOfBudget(watch, *ws, result)) {
      break;
    }
    ++result->base_candidates_tried;
    for (int restart = 0; restart < options_.restarts_per_base; ++restart) {
      if (OutOfBudget(watch, *ws, result)) break;
      ws->state.x_m = base.x();
      ws->state.y_m = base.y();
      ws->state.yaw_rad = base.z();
      if (restart == 0 && query.hint) {
        ws->state.q_rad = query.hint->q_rad.cwiseMax(limits.q_min_rad).cwiseMin(limits.q_max_rad);
      } else {
        for (int j = 0; j < ws->state.num_joints(); ++j) {
          ws->state.q_rad(j) = ws->rng.Uniform(limits.q_min_rad(j), limits.q_max_rad(j));
        }
      }
      const DlsOutcome outcome = Attempt(X_WE_target, result, ws);
      if (Accept(outcome, clearance, query, IkSeed::kSearch, ws, result)) break;
    }
  }
}

std::string WholeBodyIk::DescribeNoSolution(const WholeBodyIkResult& result) const {
  std::ostringstream out;
  out << "no valid solution: " << result.base_candidates_tried << " base poses, "
      << result.dls_runs << " DLS runs; rejected " << result.rejected_not_converged
      << " not converged, " << result.rejected_self_collision << " in self-collision, "
      << result.rejected_clearance << " with clearance <= " << options_.min_clearance_m << " m"
      << (result.budget_exhausted ? "; budget exhausted" : "");
  return out.str();
}

}  // namespace topay
