#include "procs/mapper/mapper_options.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::mapper {
namespace {

double Probability(double log_odds) { return 1.0 / (1.0 + std::exp(-log_odds)); }

void ReadVector3(YamlSection* s, const char* key, Eigen::Vector3d* value) {
  std::vector<double> v{value->x(), value->y(), value->z()};
  s->Read(key, &v);
  if (v.size() != 3) throw ConfigError(s->source(), s->FieldPath(key), "expected [x, y, z]");
  *value = Eigen::Vector3d(v[0], v[1], v[2]);
}

void ReadFloat(YamlSection* s, const char* key, float* value) {
  double v = *value;
  s->Read(key, &v);
  *value = static_cast<float>(v);
}

void ReadMap(YamlSection s, OccupancyMapOptions* o) {
  Eigen::Vector3d lo = o->bounds_W_m.min(), hi = o->bounds_W_m.max();
  ReadVector3(&s, "bounds_min_m", &lo);
  ReadVector3(&s, "bounds_max_m", &hi);
  o->bounds_W_m = Eigen::AlignedBox3d(lo, hi);
  s.Read("resolution_m", &o->resolution_m);
  ReadFloat(&s, "log_odds_hit", &o->log_odds_hit);
  ReadFloat(&s, "log_odds_miss", &o->log_odds_miss);
  ReadFloat(&s, "log_odds_min", &o->log_odds_min);
  ReadFloat(&s, "log_odds_max", &o->log_odds_max);
  ReadFloat(&s, "occupied_threshold_log_odds", &o->occupied_threshold_log_odds);
  s.Read("max_free_ray_length_m", &o->max_free_ray_length_m);
  s.Read("max_hit_range_m", &o->max_hit_range_m);
  s.Finish();
}

void ReadPublish(YamlSection s, MapPublishOptions* o) {
  s.Read("snapshot_period_s", &o->snapshot_period_s);
  s.Read("max_silence_s", &o->max_silence_s);
  s.Read("compress", &o->codec.compress);
  s.Read("zlib_level", &o->codec.zlib_level);
  s.Finish();
}

}  // namespace

MapperOptions LoadMapperOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  MapperOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  ReadMap(top.Section("map"), &o.map);
  if (const YAML::Node filter = top.Raw("filter"); filter) o.filter = LoadScanFilterOptions(filter, path, "filter");
  YamlSection history = top.Section("robot_state");
  history.Read("horizon_s", &o.robot_state.horizon_s);
  history.Read("max_gap_s", &o.robot_state.max_gap_s);
  history.Finish();
  YamlSection octomap = top.Section("octomap");
  octomap.Read("enabled", &o.octomap.enabled);
  octomap.Read("every_n_scans", &o.octomap.every_n_scans);
  octomap.Finish();
  ReadPublish(top.Section("publish"), &o.publish);
  top.Read("save", &o.save_path);
  top.Read("prior", &o.prior_path);
  top.Read("checkpoint", &o.checkpoint_path);
  o.prior_path = ResolveBeside(o.prior_path, path);
  top.Finish();
  CheckMapperOptions(o);
  return o;
}

void CheckMapperOptions(const MapperOptions& o) {
  try {
    ValidateOccupancyMapOptions(o.map);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(o.source, "map", e.what());
  }
  CheckScanFilterOptions(o.filter);
  auto require = [&o](bool ok, const char* key, const char* what) {
    if (!ok) throw ConfigError(o.source, key, what);
  };
  require(std::isfinite(o.robot_state.horizon_s) && o.robot_state.horizon_s > 0.0, "robot_state.horizon_s",
          "expected a finite time > 0");
  require(std::isfinite(o.robot_state.max_gap_s) && o.robot_state.max_gap_s > 0.0, "robot_state.max_gap_s",
          "expected a finite time > 0");
  require(o.octomap.every_n_scans >= 1, "octomap.every_n_scans", "expected an integer >= 1");
  require(std::isfinite(o.publish.snapshot_period_s) && o.publish.snapshot_period_s > 0.0,
          "publish.snapshot_period_s", "expected a finite period > 0");
  require(std::isfinite(o.publish.max_silence_s) && o.publish.max_silence_s > 0.0 &&
              o.publish.max_silence_s <= 0.5,
          "publish.max_silence_s", "expected a period in (0, 0.5] s (MAP_UPDATE goes out at >= 2 Hz)");
  require(o.publish.codec.zlib_level >= 0 && o.publish.codec.zlib_level <= 9, "publish.zlib_level",
          "expected 0 .. 9");
  try {
    CheckOctomapMirrorOptions(MirrorOptionsOf(o));
  } catch (const std::invalid_argument& e) {
    throw ConfigError(o.source, "map", std::string("as OctoMap options: ") + e.what());
  }
}

OctomapMirrorOptions MirrorOptionsOf(const MapperOptions& o) {
  OctomapMirrorOptions m;
  m.resolution_m = o.map.resolution_m;
  m.bounds_W_m = o.map.bounds_W_m;
  m.prob_hit = Probability(o.map.log_odds_hit);
  m.prob_miss = Probability(o.map.log_odds_miss);
  m.clamping_min = Probability(o.map.log_odds_min);
  m.clamping_max = Probability(o.map.log_odds_max);
  m.occupancy_threshold = Probability(o.map.occupied_threshold_log_odds);
  m.max_range_m = o.map.max_free_ray_length_m;
  return m;
}

}  // namespace topay::mapper
