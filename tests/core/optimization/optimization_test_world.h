#pragma once

// Shared by the core/optimization tests: the project's robot, a small hand-made scene with
// its two distance fields, straight-line whole-body paths, central differences and an
// independent check of a trajectory against the exact scene geometry and the limits.

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/angles.h"
#include "core/geometry/scene.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/base_band.h"
#include "core/planning/whole_body_path.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::testing {

/// The robot, its kinematics, a scene and both fields (3D 0.1 m; 2D 0.05 m on the front
/// end's base band), as the optimizer's callers build them.
struct OptimizationWorld {
  RobotModel model;
  std::unique_ptr<Kinematics> kinematics;
  Scene scene;
  std::unique_ptr<SceneDistanceFields> fields;

  const SignedDistanceField2& base_field() const { return fields->base_field_2d; }
  const SignedDistanceField3& arm_field() const { return fields->field_3d; }
};

/// A 12 x 10 x 1.6 m room section (no walls) with the given boxes.
inline std::unique_ptr<OptimizationWorld> MakeWorld(const std::vector<OrientedBox>& boxes) {
  auto world = std::make_unique<OptimizationWorld>();
  world->model = LoadTopayModel();
  world->kinematics = std::make_unique<Kinematics>(world->model);
  world->scene.boxes = boxes;
  world->scene.bounds_W_m =
      Eigen::AlignedBox3d(Eigen::Vector3d(-4.0, -5.0, 0.0), Eigen::Vector3d(8.0, 5.0, 1.6));
  world->scene.kind = "optimization test";
  SceneDistanceFieldsOptions options;
  options.resolution_m = 0.1;
  options.base_resolution_m = 0.05;
  options.base_band = FrontEndBaseBand(*world->kinematics, std::sqrt(3.0) * 0.1);
  world->fields =
      std::make_unique<SceneDistanceFields>(BuildSceneDistanceFields(world->scene, options));
  return world;
}

/// A comfortable arm configuration (elbow bent, tool forward and down), inside every limit.
inline Eigen::VectorXd ReadyJoints() {
  Eigen::VectorXd q(7);
  q << 0.0, 0.5, 0.0, -1.4, 0.0, 0.9, 0.0;
  return q;
}

inline WholeBodyState MakeState(double x, double y, double yaw, const Eigen::VectorXd& q) {
  WholeBodyState state;
  state.x_m = x;
  state.y_m = y;
  state.yaw_rad = yaw;
  state.q_rad = q;
  return state;
}

/// A path as DiscreteSE2 would make it for a straight base segment: turn in place to the
/// heading (if the base moves), drive in steps of at most 1 m, turn to the goal's yaw; the
/// joints move linearly over the whole path; yaw continuous. Times at 0.5 m/s and 0.5 rad/s.
inline WholeBodyPath StraightPath(const WholeBodyState& start, const WholeBodyState& goal) {
  std::vector<WholeBodyState> base;  // joints filled below
  base.push_back(start);
  const Eigen::Vector2d a(start.x_m, start.y_m), b(goal.x_m, goal.y_m);
  double yaw = start.yaw_rad;
  if ((b - a).norm() > 1e-9) {
    const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
    yaw += WrapAngle(heading - yaw);
    base.push_back(MakeState(a.x(), a.y(), yaw, start.q_rad));
    const int steps = static_cast<int>(std::ceil((b - a).norm() / 1.0));
    for (int i = 1; i <= steps; ++i) {
      const Eigen::Vector2d p = a + (b - a) * i / steps;
      base.push_back(MakeState(p.x(), p.y(), yaw, start.q_rad));
    }
  }
  yaw += WrapAngle(goal.yaw_rad - yaw);
  base.push_back(MakeState(b.x(), b.y(), yaw, start.q_rad));
  WholeBodyPath path;
  double t = 0.0;
  const int n = static_cast<int>(base.size());
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      const double d = std::hypot(base[i].x_m - base[i - 1].x_m, base[i].y_m - base[i - 1].y_m);
      const double turn = std::abs(base[i].yaw_rad - base[i - 1].yaw_rad);
      t += std::max({d / 0.5, turn / 0.5, 0.05});
    }
    const double f = n > 1 ? static_cast<double>(i) / (n - 1) : 1.0;
    base[i].q_rad = (1.0 - f) * start.q_rad + f * goal.q_rad;
    path.states.push_back(base[i]);
    path.times_s.push_back(t);
  }
  return path;
}

