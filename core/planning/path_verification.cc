#include "core/planning/path_verification.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/common/angles.h"

namespace topay {
namespace {

bool OnLayer(const WholeBodyState& state, const Se2Layer& layer) {
  constexpr double kTolerance = 1e-9;
  return std::abs(state.x_m - layer.x_m) <= kTolerance &&
         std::abs(state.y_m - layer.y_m) <= kTolerance &&
         std::abs(WrapAngle(state.yaw_rad - layer.yaw_rad)) <= kTolerance;
}

// Index in {previous - 1, previous, previous + 1} of a layer holding `state`, or -1.
int AdjacentLayer(const WholeBodyState& state, const DiscreteSE2Path& layers, int previous) {
  for (int candidate : {previous, previous + 1, previous - 1}) {
    if (candidate >= 0 && candidate < layers.num_layers() &&
        OnLayer(state, layers.layers[candidate])) {
      return candidate;
    }
  }
  return -1;
}

std::string CheckShapeAndStart(const WholeBodyPath& path, const WholeBodyState& start,
                               const PathVerificationOptions& o) {
  if (path.states.empty()) return "no states";
  if (path.times_s.size() != path.states.size()) return "times_s and states differ in size";
  for (std::size_t k = 1; k < path.times_s.size(); ++k) {
    if (!(path.times_s[k] > path.times_s[k - 1])) {
      return "times_s not increasing at state " + std::to_string(k);
    }
  }
  const WholeBodyState& first = path.states.front();
  if (first.num_joints() != start.num_joints() ||
      std::abs(first.x_m - start.x_m) > o.start_tolerance ||
      std::abs(first.y_m - start.y_m) > o.start_tolerance ||
      std::abs(WrapAngle(first.yaw_rad - start.yaw_rad)) > o.start_tolerance ||
      (first.q_rad - start.q_rad).cwiseAbs().maxCoeff() > o.start_tolerance) {
    return "first state is not the start state";
  }
  return "";
}

std::string CheckLayers(const WholeBodyPath& path, const DiscreteSE2Path& layers) {
  int layer = 0;
  for (std::size_t k = 0; k < path.states.size(); ++k) {
    const int next = k == 0 ? (OnLayer(path.states[0], layers.layers.front()) ? 0 : -1)
                            : AdjacentLayer(path.states[k], layers, layer);
    if (next < 0) {
      return "state " + std::to_string(k) + " is not on a layer adjacent to layer " +
             std::to_string(layer);
    }
    layer = next;
  }
  if (layer != layers.num_layers() - 1) return "last state is not on the last layer";
  return "";
}

std::string CheckJointLimits(const WholeBodyState& state, const JointLimits& limits) {
  for (int j = 0; j < state.num_joints(); ++j) {
    if (!(state.q_rad(j) >= limits.q_min_rad(j) && state.q_rad(j) <= limits.q_max_rad(j))) {
      return "joint " + std::to_string(j + 1) + " outside its limits";
    }
  }
  return "";
}

// The interpolation a -> b (state b alone for k = 0) in n intervals with steps <= the
// maxima, every state checked against the scene; "" or the collision.
std::string CheckSegment(const WholeBodyState& a, const WholeBodyState& b, std::size_t k,
                         const SceneClearanceChecker& checker, const PathVerificationOptions& o,
                         WholeBodyState* state, SceneClearanceWorkspace* workspace,
                         PathVerification* out) {
  const double translation_m = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  const double rotation_rad = std::max(std::abs(b.yaw_rad - a.yaw_rad),
                                       (b.q_rad - a.q_rad).cwiseAbs().maxCoeff());
  const int n = std::max(1, static_cast<int>(std::ceil(std::max(
                                translation_m / o.max_step_m, rotation_rad / o.max_step_rad))));
  for (int i = (k == 0 ? n : 1); i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    state->x_m = a.x_m + s * (b.x_m - a.x_m);
    state->y_m = a.y_m + s * (b.y_m - a.y_m);
    state->yaw_rad = a.yaw_rad + s * (b.yaw_rad - a.yaw_rad);
    state->q_rad = a.q_rad + s * (b.q_rad - a.q_rad);
    const SceneClearance c = checker.Compute(*state, workspace);
    ++out->num_states_checked;
    out->min_obstacle_clearance_m = std::min(out->min_obstacle_clearance_m, c.obstacle_m());
    if (!c.IsCollisionFree(o.obstacle_margin_m, o.self_margin_m)) {
      std::ostringstream message;
      message << "collision between states " << (k == 0 ? 0 : k - 1) << " and " << k
              << " (s = " << s << "): base " << c.base_m << " m, arm " << c.spheres_m
              << " m, self " << c.self_m << " m, chassis " << c.chassis_m << " m";
      return message.str();
    }
  }
  return "";
}

// The end effector at the last state within the tolerances of the target; "" or the miss.
std::string CheckEndEffector(const WholeBodyState& last, const Eigen::Isometry3d& X_WE_target,
                             const Kinematics& kinematics, const PathVerificationOptions& o) {
  const Eigen::Isometry3d X_WE = kinematics.EndEffectorPose(last);
  const double position_error_m = (X_WE.translation() - X_WE_target.translation()).norm();
  const double orientation_error_rad =
      Eigen::AngleAxisd(X_WE_target.linear() * X_WE.linear().transpose()).angle();
  if (!(position_error_m <= o.position_tolerance_m) ||
      !(orientation_error_rad <= o.orientation_tolerance_rad)) {
    std::ostringstream message;
    message << "end effector misses the target by " << position_error_m << " m, "
            << orientation_error_rad << " rad";
    return message.str();
  }
  return "";
}

}  // namespace

PathVerification VerifyWholeBodyPath(const WholeBodyPath& path, const WholeBodyState& start,
                                     const Eigen::Isometry3d& X_WE_target,
                                     const SceneClearanceChecker& checker,
                                     const Kinematics& kinematics, const DiscreteSE2Path* layers,
                                     const PathVerificationOptions& o) {
  PathVerification out;
  auto fail = [&out](std::string message) {
    out.ok = false;
    out.message = std::move(message);
    return out;
  };
  std::string why = CheckShapeAndStart(path, start, o);
  if (!why.empty()) return fail(why);
  if (layers != nullptr) {
    why = CheckLayers(path, *layers);
    if (!why.empty()) return fail(why);
  }
  const JointLimits& limits = kinematics.model().joint_limits;
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  WholeBodyState state = path.states.front();
  for (std::size_t k = 0; k < path.states.size(); ++k) {
    if (path.states[k].num_joints() != kinematics.num_joints() || !path.states[k].IsFinite()) {
      return fail("state " + std::to_string(k) + " malformed");
    }
    why = CheckJointLimits(path.states[k], limits);
    if (!why.empty()) return fail("state " + std::to_string(k) + ": " + why);
    const WholeBodyState& a = k == 0 ? path.states[0] : path.states[k - 1];
    why = CheckSegment(a, path.states[k], k, checker, o, &state, &workspace, &out);
    if (!why.empty()) return fail(why);
  }
  why = CheckEndEffector(path.states.back(), X_WE_target, kinematics, o);
  if (!why.empty()) return fail(why);
  out.ok = true;
  return out;
}

}  // namespace topay
