#include "sim/motors/motorsim_options.h"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/yaml_section.h"

namespace topay::sim::motors {
namespace {

int WholeNumber(const YamlSection& s, const char* key, double value) {
  if (value != std::floor(value) || std::abs(value) > 1e9) throw ConfigError(s.source(), s.FieldPath(key), "must be a whole number");
  return static_cast<int>(value);
}

void ReadBase(YamlSection& s, WheelControllerOptions* o) {
  s.Read("node_id", &o->node_id);
  s.Read("wheel_radius_m", &o->geometry.wheel_radius_m);
  s.Read("track_width_m", &o->geometry.track_width_m);
  s.Read("ticks_per_rev", &o->geometry.ticks_per_rev);
  s.Read("command_timeout_s", &o->modes.command_timeout_s);
  std::string timeout_mode = o->modes.timeout_mode == base::BaseMode::kStandby ? "standby" : "quick_stop";
  s.Read("timeout_mode", &timeout_mode);
  if (timeout_mode == "standby") {
    o->modes.timeout_mode = base::BaseMode::kStandby;
  } else if (timeout_mode == "quick_stop") {
    o->modes.timeout_mode = base::BaseMode::kQuickStop;
  } else {
    throw ConfigError(s.source(), s.FieldPath("timeout_mode"), "must be quick_stop or standby, got '" + timeout_mode + "'");
  }
  s.Read("status_period_s", &o->status_period_s);
  s.Read("feedback_period_s", &o->feedback_period_s);
  s.Read("battery_voltage_v", &o->battery_voltage_v);
  s.Read("max_wheel_speed_radps", &o->max_wheel_speed_radps);
  s.Read("quick_stop_decel_mps2", &o->quick_stop_decel_mps2);
  s.Read("quick_stop_decel_radps2", &o->quick_stop_decel_radps2);
  if (std::string bad = CheckWheelControllerOptions(*o); !bad.empty()) throw ConfigError(s.source(), "base", bad);
}

void ReadDrives(YamlSection& s, std::vector<int>* node_ids, DriveNodeOptions* o) {
  std::vector<double> ids(node_ids->begin(), node_ids->end());
  s.Read("node_ids", &ids);
  node_ids->clear();
  for (double id : ids) node_ids->push_back(WholeNumber(s, "node_ids", id));
  s.Read("producer_heartbeat_ms", &o->producer_heartbeat_ms);
  s.Read("max_velocity_radps", &o->max_velocity_radps);
  s.Read("quick_stop_decel_radps2", &o->quick_stop_decel_radps2);
  s.Read("standstill_radps", &o->standstill_radps);
  s.Read("fault_reaction_timeout_s", &o->fault_reaction_timeout_s);
  s.Read("quick_stop_stays_active", &o->model.quick_stop_stays_active);
  int code = o->fault_emcy_code;
  s.Read("fault_emcy_code", &code);
  if (code < 0 || code > 0xFFFF) throw ConfigError(s.source(), s.FieldPath("fault_emcy_code"), "must be in 0..65535");
  o->fault_emcy_code = static_cast<std::uint16_t>(code);
  DriveNodeOptions check = *o;
  check.node_id = node_ids->empty() ? 1 : node_ids->front();
  if (std::string bad = CheckDriveNodeOptions(check); !bad.empty()) throw ConfigError(s.source(), "drives", bad);
}

FaultEvent ReadEvent(YamlSection& e) {
  FaultEvent event;
  std::string kind;
  e.Read("kind", &kind);
  if (!ParseFaultKind(kind, &event.kind) || event.kind == FaultKind::kClear) {
    throw ConfigError(e.source(), e.FieldPath("kind"),
                      "must be drive_fault, heartbeat_loss, bus_off, rx_loss, tx_loss, delay or base_fault, got '" + kind + "'");
  }
  e.Read("at_s", &event.at_s);
  e.Read("joint", &event.joint);
  e.Read("duration_s", &event.duration_s);
  e.Read("value", &event.value);
  e.Read("code", &event.code);
  return event;
}

void ReadFaults(YamlSection& s, int num_joints, FaultInjectionOptions* o) {
  s.Read("seed", &o->seed);
  s.Read("rx_loss_percent", &o->rx_loss_percent);
  s.Read("tx_loss_percent", &o->tx_loss_percent);
  s.Read("delay_ms", &o->delay_ms);
  s.Read("delay_burst_s", &o->delay_burst_s);
  s.Read("delay_period_s", &o->delay_period_s);
  const YAML::Node events = s.Raw("events");
  if (events.IsDefined() && !events.IsNull()) {
    if (!events.IsSequence()) throw ConfigError(s.source(), s.FieldPath("events"), "must be a list");
    for (std::size_t i = 0; i < events.size(); ++i) {
      const std::string path = s.FieldPath("events") + "[" + std::to_string(i) + "]";
      if (!events[i].IsMap()) throw ConfigError(s.source(), path, "must be a map");
      YamlSection e(events[i], s.source(), path);
      const FaultEvent event = ReadEvent(e);
      e.Finish();
      if (std::string bad = CheckFaultEvent(event, num_joints); !bad.empty()) throw ConfigError(s.source(), path, bad);
      o->events.push_back(event);
    }
  }
  FaultInjectionOptions check = *o;
  check.events.clear();
  if (std::string bad = CheckFaultInjectionOptions(check, num_joints); !bad.empty()) {
    throw ConfigError(s.source(), "faults", bad);
  }
}

}  // namespace

MotorSimOptions ParseMotorSimOptions(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, "", std::string("malformed YAML: ") + e.what());
  }
  if (!root.IsNull() && !root.IsMap()) throw ConfigError(source, "", "expected a map of options");
  MotorSimOptions o;
  YamlSection top(root, source);
  top.Read("step_period_s", &o.step_period_s);
  if (!(o.step_period_s > 0.0)) throw ConfigError(source, "step_period_s", "must be > 0");
  {
    YamlSection s = top.Section("base");
    ReadBase(s, &o.base);
    s.Finish();
  }
  {
    YamlSection s = top.Section("drives");
    ReadDrives(s, &o.joint_node_ids, &o.drive);
    s.Finish();
  }
  {
    YamlSection s = top.Section("faults");
    ReadFaults(s, static_cast<int>(o.joint_node_ids.size()), &o.faults);
    s.Finish();
  }
  {
    YamlSection s = top.Section("stalled_plant");
    s.Read("stale_after_s", &o.stalled_plant.stale_after_s);
    s.Read("carry_on_s", &o.stalled_plant.carry_on_s);
    s.Finish();
  }
  top.Finish();
  if (std::string bad = CheckMotorSimOptions(o); !bad.empty()) throw ConfigError(source, "", bad);
  return o;
}

MotorSimOptions LoadMotorSimOptions(const std::string& path) {
  return ParseMotorSimOptions(ReadBoundedTextFile(path, kMaxConfigFileBytes, "motor simulator YAML"), path);
}

}  // namespace topay::sim::motors
