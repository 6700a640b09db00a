#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/arc_yaw_position_integrator.h"
#include "core/trajectory/minco_s3.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// The whole-body trajectory of TopAY (paper Sec. III-B): a MINCO s = 3 trajectory in
/// D = 2 + N dimensions ordered [s, yaw, q1..qN] (MincoS3), and the base position (x, y)
/// integrated from s' (cos yaw, sin yaw) by Simpson's rule (ArcYawPositionIntegrator, eqs. (1)-(2)).
///
/// Boundary data follow the paper's conditions (15)-(20): head = [s, yaw, q] position,
/// velocity, acceleration at t = 0 (s(0) = 0 by convention, but any value works), tail = the
/// same at the end (tail column 0 = the free end values e = (s_f, yaw_f, q_f)).
///
/// Construction allocates; Update, Evaluate, EndEffectorPose and PropagateGradient do not.
class ArcYawTrajectory {
 public:
  struct Options {
    ArcYawPositionIntegrator::Options integrator;  ///< K panels per piece (default 12).
  };

  ArcYawTrajectory(int num_joints, int num_pieces, const Options& options);

  int num_joints() const { return num_joints_; }
  int num_dims() const { return num_joints_ + 2; }
  int num_pieces() const { return minco_.num_pieces(); }

  /// Solves MINCO for the boundary data and integrates x, y from p0_W = (x0, y0). Shapes as
  /// MincoS3::Solve with D = 2 + N. Throws std::invalid_argument for bad input.
  void Update(const Eigen::Vector2d& p0_W, const Eigen::Ref<const Eigen::MatrixXd>& head,
              const Eigen::Ref<const Eigen::MatrixXd>& tail,
              const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
              const Eigen::Ref<const Eigen::VectorXd>& durations_s);

  const MincoS3& minco() const { return minco_; }
  const ArcYawPositionIntegrator& positions() const { return positions_; }
  double duration_s() const { return minco_.total_duration(); }

  /// A sample sized for this trajectory, jerk included (allocates once; reuse it).
  TrajectorySample MakePoint() const;

  /// Every quantity of the trajectory at t_s (clamped to [0, duration]): pose (x, y between
  /// samples by one Simpson panel from the previous sample, see ArcYawPositionIntegrator),
  /// s, v = s', omega = yaw', a = s'', beta = yaw'', jerk, q, q', q''. Throws std::invalid_argument for a NaN time, a point
  /// of the wrong size or before Update.
  void Evaluate(double t_s, TrajectorySample* point) const;

  /// Evaluates *point at t_s, updates *cache for its whole-body state and returns X_WE, the
  /// end-effector pose in the world.
  const Eigen::Isometry3d& EndEffectorPose(double t_s, const Kinematics& kinematics,
                                           KinematicsCache* cache, TrajectorySample* point) const;

  /// Gradient of a cost C(c, T, p_samples) with respect to MINCO's parameters. dC_dp: 2 x
  /// (M K + 1), dC/d(x, y) of every sample (ArcYawPositionIntegrator::positions). On input
  /// dC_dc (6M x D) and dC_dT (M) hold C's own partial derivatives; the samples' contributions
  /// are added to them, then everything is carried through MINCO's adjoint into *gradient
  /// (sized by MincoGradient::Resize(D, M)). Returns dC/dp0.
  Eigen::Vector2d PropagateGradient(const Eigen::Ref<const Eigen::Matrix2Xd>& dC_dp,
                                    Eigen::Ref<Eigen::MatrixXd> dC_dc,
                                    Eigen::Ref<Eigen::VectorXd> dC_dT, MincoGradient* gradient);

 private:
  int num_joints_;
  MincoS3 minco_;
  ArcYawPositionIntegrator positions_;
};

}  // namespace topay
