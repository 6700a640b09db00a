#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Poses computed by Kinematics::Update for one whole-body state. Sized once by
/// Kinematics::MakeCache; Update then never allocates.
struct KinematicsCache {
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();  ///< Base frame in the world.
  std::vector<Eigen::Isometry3d> X_WL;                     ///< Every link, in model order.
  std::vector<Eigen::Vector3d> p_WS;                       ///< Every collision sphere centre.
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();  ///< End-effector frame.
};

/// Forward kinematics and analytic Jacobians of the whole body with respect to the flat state
/// z = [x, y, yaw, q1..qN] (see WholeBodyState).
///
/// The model must outlive this object.
class Kinematics {
 public:
  explicit Kinematics(const RobotModel& model);

  const RobotModel& model() const { return model_; }
  int num_joints() const { return model_.num_joints(); }
  /// Size of the flat state z: 3 + N.
  int num_states() const { return 3 + model_.num_joints(); }

  KinematicsCache MakeCache() const;

  /// Computes X_WB, every X_WL, every sphere centre p_WS and X_WE. Allocation-free.
  void Update(const WholeBodyState& state, KinematicsCache* cache) const;

  /// d p_WS / d z (3 x (3+N)) of sphere `sphere`, at the state of the last Update of `cache`.
  void SphereJacobian(const KinematicsCache& cache, int sphere,
                      Eigen::Ref<Eigen::MatrixXd> J_WS) const;

  /// Spatial Jacobian of the end effector (6 x (3+N)): rows 0-2 map z-dot to the angular
  /// velocity w_WE expressed in W, rows 3-5 to the translational velocity v_WE of E's origin
  /// expressed in W.
  void EndEffectorJacobian(const KinematicsCache& cache, Eigen::Ref<Eigen::MatrixXd> J_WE) const;

  /// Same form as EndEffectorJacobian, for the origin of an arbitrary link.
  void LinkJacobian(const KinematicsCache& cache, int link, Eigen::Ref<Eigen::MatrixXd> J_WL) const;

  /// gradient += J_WP^T * f_W, where J_WP (3 x (3+N)) is the translational Jacobian of the
  /// point p_WP rigidly attached to `link`: the gradient of f_W . p_WP with respect to z
  /// (f_W held fixed), without forming J_WP. Allocation-free; for distance and penalty
  /// gradients.
  void AddPointJacobianTransposeTimes(const KinematicsCache& cache, int link,
                                      const Eigen::Vector3d& p_WP, const Eigen::Vector3d& f_W,
                                      Eigen::Ref<Eigen::VectorXd> gradient) const;

  /// Convenience: X_WE for a state (allocates a cache; not for hot loops).
  /// All methods throw std::invalid_argument for a state of the wrong size, a NaN in it, an
  /// index out of range or a Jacobian buffer of the wrong shape.
  Eigen::Isometry3d EndEffectorPose(const WholeBodyState& state) const;

 private:
  const RobotModel& model_;
  /// Fills columns of a point Jacobian J (3 or 6 rows: [angular;] linear) for point p_WP
  /// fixed to `link`.
  void PointJacobian(const KinematicsCache& cache, int link, const Eigen::Vector3d& p_WP,
                     bool with_angular, Eigen::Ref<Eigen::MatrixXd> J) const;

  // For each link, the indices of the links on its path from the root (ancestors and itself)
  // whose joint is movable, so Jacobians visit only the joints that move it.
  std::vector<std::vector<int>> ancestor_links_with_joints_;
  // For each revolute link, R_PJ K and R_PJ K^2 (K: the cross-product matrix of the unit joint
  // axis), so that R_PC(q) = R_PJ R(q) = R_PJ + sin q R_PJ K + (1 - cos q) R_PJ K^2 (Rodrigues)
  // costs two scaled additions instead of an axis-angle conversion and a 3x3 product.
  std::vector<Eigen::Matrix3d> rotation_sin_terms_;
  std::vector<Eigen::Matrix3d> rotation_cos_terms_;
};

}  // namespace topay
