#include "procs/mapper/scan_filter_options.h"

#include <cmath>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::mapper {
namespace {

std::string Key(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

void Require(bool ok, const ScanFilterOptions& o, const std::string& key,
             const std::string& what) {
  if (!ok) throw ConfigError(o.source, Key(o.key_prefix, key), what);
}

OutlierMethod ParseOutlierMethod(const std::string& name, const ScanFilterOptions& o) {
  for (OutlierMethod method :
       {OutlierMethod::kNone, OutlierMethod::kRadius, OutlierMethod::kStatistical}) {
    if (name == OutlierMethodName(method)) return method;
  }
  throw ConfigError(o.source, Key(o.key_prefix, "outlier_method"),
                    "expected none, radius or statistical, got '" + name + "'");
}

// Fewer than 2^31 leaves in a cube of side 2 range_max (PCL's 32-bit leaf index).
bool LeafIndexFits(double leaf_m, double range_max_m) {
  const double per_axis = 2.0 * range_max_m / leaf_m + 1.0;
  return per_axis * per_axis * per_axis < 2147483647.0;
}

}  // namespace

const char* OutlierMethodName(OutlierMethod method) {
  switch (method) {
    case OutlierMethod::kNone: return "none";
    case OutlierMethod::kRadius: return "radius";
    case OutlierMethod::kStatistical: return "statistical";
  }
  return "?";
}

void CheckScanFilterOptions(const ScanFilterOptions& o) {
  Require(o.input.max_points >= 1, o, "input.max_points", "expected an integer >= 1");
  Require(o.input.quaternion_norm_tolerance > 0.0 && o.input.quaternion_norm_tolerance < 1.0, o,
          "input.quaternion_norm_tolerance", "expected a number in (0, 1)");
  Require(std::isfinite(o.range_min_m) && o.range_min_m >= 0.0, o, "range_min_m",
          "expected a finite range >= 0");
  Require(std::isfinite(o.range_max_m) && o.range_max_m > o.range_min_m, o, "range_max_m",
          "expected a finite range > range_min_m (" + std::to_string(o.range_min_m) + " m)");
  Require(std::isfinite(o.ground_max_z_m), o, "ground_max_z_m", "expected a finite height");
  Require(std::isfinite(o.self_margin_m) && o.self_margin_m >= 0.0, o, "self_margin_m",
          "expected a finite margin >= 0");
  Require(std::isfinite(o.no_state_radius_m) && o.no_state_radius_m >= 0.0, o, "no_state_radius_m",
          "expected a finite value >= 0");
  Require(std::isfinite(o.voxel_leaf_m) && o.voxel_leaf_m >= 0.0, o, "voxel_leaf_m",
          "expected a finite leaf size >= 0 (0: off)");
  Require(o.voxel_leaf_m == 0.0 || LeafIndexFits(o.voxel_leaf_m, o.range_max_m), o,
          "voxel_leaf_m",
          std::to_string(o.voxel_leaf_m) + " m: too fine for range_max_m (" +
              std::to_string(o.range_max_m) + " m): more than 2^31 leaves");
  Require(std::isfinite(o.outlier_radius_m) && o.outlier_radius_m > 0.0, o, "outlier_radius_m",
          "expected a finite radius > 0");
  Require(o.outlier_min_neighbors >= 1, o, "outlier_min_neighbors", "expected an integer >= 1");
  Require(o.outlier_mean_k >= 1, o, "outlier_mean_k", "expected an integer >= 1");
  Require(std::isfinite(o.outlier_stddev_mul) && o.outlier_stddev_mul > 0.0, o,
          "outlier_stddev_mul", "expected a finite number > 0");
}

ScanFilterOptions LoadScanFilterOptions(const YAML::Node& given, const std::string& source,
                                        const std::string& key_prefix) {
  // An absent section (also an invalid node from a lookup of a missing key): the defaults.
  const YAML::Node node = given.IsDefined() ? given : YAML::Node();
  ScanFilterOptions o;
  o.source = source;
  o.key_prefix = key_prefix;
  YamlSection section(node, source, key_prefix);
  YamlSection input = section.Section("input");
  input.Read("max_points", &o.input.max_points);
  input.Read("quaternion_norm_tolerance", &o.input.quaternion_norm_tolerance);
  input.Finish();
  section.Read("range_min_m", &o.range_min_m);
  section.Read("range_max_m", &o.range_max_m);
  section.Read("ground_max_z_m", &o.ground_max_z_m);
  section.Read("self_margin_m", &o.self_margin_m);
  section.Read("no_state_radius_m", &o.no_state_radius_m);
  section.Read("voxel_leaf_m", &o.voxel_leaf_m);
  std::string method = OutlierMethodName(o.outlier_method);
  section.Read("outlier_method", &method);
  o.outlier_method = ParseOutlierMethod(method, o);
  section.Read("outlier_radius_m", &o.outlier_radius_m);
  section.Read("outlier_min_neighbors", &o.outlier_min_neighbors);
  section.Read("outlier_mean_k", &o.outlier_mean_k);
  section.Read("outlier_stddev_mul", &o.outlier_stddev_mul);
  section.Finish();
  CheckScanFilterOptions(o);
  return o;
}

}  // namespace topay::mapper
