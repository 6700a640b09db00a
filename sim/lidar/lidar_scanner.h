#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/random.h"
#include "core/geometry/oriented_box.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "sim/lidar/box_ray_grid.h"
#include "sim/lidar/lidar_options.h"
#include "sim/lidar/robot_body_rays.h"
#include "sim/lidar/scan_pattern.h"

namespace topay::sim {

/// What each point hit (LidarScan::target): a box index >= 0, or one of these.
inline constexpr std::int32_t kTargetGround = -1;  ///< The floor (LidarOptions::ground_plane).
inline constexpr std::int32_t kTargetSelf = -2;    ///< The robot's own base cylinder or arm.

/// One full scan. The points are in the sensor frame S at the capture pose X_WS.
struct LidarScan {
  double t_s = 0.0;                          ///< Capture time (plant time), s: the scan's start.
  Eigen::Isometry3d X_WS = Eigen::Isometry3d::Identity();  ///< Sensor pose at capture time.
  std::vector<Eigen::Vector3f> p_SP;         ///< Points in S, m.
  std::vector<float> t_offset_s;             ///< Per point: firing time after t_s, in [0, T).
  std::vector<std::int32_t> target;          ///< Per point: box index, kTargetGround or kTargetSelf.
  int self_hits = 0;                         ///< Points on the robot itself.
  int rays = 0;                              ///< Rays cast (points + misses).
};

/// A simulated Livox Mid-360-like LiDAR on the robot.
///
/// Each scan fires LidarOptions::PointsPerScan() rays in the non-repetitive pattern of
/// ScanPattern (scan s uses rays s N .. s N + N - 1, s counting this scanner's scans from 0),
/// ray k at time offset k T / N within the scan period T = 1 / scan_rate_hz.
///
/// Poses: the message carries one sensor pose per scan, so every ray is cast from the pose at
/// the capture time t_s (the state given to Scan): X_WS = X_WL(parent link) * X_PS. The
/// motion during the scan period (10 cm at 1 m/s over 100 ms) is not applied to the rays;
/// the per-point time offsets are reported for a consumer that wants to model it.
///
/// Each ray returns its nearest hit among the world's boxes (BoxRayGrid), the floor if
/// enabled, and the robot's own body at that state: the base cylinder (RobotModel::
/// base_cylinder about the base axis, ground to chassis top) and every arm collision sphere
/// (Kinematics sphere centres). A hit on the body is a point like any other (a real sensor
/// sees its robot) and is counted in self_hits (ties at equal range: a box, then the body, then
/// the floor). A first hit nearer than range_min_m (blind
/// zone) or beyond range_max_m, or no hit, gives no point. The measured range is the exact
/// one plus Gaussian noise (sigma range_noise_sigma_m, drawn from a seeded topay::Rng, one
/// draw per returned point), clamped at 0; the point is d_S times that range.
///
/// The Kinematics must outlive the scanner. Scan is allocation-free after the first call
/// apart from the returned scan's vectors (reserved once per scan).
class LidarScanner {
 public:
  /// Throws ConfigError (naming options.source and the key) for inconsistent options or a
  /// mount link the robot model lacks.
  LidarScanner(const LidarOptions& options, const Kinematics& kinematics, std::uint64_t seed);

  /// Replaces the world's boxes and rebuilds the grid (boxes may appear and disappear at run
  /// time; the point targets index this vector).
  void SetWorld(const std::vector<OrientedBox>& boxes);

  /// One full scan from `state` at plant time t_s. Throws std::invalid_argument for a state
  /// of the wrong size or with a NaN (from Kinematics::Update).
  LidarScan Scan(const WholeBodyState& state, double t_s);

  /// The sensor pose for a state (no scan).
  Eigen::Isometry3d SensorPose(const WholeBodyState& state);

  const LidarOptions& options() const { return options_; }
  int points_per_scan() const { return points_per_scan_; }
  std::uint64_t scans_done() const { return scan_index_; }
  const BoxRayGrid& grid() const { return grid_; }

 private:
  struct Return {
    double range_m;       // exact range of the first hit; kNoHit if none
    std::int32_t target;  // box index, kTargetGround or kTargetSelf
  };
  // The first hit among the robot's body, the boxes (up to range_max_m) and the floor.
  Return CastRay(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W);
  // The exact range plus the Gaussian noise, clamped at 0.
  double MeasuredRange(double range_m);

  LidarOptions options_;
  const Kinematics& kinematics_;
  int mount_link_ = -1;
  Eigen::Isometry3d X_PS_ = Eigen::Isometry3d::Identity();
  int points_per_scan_ = 0;
  ScanPattern pattern_;
  BoxRayGrid grid_;
  KinematicsCache cache_;
  RobotBodyRays body_;
  Rng rng_;
  std::uint64_t scan_index_ = 0;
};

}  // namespace topay::sim
