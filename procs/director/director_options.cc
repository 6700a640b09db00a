#include "procs/director/director_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::director {
namespace {

// A [min, max] pair (both finite, min <= max) into *min, *max, if present.
void ReadRange(YamlSection* section, const char* key, double* min, double* max) {
  std::vector<double> values;
  section->Read(key, &values);
  if (values.empty()) return;
  if (values.size() != 2 || !(values[0] <= values[1])) {
    throw ConfigError(section->source(), section->FieldPath(key), "expected [min, max] with min <= max");
  }
  *min = values[0];
  *max = values[1];
}

BoxOnRouteEvent ReadEvent(const YAML::Node& node, const std::string& source, int index) {
  const std::string path = "events[" + std::to_string(index) + "]";
  if (!node.IsMap()) throw ConfigError(source, path, "expected a map");
  YamlSection e(node, source, path);
  std::string type;
  e.Read("type", &type);
  if (type != "box_on_route") {
    throw ConfigError(source, e.FieldPath("type"), "expected box_on_route, got '" + type + "'");
  }
  BoxOnRouteEvent event;
  event.name = "box on route " + std::to_string(index);
  e.Read("name", &event.name);
  e.Read("during_step", &event.during_step);
  e.Read("min_speed_mps", &event.min_speed_mps);
  if (!(event.min_speed_mps >= 0.0)) throw ConfigError(source, e.FieldPath("min_speed_mps"), "must be >= 0");
  ReadRange(&e, "ahead_m", &event.box.ahead_min_m, &event.box.ahead_max_m);
  ReadRange(&e, "side_m", &event.box.side_min_m, &event.box.side_max_m);
  e.Read("height_m", &event.box.height_m);
  e.Read("min_robot_distance_m", &event.box.min_robot_distance_m);
  e.Read("scene_gap_m", &event.box.scene_gap_m);
  e.Read("end_margin_m", &event.box.end_margin_m);
  e.Read("tries", &event.box.tries);
  e.Read("box_id", &event.box_id);
  if (event.box_id < -1) throw ConfigError(source, e.FieldPath("box_id"), "must be >= 0 (or -1: automatic)");
  e.Finish();  // a misspelt key first: it may be the missing one
  if (event.during_step.empty()) throw ConfigError(source, e.FieldPath("during_step"), "required (a step's name)");
  try {
    CheckRouteBoxOptions(event.box);
  } catch (const std::invalid_argument& error) {
    throw ConfigError(source, path, error.what());
  }
  return event;
}

}  // namespace

DirectorOptions LoadDirectorOptions(const std::string& path) {
  DirectorOptions o;
  o.source = path;
  YamlSection top(LoadYamlFile(path), path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  top.Read("seed", &o.seed);
  top.Read("tick_period_s", &o.tick_period_s);
  if (!(o.tick_period_s > 0.0)) throw ConfigError(path, "tick_period_s", "must be > 0");
  top.Read("retry_period_s", &o.retry_period_s);
  if (!(o.retry_period_s >= 0.0 && o.retry_period_s < 3600.0)) {
    throw ConfigError(path, "retry_period_s", "must be >= 0 and < 3600");
  }
  top.Read("path_sample_s", &o.path_sample_s);
  if (!(o.path_sample_s > 0.0)) throw ConfigError(path, "path_sample_s", "must be > 0");
  const YAML::Node events = top.Raw("events");
  if (events.IsDefined() && !events.IsNull()) {
    if (!events.IsSequence()) throw ConfigError(path, "events", "expected a list of events");
    for (std::size_t i = 0; i < events.size(); ++i) o.events.push_back(ReadEvent(events[i], path, static_cast<int>(i)));
  }
  top.Finish();
  return o;
}

}  // namespace topay::director
