#include "core/collision/start_target_diagnosis.h"

#include <cmath>
#include <cstdio>

#include "core/collision/scene_clearance.h"
#include "core/geometry/oriented_box.h"

namespace topay {
namespace {

std::string Fixed(double value, int digits = 3) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

std::string Vector(const Eigen::Vector3d& v) {
  return "(" + Fixed(v.x()) + ", " + Fixed(v.y()) + ", " + Fixed(v.z()) + ")";
}

std::string BoxName(const Scene& scene, int box) {
  const OrientedBox& b = scene.boxes[static_cast<std::size_t>(box)];
  return "box " + std::to_string(box) + " (centre " + Vector(b.center_W_m) + " m, size " +
         Vector(b.size_m) + " m, yaw " + Fixed(b.yaw_rad) + " rad)";
}

// "penetrates X by d m" for d < 0, "touches X" for d == 0, "is d m from X" otherwise.
std::string Contact(double distance_m, const std::string& what) {
  if (distance_m < 0.0) return "penetrates " + what + " by " + Fixed(-distance_m) + " m";
  if (distance_m == 0.0) return "touches " + what;
  return "is " + Fixed(distance_m) + " m from " + what;
}

std::string SphereName(const RobotModel& model, int sphere) {
  const CollisionSphere& s = model.spheres[static_cast<std::size_t>(sphere)];
  return "arm sphere " + std::to_string(sphere) + " (radius " + Fixed(s.radius_m) +
         " m) on link '" + model.links[static_cast<std::size_t>(s.link)].name + "'";
}

std::optional<std::string> Malformed(const RobotModel& model, const WholeBodyState& state) {
  if (state.num_joints() != model.num_joints()) {
    return "the state has " + std::to_string(state.num_joints()) + " joint values, the robot " +
           std::to_string(model.num_joints()) + " joints";
  }
  if (!state.IsFinite()) return "the state holds a value that is not finite";
  return std::nullopt;
}

std::optional<std::string> JointOutsideLimits(const RobotModel& model,
                                              const WholeBodyState& state) {
  const JointLimits& limits = model.joint_limits;
  for (int i = 0; i < model.num_joints(); ++i) {
    const double q = state.q_rad(i);
    if (q < limits.q_min_rad(i) || q > limits.q_max_rad(i)) {
      return "joint '" + model.joint_names[static_cast<std::size_t>(i)] + "' (q" +
             std::to_string(i + 1) + ") is " + Fixed(q) + " rad, outside its limits [" +
             Fixed(limits.q_min_rad(i)) + ", " + Fixed(limits.q_max_rad(i)) + "] rad";
    }
  }
  return std::nullopt;
}

std::optional<std::string> BaseOutsideBounds(const Scene& scene, const WholeBodyState& state) {
  const Eigen::Vector3d& lo = scene.bounds_W_m.min();
  const Eigen::Vector3d& hi = scene.bounds_W_m.max();
  if (state.x_m < lo.x() || state.x_m > hi.x() || state.y_m < lo.y() || state.y_m > hi.y()) {
    return "the base position (" + Fixed(state.x_m) + ", " + Fixed(state.y_m) +
           ") m is outside the scene bounds x [" + Fixed(lo.x()) + ", " + Fixed(hi.x()) +
           "], y [" + Fixed(lo.y()) + ", " + Fixed(hi.y()) + "] m";
  }
  return std::nullopt;
}

std::optional<std::string> Clearances(const Kinematics& kinematics, const Scene& scene,
                                      const WholeBodyState& state,
                                      const StartDiagnosisOptions& options) {
  const RobotModel& model = kinematics.model();
  const SceneClearance c = SceneClearanceChecker(kinematics, scene).Compute(state);
  if (c.base_box >= 0 && c.base_m <= options.obstacle_margin_m) {
    return "the base (cylinder radius " + Fixed(model.base_cylinder.radius_m) + " m) " +
           Contact(c.base_m, BoxName(scene, c.base_box));
  }
  if (c.sphere >= 0 && c.sphere_box >= 0 && c.spheres_m <= options.obstacle_margin_m) {
    return "the " + SphereName(model, c.sphere) + " " +
           Contact(c.spheres_m, BoxName(scene, c.sphere_box));
  }
  if (c.self_pair >= 0 && c.self_m <= options.self_margin_m) {
    const auto [a, b] = model.self_collision_pairs[static_cast<std::size_t>(c.self_pair)];
    return "self collision: the " + SphereName(model, a) + " and the " + SphereName(model, b) +
           (c.self_m < 0.0 ? " overlap by " + Fixed(-c.self_m) + " m"
                           : " are " + Fixed(c.self_m) + " m apart");
  }
  if (c.chassis_sphere >= 0 && c.chassis_m <= options.self_margin_m) {
    return "the " + SphereName(model, c.chassis_sphere) +
           (c.chassis_m < 0.0 ? " reaches " + Fixed(-c.chassis_m) + " m below"
                              : " is only " + Fixed(c.chassis_m) + " m above") +
           " the chassis top (z = " + Fixed(model.base_cylinder.height_m) + " m)";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> DiagnoseStartState(const Kinematics& kinematics, const Scene& scene,
                                              const WholeBodyState& state,
                                              const StartDiagnosisOptions& options) {
  const RobotModel& model = kinematics.model();
  if (auto why = Malformed(model, state)) return why;
  if (auto why = JointOutsideLimits(model, state)) return why;
  if (auto why = BaseOutsideBounds(scene, state)) return why;
  return Clearances(kinematics, scene, state, options);
}

std::optional<std::string> DiagnoseTarget(const Scene& scene, const Eigen::Isometry3d& X_WE) {
  if (!X_WE.matrix().allFinite()) return "the target pose holds a value that is not finite";
  const Eigen::Matrix3d R = X_WE.linear();
  if (!(R.transpose() * R).isIdentity(1e-6) || R.determinant() < 0.0) {
    return "the target rotation is not a rotation matrix (orthonormal, determinant +1)";
  }
  const Eigen::Vector3d p = X_WE.translation();
  const Eigen::Vector3d& lo = scene.bounds_W_m.min();
  const Eigen::Vector3d& hi = scene.bounds_W_m.max();
  if (p.z() < lo.z()) {
    return "the target point " + Vector(p) + " m is below the floor (z = " + Fixed(lo.z()) +
           " m)";
  }
  if (!scene.bounds_W_m.contains(p)) {
    return "the target point " + Vector(p) + " m is outside the room (scene bounds " +
           Vector(lo) + " to " + Vector(hi) + " m)";
  }
  int first = -1;
  int count = 0;
  double depth_m = 0.0;
  for (int b = 0; b < static_cast<int>(scene.boxes.size()); ++b) {
    const double d = SignedDistanceToBox(scene.boxes[static_cast<std::size_t>(b)], p);
    if (d >= 0.0) continue;
    if (first < 0) {
      first = b;
      depth_m = -d;
    }
    ++count;
  }
  if (first < 0) return std::nullopt;
  std::string why = "the target point " + Vector(p) + " m is inside " + BoxName(scene, first) +
                    ", " + Fixed(depth_m) + " m deep";
  if (count > 1) why += " (and inside " + std::to_string(count - 1) + " more boxes)";
  return why;
}

}  // namespace topay
