#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <yaml-cpp/yaml.h>

namespace topay::sim {

/// Where the sensor frame S sits on the robot: rigidly fixed to the link `parent_link` at
/// X_PS = Trans(xyz) * Rz(yaw) * Ry(pitch) * Rx(roll) (URDF rpy convention). S: x forward,
/// z up along the sensor's spin axis (the Livox convention).
struct LidarMount {
  std::string parent_link = "base_link";
  /// Default: on the chassis top near the front edge, optical centre 6.5 cm above the
  /// chassis top (z = 0.155 m) as a Mid-360 standing on it.
  Eigen::Vector3d xyz_m{0.30, 0.0, 0.22};
  Eigen::Vector3d rpy_rad = Eigen::Vector3d::Zero();

  /// X_PS from xyz and rpy.
  Eigen::Isometry3d X_PS() const;
};

/// A simulated Livox Mid-360-like 3D LiDAR (see lidar_scanner.h). Every default is the
/// Mid-360's data-sheet figure unless said otherwise. config/sim/lidar.yaml lists each key.
struct LidarOptions {
  LidarMount mount;
  double points_per_s = 200000.0;    ///< Point rate (Mid-360: 200,000 points/s).
  double scan_rate_hz = 10.0;        ///< Scans per second; points per scan = rate / scan rate.
  double elevation_min_rad = -7.0 * 3.14159265358979323846 / 180.0;   ///< -7 deg.
  double elevation_max_rad = 52.0 * 3.14159265358979323846 / 180.0;   ///< +52 deg.
  double range_min_m = 0.1;          ///< Blind zone: a first hit nearer gives no point.
  double range_max_m = 40.0;         ///< At 10 % reflectivity; farther: no point.
  double range_noise_sigma_m = 0.02; ///< Gaussian range noise, 1 sigma (data sheet: <= 2 cm).
  /// The floor z = 0 returns points as a real floor would. Off by default: the scenes have no
  /// floor box and the mapper is given box returns only; turn on to test ground filtering.
  bool ground_plane = false;
  /// Side of the square cells of the ray-casting grid over the boxes (m, > 0).
  double grid_cell_m = 0.5;

  /// Where the options came from, for errors raised later (e.g. an unknown mount link):
  /// the file and the dotted key prefix of the section ("" at the top level).
  std::string source = "(built-in defaults)";
  std::string key_prefix;

  /// Points in one scan: round(points_per_s / scan_rate_hz).
  int PointsPerScan() const;
  double ScanPeriodS() const { return 1.0 / scan_rate_hz; }
};

/// Reads LidarOptions from a YAML map (every key optional, defaults above) and checks them.
/// `source` names the file in errors, `key_prefix` is the dotted path of the map inside it
/// (e.g. "lidar" when it is a section of config/sim/sim.yaml). Throws topay::ConfigError
/// naming file and key for an unknown key, a wrong type, a non-finite number, an inverted or
/// non-positive range, an empty elevation interval or one outside [-90, 90] deg, a rate <= 0,
/// fewer than 1 or more than 10,000,000 points per scan, a negative noise or a cell <= 0.
LidarOptions LoadLidarOptions(const YAML::Node& node, const std::string& source,
                              const std::string& key_prefix = "");

/// The whole file is the LiDAR map (as config/sim/lidar.yaml), or, with `section` given, the
/// map under that top-level key. Throws ConfigError for a missing, unreadable or malformed file.
LidarOptions LoadLidarOptionsFile(const std::string& path, const std::string& section = "");

/// Throws ConfigError (naming options.source and key) if the options are inconsistent (as
/// listed for LoadLidarOptions). Called by the loader and by LidarScanner's constructor.
void CheckLidarOptions(const LidarOptions& options);

}  // namespace topay::sim
