#include "sim/events/event_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/yaml_section.h"

namespace topay::sim {
namespace {

Eigen::VectorXd ReadFixed(YamlSection& s, const char* key, int size, bool required) {
  std::vector<double> values;
  s.Read(key, &values);
  if (values.empty() && !required) return Eigen::VectorXd();
  if (static_cast<int>(values.size()) != size) {
    throw ConfigError(s.source(), s.FieldPath(key), "expected " + std::to_string(size) + " numbers");
  }
  return Eigen::Map<Eigen::VectorXd>(values.data(), size);
}

SimEvent ReadEvent(const YAML::Node& node, const std::string& source, const std::string& path) {
  YamlSection s(node, source, path);
  if (!node.IsMap()) throw ConfigError(source, path, "expected a map (an event)");
  SimEvent event;
  s.Read("name", &event.name);
  const bool has_time = node["at_s"].IsDefined(), has_near = node["near"].IsDefined();
  const bool has_appear = node["appear"].IsDefined(), has_disappear = node["disappear"].IsDefined();
  if (has_time == has_near) throw ConfigError(source, path, "needs exactly one trigger: at_s or near");
  if (has_appear == has_disappear) throw ConfigError(source, path, "needs exactly one action: appear or disappear");
  if (has_time) {
    event.trigger = SimEvent::Trigger::kAtTime;
    s.Read("at_s", &event.at_s);
    s.Read("jitter_s", &event.jitter_s);
    if (!(event.at_s >= 0.0) || !std::isfinite(event.at_s)) throw ConfigError(source, s.FieldPath("at_s"), "must be a finite time >= 0");
    if (!(event.jitter_s >= 0.0) || !std::isfinite(event.jitter_s)) throw ConfigError(source, s.FieldPath("jitter_s"), "must be finite and >= 0");
  } else {
    event.trigger = SimEvent::Trigger::kNearPoint;
    YamlSection near = s.Section("near");
    event.point_W_m = ReadFixed(near, "point", 2, true);
    event.distance_m = -1.0;
    near.Read("distance_m", &event.distance_m);
    if (!(event.distance_m > 0.0) || !std::isfinite(event.distance_m)) {
      throw ConfigError(source, near.FieldPath("distance_m"), "required, a finite distance > 0");
    }
    near.Finish();
  }
  YamlSection action = s.Section(has_appear ? "appear" : "disappear");
  event.action = has_appear ? SimEvent::Action::kAppear : SimEvent::Action::kDisappear;
  action.Read("id", &event.box_id);
  if (event.box_id < 0) throw ConfigError(source, action.FieldPath("id"), "required, a box id >= 0");
  if (has_appear) {
    const Eigen::VectorXd center = ReadFixed(action, "center", 3, false);
    const Eigen::VectorXd size = ReadFixed(action, "size", 3, false);
    double yaw = 0.0;
    const bool has_yaw = node["appear"]["yaw"].IsDefined();
    action.Read("yaw", &yaw);
    if (center.size() != size.size() || (has_yaw && center.size() == 0)) {
      throw ConfigError(source, action.FieldPath("center"), "give center and size (and optionally yaw) together, or none of them");
    }
    if (center.size() == 3) {
      if ((size.array() <= 0.0).any()) throw ConfigError(source, action.FieldPath("size"), "sizes must be > 0");
      // YamlSection reads .inf as a number (for limits); a box's yaw must be finite.
      if (!std::isfinite(yaw)) throw ConfigError(source, action.FieldPath("yaw"), "must be a finite angle");
      OrientedBox box;
      box.center_W_m = center;
      box.size_m = size;
      box.yaw_rad = yaw;
      event.box = box;
    }
  }
  action.Finish();
  s.Finish();
  return event;
}

}  // namespace

EventScript ParseEventScript(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, "", std::string("malformed YAML: ") + e.what());
  }
  if (!root.IsMap()) throw ConfigError(source, "(top level)", "expected a map with `events:`");
  YamlSection top(root, source);
  EventScript script;
  if (root["seed"].IsDefined()) {
    std::uint64_t seed = 0;
    top.Read("seed", &seed);
    script.seed = seed;
  }
  const YAML::Node events = top.Raw("events");
  if (!events.IsDefined() || events.IsNull()) throw ConfigError(source, "events", "missing (a list of events)");
  if (!events.IsSequence()) throw ConfigError(source, "events", "expected a list of events");
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string path = "events[" + std::to_string(i) + "]";
    SimEvent event = ReadEvent(events[i], source, path);
    if (event.name.empty()) event.name = "event " + std::to_string(i);
    script.events.push_back(std::move(event));
  }
  top.Finish();
  return script;
}

EventScript LoadEventFile(const std::string& path) {
  return ParseEventScript(ReadBoundedTextFile(path, kMaxConfigFileBytes, "event file"), path);
}

}  // namespace topay::sim
