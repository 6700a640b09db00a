#include "core/planning/whole_body_validity.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/planning/base_band.h"

namespace topay {
namespace {

// Default margins: why field-valid implies exactly clear.
//
// Let d be the exact signed distance to the boxes (in 2D: to their footprints), res the cell
// size and n the dimension (2 or 3). With the fields' default zero level (boundary occupied
// cell centres, SignedDistanceFieldOptions::zero_level_inset_cells = 0.5) and conservative
// rasterisation (a cell is occupied iff it overlaps a box):
//  (1) a free cell's value is the distance from its centre c to the nearest occupied centre;
//      the box point nearest to c lies in an occupied cell whose centre is within
//      sqrt(n)/2 res of it, so value(c) <= d(c) + sqrt(n)/2 res. Occupied cells hold values
//      <= 0 and d(c) >= -(depth) with depth <= (distance to a free centre) - res/2, which
//      gives the same inequality.
//  (2) the interpolant is a convex combination sum_i w_i value(c_i) over the cell's corners,
//      and d is 1-Lipschitz: d(c_i) <= d(p) + |c_i - p|, with sum_i w_i |c_i - p| at most
//      sqrt(n)/2 res (attained at the cell's centre).
// Hence field(p) <= d(p) + sqrt(n) res, and field(p) >= r + sqrt(n) res implies d(p) >= r.
// A field of exact (possibly capped) distances at the centres (BuildFootprintDistanceField)
// (BuildBoxDistanceField in 3D) has value(c) <= d(c) in (1), so only (2) remains:
// sqrt(n)/2 res. Each field states its own bound (exactness_margin_m), the default margin.
// The exact base test (cylinder from the ground to the chassis top) equals the 2D distance to
// the footprints of the boxes in the base band, which is what the 2D field rasterises.
double ResolveMargin(const std::optional<double>& margin, double default_m, const char* name) {
  const double value = margin.value_or(default_m);
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("WholeBodyValidity: ") + name +
                                " must be finite and >= 0, got " + std::to_string(value));
  }
  return value;
}

}  // namespace

void CheckWholeBodyValidityOptions(const WholeBodyValidityOptions& options) {
  if (options.base_margin_m) ResolveMargin(options.base_margin_m, 0.0, "base_margin_m");
  if (options.arm_margin_m) ResolveMargin(options.arm_margin_m, 0.0, "arm_margin_m");
  if (!std::isfinite(options.self_margin_m)) {
    throw std::invalid_argument("WholeBodyValidity: self_margin_m must be finite");
  }
  if (!(options.max_edge_step_m > 0.0)) {
    throw std::invalid_argument("WholeBodyValidity: max_edge_step_m must be positive");
  }
  if (!(options.max_edge_step_rad > 0.0)) {
    throw std::invalid_argument("WholeBodyValidity: max_edge_step_rad must be positive");
  }
}

std::string_view ToString(ValidityFailure failure) {
  switch (failure) {
    case ValidityFailure::kNone:
      return "valid";
    case ValidityFailure::kMalformed:
      return "malformed state (joint count or non-finite value)";
    case ValidityFailure::kJointLimit:
      return "joint limit";
    case ValidityFailure::kBaseCollision:
      return "base collision (2D field)";
    case ValidityFailure::kArmCollision:
      return "arm collision (3D field)";
    case ValidityFailure::kSelfCollision:
      return "self collision";
    case ValidityFailure::kChassis:
      return "arm below the chassis top";
    case ValidityFailure::kExactCollision:
      return "collision (exact geometry)";
  }
  return "unknown";
}

WholeBodyValidity::WholeBodyValidity(const Kinematics& kinematics,
                                     const SignedDistanceField2& base_field,
                                     const SignedDistanceField3& arm_field,
                                     const WholeBodyValidityOptions& options)
    : kinematics_(kinematics),
      base_field_(base_field),
      arm_field_(arm_field),
      self_collision_(kinematics),
      options_(options),
      arm_field_spheres_(SpheresToCheckOnArmField(kinematics, base_field)) {
  CheckWholeBodyValidityOptions(options);
  base_margin_m_ = ResolveMargin(
      options.base_margin_m, base_field.exactness_margin_m(), "base_margin_m");
  arm_margin_m_ = ResolveMargin(
      options.arm_margin_m, arm_field.exactness_margin_m(), "arm_margin_m");
}

WholeBodyValidityWorkspace WholeBodyValidity::MakeWorkspace() const {
  WholeBodyValidityWorkspace workspace;
  workspace.cache = kinematics_.MakeCache();
  workspace.pair_distances_m.resize(self_collision_.num_pairs());
  workspace.chassis_margins_m.resize(self_collision_.num_spheres());
  workspace.interpolated.q_rad.resize(kinematics_.num_joints());
  return workspace;
}

WholeBodyValidity WholeBodyValidity::WithExactZones(ExactZones zones) const {
  CheckExactZoneOptions(zones.options);
  WholeBodyValidity copy(*this);
  copy.zones_ = std::move(zones);
  return copy;
}

bool WholeBodyValidity::IsBaseValidOnField(const Eigen::Vector2d& p_WB) const {
  // NaN compares false, so a NaN position is invalid.
  return base_field_.Distance(p_WB) >= model().base_cylinder.radius_m + base_margin_m_;
}

