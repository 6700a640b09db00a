#include "procs/sim/sim_options.h"

#include <cmath>
#include <filesystem>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/yaml_section.h"

namespace topay::simproc {
namespace {

std::string Resolve(const std::string& path, const std::filesystem::path& folder) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (folder / path).lexically_normal().string();
}

void Positive(const YamlSection& s, const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) throw ConfigError(s.source(), s.FieldPath(key), "must be a finite number > 0");
}

void ReadFollowerOptions(YamlSection& s, TrajectoryFollowerOptions* o) {
  s.Read("max_start_offset_m", &o->max_start_offset_m);
  Positive(s, "max_start_offset_m", o->max_start_offset_m);
  s.Read("max_start_offset_rad", &o->max_start_offset_rad);
  Positive(s, "max_start_offset_rad", o->max_start_offset_rad);
  int& panels = o->rebuild.trajectory.integrator.panels_per_piece;
  s.Read("panels_per_piece", &panels);
  if (panels < 1) throw ConfigError(s.source(), s.FieldPath("panels_per_piece"), "must be >= 1");
  s.Read("coefficient_tolerance", &o->rebuild.coefficient_tolerance);
  Positive(s, "coefficient_tolerance", o->rebuild.coefficient_tolerance);
  s.Read("yaw0_tolerance_rad", &o->rebuild.yaw0_tolerance_rad);
  Positive(s, "yaw0_tolerance_rad", o->rebuild.yaw0_tolerance_rad);
}

}  // namespace

SimOptions LoadSimOptions(const std::string& path) {
  const std::string text = ReadBoundedTextFile(path, kMaxConfigFileBytes, "simulator YAML");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path, "", std::string("malformed YAML: ") + e.what());
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  SimOptions o;
  o.source = path;
  YamlSection top(root, path);
  top.Read("seed", &o.seed);
  double start_utime = 0.0;
  top.Read("start_utime", &start_utime);
  // Below 2^63: a larger value (or .inf) does not fit the int64 it is converted to.
  constexpr double kMaxUtime = 9223372036854775808.0;  // 2^63
  if (!(start_utime >= 0.0 && start_utime < kMaxUtime) || start_utime != std::floor(start_utime)) {
    throw ConfigError(path, "start_utime", "must be a whole number of microseconds >= 0 (and below 2^63)");
  }
  o.start_utime = static_cast<std::int64_t>(start_utime);
  top.Read("rate", &o.rate);
  if (!(o.rate >= 0.0) || !std::isfinite(o.rate)) throw ConfigError(path, "rate", "must be >= 0 (0: as fast as possible)");
  top.Read("max_catch_up_steps", &o.max_catch_up_steps);
  if (o.max_catch_up_steps < 1) throw ConfigError(path, "max_catch_up_steps", "must be >= 1");
  {
    YamlSection s = top.Section("robot");
    s.Read("urdf", &o.robot_urdf);
    s.Read("yaml", &o.robot_yaml);
    s.Finish();
  }
  {
    YamlSection s = top.Section("scene");
    s.Read("source", &o.scene);
    s.Read("seed", &o.scene_seed);
    s.Read("keep_out_radius_m", &o.keep_out_radius_m);
    if (!(o.keep_out_radius_m >= 0.0)) throw ConfigError(path, "scene.keep_out_radius_m", "must be >= 0");
    s.Finish();
  }
  top.Read("events_file", &o.events_file);
  {
    YamlSection s = top.Section("plant");
    sim::ReadPlantOptions(s, &o.plant);
    s.Finish();
  }
  {
    YamlSection s = top.Section("state");
    s.Read("rate_hz", &o.state_rate_hz);
    Positive(s, "rate_hz", o.state_rate_hz);
    YamlSection noise = s.Section("pose_noise");
    sim::ReadPoseNoiseOptions(noise, &o.pose_noise);
    noise.Finish();
    s.Finish();
  }
  {
    YamlSection s = top.Section("lidar");
    s.Read("enabled", &o.lidar_enabled);
    s.Read("file", &o.lidar_file);
    o.lidar_options = s.Raw("options");
    if (!o.lidar_file.empty() && o.lidar_options.IsDefined() && !o.lidar_options.IsNull()) {
      throw ConfigError(path, "lidar", "give `file` or `options`, not both");
    }
    s.Finish();
  }
  {
    YamlSection s = top.Section("monitor");
    s.Read("enabled", &o.monitor_enabled);
    s.Finish();
  }
  top.Read("status_rate_hz", &o.status_rate_hz);
  Positive(top, "status_rate_hz", o.status_rate_hz);
  top.Read("follow", &o.follow);
  top.Read("plant_input", &o.plant_input);
  if (o.plant_input != "control_command" && o.plant_input != "actuators") {
    throw ConfigError(path, "plant_input", "must be control_command or actuators, got '" + o.plant_input + "'");
  }
  top.Read("plant_state_rate_hz", &o.plant_state_rate_hz);
  Positive(top, "plant_state_rate_hz", o.plant_state_rate_hz);
  if (o.follow && o.plant_input == "actuators") throw ConfigError(path, "plant_input", "actuators and follow exclude each other");
  {
    YamlSection s = top.Section("follower");
    ReadFollowerOptions(s, &o.follower);
    s.Finish();
  }
  top.Finish();
  o.robot_urdf = Resolve(o.robot_urdf, folder);
  o.robot_yaml = Resolve(o.robot_yaml, folder);
  o.events_file = Resolve(o.events_file, folder);
  o.lidar_file = Resolve(o.lidar_file, folder);
  if (o.scene != "tables" && o.scene != "cuboids") o.scene = Resolve(o.scene, folder);
  return o;
}

}  // namespace topay::simproc
