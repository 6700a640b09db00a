#include "sim/lidar/lidar_options.h"

#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/yaml_section.h"

namespace topay::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;

std::string Key(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

// A list of exactly three finite numbers, e.g. xyz: [0.3, 0, 0.22].
Eigen::Vector3d ReadVector3(const YAML::Node& node, const std::string& source,
                            const std::string& key) {
  if (!node.IsSequence() || node.size() != 3) {
    throw ConfigError(source, key, "expected a list of 3 numbers");
  }
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    double value = 0.0;
    if (!node[i].IsScalar() || !YAML::convert<double>::decode(node[i], value) ||
        !std::isfinite(value)) {
      throw ConfigError(source, key + "[" + std::to_string(i) + "]",
                        "expected a finite number, got '" +
                            (node[i].IsScalar() ? node[i].Scalar() : std::string("a list")) + "'");
    }
    v(i) = value;
  }
  return v;
}

// mount: {parent_link, xyz, rpy}; YamlSection reads scalars only, so the two lists are read
// here, with the same unknown-key check.
void ReadMount(const YAML::Node& node, const std::string& source, const std::string& path,
               LidarMount* mount) {
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap()) throw ConfigError(source, path, "expected a map of fields");
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>("?");
    if (key == "parent_link") {
      if (!entry.second.IsScalar() || entry.second.Scalar().empty()) {
        throw ConfigError(source, Key(path, key), "expected a link name");
      }
      mount->parent_link = entry.second.Scalar();
    } else if (key == "xyz") {
      mount->xyz_m = ReadVector3(entry.second, source, Key(path, key));
    } else if (key == "rpy") {
      mount->rpy_rad = ReadVector3(entry.second, source, Key(path, key));
    } else {
      throw ConfigError(source, Key(path, key), "unknown field (misspelt?)");
    }
  }
}

void Require(bool ok, const LidarOptions& o, const std::string& key, const std::string& what) {
  if (!ok) throw ConfigError(o.source, Key(o.key_prefix, key), what);
}

}  // namespace

Eigen::Isometry3d LidarMount::X_PS() const {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = xyz_m;
  // URDF rpy: fixed-axis roll (x), pitch (y), yaw (z), i.e. R = Rz(yaw) Ry(pitch) Rx(roll).
  X.linear() = (Eigen::AngleAxisd(rpy_rad.z(), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(rpy_rad.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(rpy_rad.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return X;
}

int LidarOptions::PointsPerScan() const {
  return static_cast<int>(std::lround(points_per_s / scan_rate_hz));
}

void CheckLidarOptions(const LidarOptions& o) {
  Require(std::isfinite(o.points_per_s) && o.points_per_s > 0.0, o, "points_per_s",
          "expected a finite rate > 0");
  Require(std::isfinite(o.scan_rate_hz) && o.scan_rate_hz > 0.0, o, "scan_rate_hz",
          "expected a finite rate > 0");
  const double points = o.points_per_s / o.scan_rate_hz;
  Require(points >= 0.5 && points <= 1e7, o, "points_per_s",
          "points per scan (points_per_s / scan_rate_hz = " + std::to_string(points) +
              ") must lie in [1, 10000000]");
  Require(std::isfinite(o.elevation_min_rad) && o.elevation_min_rad >= -kPi / 2, o,
          "elevation_min_deg", "expected a finite angle >= -90 deg");
  Require(std::isfinite(o.elevation_max_rad) && o.elevation_max_rad <= kPi / 2, o,
          "elevation_max_deg", "expected a finite angle <= 90 deg");
  Require(o.elevation_min_rad < o.elevation_max_rad, o, "elevation_max_deg",
          "must exceed elevation_min_deg (" + std::to_string(o.elevation_min_rad * kDegPerRad) +
              " deg)");
  Require(std::isfinite(o.range_min_m) && o.range_min_m >= 0.0, o, "range_min_m",
          "expected a finite range >= 0");
  Require(std::isfinite(o.range_max_m) && o.range_max_m > o.range_min_m, o, "range_max_m",
          "expected a finite range > range_min_m (" + std::to_string(o.range_min_m) + " m)");
  Require(std::isfinite(o.range_noise_sigma_m) && o.range_noise_sigma_m >= 0.0, o,
          "range_noise_sigma_m", "expected a finite sigma >= 0");
  Require(std::isfinite(o.grid_cell_m) && o.grid_cell_m > 0.0, o, "grid_cell_m",
          "expected a finite cell size > 0");
  Require(!o.mount.parent_link.empty(), o, "mount.parent_link", "expected a link name");
  Require(o.mount.xyz_m.allFinite(), o, "mount.xyz", "expected finite numbers");
  Require(o.mount.rpy_rad.allFinite(), o, "mount.rpy", "expected finite numbers");
}

LidarOptions LoadLidarOptions(const YAML::Node& given, const std::string& source,
                              const std::string& key_prefix) {
  // An absent section (also an invalid node from a lookup of a missing key): the defaults.
  const YAML::Node node = given.IsDefined() ? given : YAML::Node();
  LidarOptions o;
  o.source = source;
  o.key_prefix = key_prefix;
  YamlSection section(node, source, key_prefix);
  section.Read("points_per_s", &o.points_per_s);
  section.Read("scan_rate_hz", &o.scan_rate_hz);
  // Angles in the file are in degrees (data-sheet units), in the struct in radians.
  double elevation_min_deg = o.elevation_min_rad * kDegPerRad;
  double elevation_max_deg = o.elevation_max_rad * kDegPerRad;
  section.Read("elevation_min_deg", &elevation_min_deg);
  section.Read("elevation_max_deg", &elevation_max_deg);
  o.elevation_min_rad = elevation_min_deg / kDegPerRad;
  o.elevation_max_rad = elevation_max_deg / kDegPerRad;
  section.Read("range_min_m", &o.range_min_m);
  section.Read("range_max_m", &o.range_max_m);
  section.Read("range_noise_sigma_m", &o.range_noise_sigma_m);
  section.Read("ground_plane", &o.ground_plane);
  section.Read("grid_cell_m", &o.grid_cell_m);
  // The mount is read by hand (lists); mark it used through an (ignored) sub-section read.
  const YAML::Node mount = node.IsMap() ? node["mount"] : YAML::Node();
  (void)section.Section("mount");  // marks the key as known; its content is checked below
  ReadMount(mount, source, Key(key_prefix, "mount"), &o.mount);
  section.Finish();
  CheckLidarOptions(o);
  return o;
}

LidarOptions LoadLidarOptionsFile(const std::string& path, const std::string& section) {
  const std::string text = ReadBoundedTextFile(path, kMaxConfigFileBytes, "LiDAR YAML");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path, "", std::string("malformed YAML: ") + e.what());
  }
  if (section.empty()) return LoadLidarOptions(root, path);
  if (!root.IsMap()) throw ConfigError(path, "(top level)", "expected a map of sections");
  const YAML::Node& const_root = root;  // const lookup: no node is inserted
  return LoadLidarOptions(const_root[section], path, section);
}

}  // namespace topay::sim