bool WholeBodyValidity::IsBaseValid(const Eigen::Vector2d& p_WB) const {
  if (IsBaseValidOnField(p_WB)) return true;
  if (!p_WB.allFinite() || !zones_.Contains(p_WB)) return false;
  const double margin_m = zones_.options.obstacle_margin_m;
  return zones_.checker->BaseClearance(p_WB, margin_m) > margin_m;
}

ValidityFailure WholeBodyValidity::Check(const WholeBodyState& state,
                                         WholeBodyValidityWorkspace* workspace,
                                         bool check_base) const {
  if (zones_.empty() || !std::isfinite(state.x_m) || !std::isfinite(state.y_m) ||
      !zones_.Contains(state)) {
    return CheckOnFields(state, workspace, check_base);
  }
  const ValidityFailure failure = CheckOnFields(state, workspace, /*check_base=*/true);
  if (failure != ValidityFailure::kBaseCollision && failure != ValidityFailure::kArmCollision) {
    return failure;
  }
  // The fields are conservative here: ask the exact scene (every part, at the zones' margins).
  if (!workspace->exact) workspace->exact = zones_.checker->MakeWorkspace();
  const double self_margin_m = std::max(zones_.options.self_margin_m, options_.self_margin_m);
  return zones_.checker->IsCollisionFree(state, zones_.options.obstacle_margin_m, self_margin_m,
                                         &*workspace->exact)
             ? ValidityFailure::kNone
             : ValidityFailure::kExactCollision;
}

ValidityFailure WholeBodyValidity::CheckOnFields(const WholeBodyState& state,
                                                 WholeBodyValidityWorkspace* workspace,
                                                 bool check_base) const {
  const RobotModel& robot = model();
  if (state.num_joints() != robot.num_joints() || !state.IsFinite()) {
    return ValidityFailure::kMalformed;
  }
  const JointLimits& limits = robot.joint_limits;
  for (int i = 0; i < robot.num_joints(); ++i) {
    if (state.q_rad(i) < limits.q_min_rad(i) || state.q_rad(i) > limits.q_max_rad(i)) {
      return ValidityFailure::kJointLimit;
    }
  }
  if (check_base && !IsBaseValidOnField(Eigen::Vector2d(state.x_m, state.y_m))) {
    return ValidityFailure::kBaseCollision;
  }
  kinematics_.Update(state, &workspace->cache);
  for (const int s : arm_field_spheres_) {
    const double needed = robot.spheres[s].radius_m + arm_margin_m_;
    if (!(arm_field_.Distance(workspace->cache.p_WS[s]) >= needed)) {
      return ValidityFailure::kArmCollision;
    }
  }
  self_collision_.ChassisMargins(workspace->cache, workspace->chassis_margins_m);
  if (self_collision_.num_spheres() > 0 &&
      !(workspace->chassis_margins_m.minCoeff() > options_.self_margin_m)) {
    return ValidityFailure::kChassis;
  }
  self_collision_.Distances(workspace->cache, workspace->pair_distances_m);
  if (self_collision_.num_pairs() > 0 &&
      !(workspace->pair_distances_m.minCoeff() > options_.self_margin_m)) {
    return ValidityFailure::kSelfCollision;
  }
  return ValidityFailure::kNone;
}

int WholeBodyValidity::EdgeInterpolationSteps(const WholeBodyState& a, const WholeBodyState& b,
                                              double max_step_m, double max_step_rad) {
  const double translation = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  double rotation = std::abs(b.yaw_rad - a.yaw_rad);
  if (a.q_rad.size() == b.q_rad.size() && a.q_rad.size() > 0) {
    rotation = std::max(rotation, (b.q_rad - a.q_rad).cwiseAbs().maxCoeff());
  }
  const double steps = std::max(translation / max_step_m, rotation / max_step_rad);
  if (!std::isfinite(steps)) return 1;
  return std::max(1, static_cast<int>(std::ceil(steps - 1e-9)));
}

void WholeBodyValidity::Interpolate(const WholeBodyState& a, const WholeBodyState& b, double s,
                                    WholeBodyState* out) {
  out->x_m = a.x_m + s * (b.x_m - a.x_m);
  out->y_m = a.y_m + s * (b.y_m - a.y_m);
  out->yaw_rad = a.yaw_rad + s * (b.yaw_rad - a.yaw_rad);
  out->q_rad = a.q_rad + s * (b.q_rad - a.q_rad);  // no allocation once sized
}

ValidityFailure WholeBodyValidity::CheckEdge(const WholeBodyState& a, const WholeBodyState& b,
                                             WholeBodyValidityWorkspace* workspace,
                                             bool check_base) const {
  if (a.num_joints() != model().num_joints() || b.num_joints() != model().num_joints()) {
    return ValidityFailure::kMalformed;
  }
  const int steps = EdgeSteps(a, b);
  // End points first (most likely to fail cheaply), then the interior.
  ValidityFailure failure = Check(b, workspace, check_base);
  if (failure != ValidityFailure::kNone) return failure;
  failure = Check(a, workspace, check_base);
  if (failure != ValidityFailure::kNone) return failure;
  WholeBodyState& state = workspace->interpolated;
  for (int k = 1; k < steps; ++k) {
    Interpolate(a, b, static_cast<double>(k) / steps, &state);
    failure = Check(state, workspace, check_base);
    if (failure != ValidityFailure::kNone) return failure;
  }
  return ValidityFailure::kNone;
}

}  // namespace topay
