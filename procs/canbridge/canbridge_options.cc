#include "procs/canbridge/canbridge_options.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::canbridge {
namespace {

void Require(bool ok, const std::string& field, const std::string& what) {
  if (!ok) throw std::invalid_argument(field + ": " + what);
}

bool Positive(double value) { return std::isfinite(value) && value > 0.0; }

void ReadBase(YamlSection s, BaseLinkOptions* o) {
  s.Read("node_id", &o->node_id);
  s.Read("mode_request_repeat_s", &o->mode_request_repeat_s);
  s.Read("status_timeout_s", &o->status_timeout_s);
  s.Read("wheel_radius_m", &o->geometry.wheel_radius_m);
  s.Read("track_width_m", &o->geometry.track_width_m);
  s.Read("ticks_per_rev", &o->geometry.ticks_per_rev);
  s.Finish();
}

void ReadDrives(YamlSection s, DriveLinkOptions* o) {
  std::vector<double> ids(o->node_ids.begin(), o->node_ids.end());
  s.Read("node_ids", &ids);
  o->node_ids.clear();
  for (const double id : ids) {
    if (id != std::floor(id)) throw ConfigError(s.source(), s.FieldPath("node_ids"), "node ids must be integers");
    // Before the conversion to int, which is undefined for a double out of its range (1e300).
    if (!(id >= 1.0 && id <= 127.0)) {
      throw ConfigError(s.source(), s.FieldPath("node_ids"), fmt::format("node id {} is outside 1..127", id));
    }
    o->node_ids.push_back(static_cast<int>(id));
  }
  s.Read("heartbeat_timeout_s", &o->heartbeat_timeout_s);
  s.Read("pdo_timeout_s", &o->pdo_timeout_s);
  s.Read("sdo_timeout_s", &o->sdo_timeout_s);
  s.Read("sdo_attempts", &o->sdo_attempts);
  s.Read("boot_timeout_s", &o->boot_timeout_s);
  s.Read("retry_after_s", &o->retry_after_s);
  s.Read("host_heartbeat_period_s", &o->host_heartbeat_period_s);
  s.Read("producer_heartbeat_ms", &o->startup.producer_heartbeat_ms);
  s.Read("consumer_heartbeat_ms", &o->startup.consumer_heartbeat_ms);
  s.Read("rpdo_deadline_ms", &o->startup.rpdo_deadline_ms);
  s.Read("host_node_id", &o->startup.host_node_id);
  s.Finish();
}

}  // namespace