/// Central difference of f with respect to x(i), x restored afterwards.
inline double CentralDifference(const std::function<double(const Eigen::VectorXd&)>& f,
                                Eigen::VectorXd x, int i, double step) {
  const double original = x(i);
  x(i) = original + step;
  const double plus = f(x);
  x(i) = original - step;
  const double minus = f(x);
  return (plus - minus) / (2.0 * step);
}

/// Worst findings of CheckTrajectoryExactly.
struct ExactCheck {
  double min_obstacle_clearance_m = 1e9;  ///< Base and spheres vs the boxes (exact).
  double min_self_clearance_m = 1e9;      ///< Pairs and chassis.
  double max_rate_ratio = 0.0;            ///< Largest value / limit over every rate limit.
  double max_joint_excess_rad = -1e9;     ///< Largest q beyond a limit (<= 0: inside).
  double ee_position_error_m = 0.0;
  double ee_angle_error_rad = 0.0;
  std::string worst_rate;                 ///< Which rate limit attained max_rate_ratio.

  bool Passes(double rate_tolerance = 0.01) const {
    return min_obstacle_clearance_m > 0.0 && min_self_clearance_m > 0.0 &&
           max_rate_ratio <= 1.0 + rate_tolerance && max_joint_excess_rad <= 1e-9 &&
           ee_position_error_m <= 0.01 && ee_angle_error_rad <= 0.02;
  }
};

/// Samples the trajectory every 10 ms (and at its end): exact clearance against the scene's
/// boxes (SceneClearanceChecker, no field), self clearance, every rate limit (coupled
/// v-omega included), joint limits, and the end-effector pose at the end against X_WE_goal.
inline ExactCheck CheckTrajectoryExactly(const ArcYawTrajectory& trajectory,
                                         const OptimizationWorld& world,
                                         const BaseLimits& limits,
                                         const Eigen::Isometry3d& X_WE_goal) {
  ExactCheck check;
  const SceneClearanceChecker checker(*world.kinematics, world.scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  TrajectorySample point = trajectory.MakePoint();
  const JointLimits& joints = world.model.joint_limits;
  const auto rate = [&](double ratio, const std::string& what) {
    if (ratio > check.max_rate_ratio) {
      check.max_rate_ratio = ratio;
      check.worst_rate = what;
    }
  };
  const double duration = trajectory.duration_s();
  const int steps = static_cast<int>(std::ceil(duration / 0.01));
  for (int i = 0; i <= steps; ++i) {
    const double t = std::min(i * 0.01, duration);
    trajectory.Evaluate(t, &point);
    const SceneClearance clearance = checker.Compute(point.state, &workspace);
    check.min_obstacle_clearance_m =
        std::min({check.min_obstacle_clearance_m, clearance.base_m, clearance.spheres_m});
    check.min_self_clearance_m =
        std::min({check.min_self_clearance_m, clearance.self_m, clearance.chassis_m});
    const double w = point.omega_radps / limits.omega_max_radps;
    const double v = point.v_mps / limits.v_max_mps;
    rate(std::max(std::abs(w + v), std::abs(w - v)), "v-omega");
    rate(std::abs(point.a_mps2) / limits.a_max_mps2, "a");
    rate(std::abs(point.beta_radps2) / limits.beta_max_radps2, "beta");
    for (int k = 0; k < world.model.num_joints(); ++k) {
      rate(std::abs(point.qd_radps(k)) / joints.qd_max_radps(k), "qd" + std::to_string(k + 1));
      rate(std::abs(point.qdd_radps2(k)) / joints.qdd_max_radps2(k),
           "qdd" + std::to_string(k + 1));
      check.max_joint_excess_rad =
          std::max({check.max_joint_excess_rad, point.state.q_rad(k) - joints.q_max_rad(k),
                    joints.q_min_rad(k) - point.state.q_rad(k)});
    }
  }
  trajectory.Evaluate(duration, &point);
  const Eigen::Isometry3d X_WE = world.kinematics->EndEffectorPose(point.state);
  check.ee_position_error_m = (X_WE.translation() - X_WE_goal.translation()).norm();
  check.ee_angle_error_rad =
      Eigen::AngleAxisd(X_WE_goal.linear().transpose() * X_WE.linear()).angle();
  return check;
}

}  // namespace topay::testing
