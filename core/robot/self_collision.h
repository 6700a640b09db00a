#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"

namespace topay {

/// For each link, the index of the rigid body it belongs to: links joined to their parent by
/// a fixed joint share the parent's body; a movable joint starts a new body (whose index is
/// that link's own).
std::vector<int> RigidBodiesOfLinks(const RobotModel& model);

/// The sphere pairs worth checking for self-collision (the authors' code): spheres i < j that
/// lie on different rigid bodies, on bodies not directly joined by one movable joint, and that
/// do not overlap at q = 0 (base at the origin). Sorted by (i, j).
std::vector<std::pair<int, int>> FindSelfCollisionPairs(const RobotModel& model);

/// Self-collision distances of the model's self_collision_pairs and the arm-above-chassis
/// margins, with their gradients with respect to z = [x, y, yaw, q]. Evaluates from a
/// KinematicsCache updated by the same Kinematics; allocation-free, into caller buffers.
/// The Kinematics (and its model) must outlive this object.
class SelfCollision {
 public:
  explicit SelfCollision(const Kinematics& kinematics);

  int num_pairs() const { return static_cast<int>(pairs().size()); }
  int num_spheres() const { return static_cast<int>(model().spheres.size()); }
  const std::vector<std::pair<int, int>>& pairs() const { return model().self_collision_pairs; }

  /// Signed distance of each pair k = (i, j): d_k = |p_i - p_j| - r_i - r_j (m); negative when
  /// the spheres overlap. `distances_m` has num_pairs() entries.
  /// If `gradients` is non-null it must be (3+N) x num_pairs(); column k gets grad_z d_k
  /// = (J_i - J_j)^T n, n = (p_i - p_j) / |p_i - p_j| (zero if the centres coincide).
  void Distances(const KinematicsCache& cache, Eigen::Ref<Eigen::VectorXd> distances_m,
                 Eigen::MatrixXd* gradients = nullptr) const;

  /// The smallest pair distance (m; +infinity if there are no pairs) and, if `gradient` is
  /// non-null (size 3+N), its gradient (zero if there are no pairs).
  double MinDistance(const KinematicsCache& cache, Eigen::VectorXd* gradient = nullptr) const;

  /// Margin of each sphere s above the chassis top: m_s = z_s - r_s - base_cylinder.height_m
  /// (m; negative when the sphere dips below the top). `margins_m` has num_spheres() entries;
  /// if `gradients` is non-null it must be (3+N) x num_spheres(); column s gets
  /// grad_z m_s = J_s^T e_z.
  void ChassisMargins(const KinematicsCache& cache, Eigen::Ref<Eigen::VectorXd> margins_m,
                      Eigen::MatrixXd* gradients = nullptr) const;

 private:
  const RobotModel& model() const { return kinematics_.model(); }
  double PairDistance(const KinematicsCache& cache, int k, Eigen::Vector3d* n_W) const;
  void AddPairGradient(const KinematicsCache& cache, int k, const Eigen::Vector3d& n_W,
                       Eigen::Ref<Eigen::VectorXd> gradient) const;

  const Kinematics& kinematics_;
};

}  // namespace topay
