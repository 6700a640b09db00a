#include "sim/lidar/lidar_scanner.h"

#include <algorithm>

#include "core/common/error.h"
#include "sim/lidar/ray_primitives.h"

namespace topay::sim {
namespace {

// The options checked before any member is built from them.
const LidarOptions& Checked(const LidarOptions& options) {
  CheckLidarOptions(options);
  return options;
}

int MountLink(const LidarOptions& options, const RobotModel& model) {
  const int link = model.FindLink(options.mount.parent_link);
  if (link < 0) {
    const std::string key =
        options.key_prefix.empty() ? "mount.parent_link" : options.key_prefix + ".mount.parent_link";
    throw ConfigError(options.source, key,
                      "no link '" + options.mount.parent_link + "' in robot '" + model.name + "'");
  }
  return link;
}

}  // namespace

LidarScanner::LidarScanner(const LidarOptions& options, const Kinematics& kinematics,
                           std::uint64_t seed)
    : options_(Checked(options)),
      kinematics_(kinematics),
      mount_link_(MountLink(options, kinematics.model())),
      X_PS_(options.mount.X_PS()),
      points_per_scan_(options.PointsPerScan()),
      pattern_(options.elevation_min_rad, options.elevation_max_rad),
      grid_(options.grid_cell_m),
      cache_(kinematics.MakeCache()),
      rng_(seed) {}

void LidarScanner::SetWorld(const std::vector<OrientedBox>& boxes) { grid_.Build(boxes); }

Eigen::Isometry3d LidarScanner::SensorPose(const WholeBodyState& state) {
  kinematics_.Update(state, &cache_);
  return cache_.X_WL[mount_link_] * X_PS_;
}

LidarScanner::Return LidarScanner::CastRay(const Eigen::Vector3d& p_WO,
                                           const Eigen::Vector3d& d_W) {
  // The robot first: its entry bounds the grid's walk (a box at the same range wins).
  Return hit{body_.Entry(d_W), kTargetSelf};
  const BoxRayGrid::Hit box =
      grid_.FirstHit(p_WO, d_W, std::min(hit.range_m, options_.range_max_m));
  if (box.box >= 0) hit = {box.t_m, box.box};
  if (options_.ground_plane) {
    const double t_ground = RayGroundEntry(p_WO, d_W);
    if (t_ground < hit.range_m) hit = {t_ground, kTargetGround};
  }
  return hit;
}

double LidarScanner::MeasuredRange(double range_m) {
  if (options_.range_noise_sigma_m == 0.0) return range_m;
  // Gaussian range noise; a range cannot be negative.
  return std::max(0.0, range_m + options_.range_noise_sigma_m * rng_.Normal());
}

LidarScan LidarScanner::Scan(const WholeBodyState& state, double t_s) {
  LidarScan scan;
  scan.t_s = t_s;
  scan.X_WS = SensorPose(state);  // also updates cache_ (body spheres) for this state
  scan.p_SP.reserve(points_per_scan_);
  scan.t_offset_s.reserve(points_per_scan_);
  scan.target.reserve(points_per_scan_);
  const Eigen::Vector3d p_WO = scan.X_WS.translation();
  const Eigen::Matrix3d R_WS = scan.X_WS.linear();
  body_.Update(kinematics_.model(), cache_, p_WO);
  const double dt_s = options_.ScanPeriodS() / points_per_scan_;
  const std::uint64_t first_ray = scan_index_ * static_cast<std::uint64_t>(points_per_scan_);
  for (int k = 0; k < points_per_scan_; ++k) {
    const Eigen::Vector3d d_S = pattern_.Direction(first_ray + k);
    const Return hit = CastRay(p_WO, R_WS * d_S);
    // No return: nothing within range_max_m, or the first hit in the blind zone.
    if (!(hit.range_m <= options_.range_max_m) || hit.range_m < options_.range_min_m) continue;
    scan.p_SP.push_back((MeasuredRange(hit.range_m) * d_S).cast<float>());
    scan.t_offset_s.push_back(static_cast<float>(k * dt_s));
    scan.target.push_back(hit.target);
    if (hit.target == kTargetSelf) ++scan.self_hits;
  }
  scan.rays = points_per_scan_;
  ++scan_index_;
  return scan;
}

}  // namespace topay::sim