void CanbridgeOptions::Check() const {
  Require(!can_url.empty(), "can_url", "must not be empty");
  Require(Positive(cycle_period_s) && cycle_period_s <= 0.1, "cycle_period_s", "must be in (0, 0.1]");
  Require(Positive(bit_rate_bps), "bit_rate_bps", "must be finite and > 0");
  Require(Positive(command_timeout_s) && command_timeout_s > cycle_period_s, "command_timeout_s",
          "must be finite and longer than cycle_period_s");
  Require(std::isfinite(zero_command_tolerance) && zero_command_tolerance >= 0.0, "zero_command_tolerance",
          "must be finite and >= 0");
  Require(std::isfinite(recovery_hold_s) && recovery_hold_s >= 0.0, "recovery_hold_s", "must be finite and >= 0");
  Require(Positive(enable_timeout_s), "enable_timeout_s", "must be finite and > 0");
  Require(Positive(fault_reset_timeout_s), "fault_reset_timeout_s", "must be finite and > 0");
  Require(max_auto_resets_per_minute >= 0 && max_auto_resets_per_minute <= 60, "max_auto_resets_per_minute",
          "must be in 0..60");
  Require(Positive(status_period_s), "status_period_s", "must be finite and > 0");
  Require(Positive(bus_reopen_period_s), "bus_reopen_period_s", "must be finite and > 0");
  Require(!record_interface.empty() && record_interface.size() <= 15 &&
              record_interface.find_first_of(" \t") == std::string::npos,
          "record_interface", "must be 1-15 characters without spaces");
  Require(base.node_id >= 1 && base.node_id <= 127, "base.node_id", "must be in 1..127");
  Require(Positive(base.mode_request_repeat_s), "base.mode_request_repeat_s", "must be finite and > 0");
  Require(Positive(base.status_timeout_s), "base.status_timeout_s", "must be finite and > 0");
  Require(base::CheckDriveGeometry(base.geometry).empty(), "base", base::CheckDriveGeometry(base.geometry));
  std::set<int> ids;
  for (const int id : drives.node_ids) {
    Require(id >= 1 && id <= 127, "drives.node_ids", "node id " + std::to_string(id) + " is outside 1..127");
    Require(ids.insert(id).second, "drives.node_ids", "node id " + std::to_string(id) + " appears twice");
    Require(id != base.node_id, "drives.node_ids",
            "node id " + std::to_string(id) + " is the base's (base.node_id): their CAN ids would clash");
    Require(id != drives.startup.host_node_id, "drives.node_ids",
            "node id " + std::to_string(id) + " is the host's (drives.host_node_id)");
  }
  Require(drives.startup.host_node_id != base.node_id, "drives.host_node_id", "must differ from base.node_id");
  Require(Positive(drives.heartbeat_timeout_s), "drives.heartbeat_timeout_s", "must be finite and > 0");
  Require(std::isfinite(drives.pdo_timeout_s) && drives.pdo_timeout_s >= 0.0, "drives.pdo_timeout_s",
          "must be finite and >= 0");
  Require(Positive(drives.sdo_timeout_s), "drives.sdo_timeout_s", "must be finite and > 0");
  Require(drives.sdo_attempts >= 1, "drives.sdo_attempts", "must be >= 1");
  Require(Positive(drives.boot_timeout_s), "drives.boot_timeout_s", "must be finite and > 0");
  Require(Positive(drives.retry_after_s), "drives.retry_after_s", "must be finite and > 0");
  Require(Positive(drives.host_heartbeat_period_s), "drives.host_heartbeat_period_s", "must be finite and > 0");
  Require(drives.startup.producer_heartbeat_ms >= 1 && drives.startup.producer_heartbeat_ms <= 65535,
          "drives.producer_heartbeat_ms", "must be in 1..65535");
  Require(drives.startup.consumer_heartbeat_ms >= 1 && drives.startup.consumer_heartbeat_ms <= 65535,
          "drives.consumer_heartbeat_ms", "must be in 1..65535");
  // A deadline of fewer than 3 cycles would fault the drives on one late cycle.
  const int deadline_ms = drives.startup.rpdo_deadline_ms;
  Require(deadline_ms == 0 || (deadline_ms <= 65535 && deadline_ms * 1e-3 >= 3.0 * cycle_period_s - 1e-9),
          "drives.rpdo_deadline_ms", "must be 0 (not monitored) or from 3 CAN cycles to 65535 ms");
}

CanbridgeOptions LoadCanbridgeOptions(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  CanbridgeOptions o;
  o.source = path;
  YamlSection top(root, path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  top.Read("can_url", &o.can_url);
  top.Read("cycle_period_s", &o.cycle_period_s);
  top.Read("bit_rate_bps", &o.bit_rate_bps);
  top.Read("command_timeout_s", &o.command_timeout_s);
  top.Read("zero_command_tolerance", &o.zero_command_tolerance);
  top.Read("recovery_hold_s", &o.recovery_hold_s);
  top.Read("enable_timeout_s", &o.enable_timeout_s);
  top.Read("fault_reset_timeout_s", &o.fault_reset_timeout_s);
  top.Read("auto_reset_communication_faults", &o.auto_reset_communication_faults);
  top.Read("max_auto_resets_per_minute", &o.max_auto_resets_per_minute);
  top.Read("status_period_s", &o.status_period_s);
  top.Read("bus_reopen_period_s", &o.bus_reopen_period_s);
  top.Read("record_interface", &o.record_interface);
  ReadBase(top.Section("base"), &o.base);
  ReadDrives(top.Section("drives"), &o.drives);
  top.Finish();
  try {
    o.Check();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    const std::size_t colon = what.find(": ");
    throw ConfigError(path, what.substr(0, colon), colon == std::string::npos ? what : what.substr(colon + 2));
  }
  return o;
}

}  // namespace topay::canbridge
