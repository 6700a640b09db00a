#include "procs/viz/viz_options.h"

#include "core/common/error.h"
#include "core/io/yaml_section.h"

namespace topay::viz {
namespace {

void ReadSize(YamlSection* s, const char* key, std::size_t* value) {
  std::uint64_t v = *value;
  s->Read(key, &v);
  *value = static_cast<std::size_t>(v);
}

void ReadServer(YamlSection s, WsServerOptions* o) {
  s.Read("bind_address", &o->bind_address);
  s.Read("port", &o->port);
  s.Read("web_root", &o->web_root);
  o->web_root = ResolveBeside(o->web_root, s.source());
  ReadSize(&s, "max_clients", &o->max_clients);
  ReadSize(&s, "max_http_connections", &o->max_http_connections);
  ReadSize(&s, "max_queue_frames", &o->max_queue_frames);
  ReadSize(&s, "max_queue_bytes", &o->max_queue_bytes);
  ReadSize(&s, "max_incoming_message_bytes", &o->max_incoming_message_bytes);
  s.Read("handshake_timeout_s", &o->handshake_timeout_s);
  s.Read("idle_timeout_s", &o->idle_timeout_s);
  s.Read("permessage_deflate", &o->permessage_deflate);
  s.Finish();
}

void ReadRates(YamlSection s, VizRates* o) {
  s.Read("robot_state_hz", &o->robot_state_hz);
  s.Read("map_hz", &o->map_hz);
  s.Read("scan_hz", &o->scan_hz);
  s.Read("plot_hz", &o->plot_hz);
  s.Read("status_hz", &o->status_hz);
  s.Read("drive_hz", &o->drive_hz);
  s.Read("sim_hz", &o->sim_hz);
  s.Finish();
}

void ReadPipeline(YamlSection s, VizPipelineOptions* o) {
  ReadRates(s.Section("rates"), &o->rates);
  s.Read("scan_max_points", &o->scan.max_points);
  s.Read("trajectory_sample_dt_s", &o->trajectory.sample_dt_s);
  s.Read("trajectory_max_samples", &o->trajectory.max_samples);
  s.Read("max_contacts", &o->max_contacts);
  s.Finish();
}

void Require(bool ok, const std::string& source, const char* field, const char* why) {
  if (!ok) throw ConfigError(source, field, why);
}

}  // namespace

void CheckVizOptions(const VizOptions& o, const std::string& source) {
  const std::string server = CheckWsServerOptions(o.server);
  Require(server.empty(), source, "server", server.c_str());
  const VizRates& r = o.pipeline.rates;
  for (double rate : {r.robot_state_hz, r.map_hz, r.scan_hz, r.plot_hz, r.status_hz, r.drive_hz, r.sim_hz}) {
    Require(rate >= 0, source, "pipeline.rates", "rates must be >= 0 (0: every message)");
  }
  Require(o.pipeline.scan.max_points >= 1, source, "pipeline.scan_max_points", "must be >= 1");
  Require(o.pipeline.trajectory.sample_dt_s > 0, source, "pipeline.trajectory_sample_dt_s", "must be > 0");
  Require(o.pipeline.trajectory.max_samples >= 2, source, "pipeline.trajectory_max_samples", "must be >= 2");
  Require(o.pipeline.max_contacts >= 1, source, "pipeline.max_contacts", "must be >= 1");
  Require(o.flush_hz > 0 && o.flush_hz <= 1000, source, "flush_hz", "must be in (0, 1000]");
}

VizOptions LoadVizOptions(const std::string& path) {
  VizOptions o;
  YamlSection top(LoadYamlFile(path), path);
  ReadRobotFiles(&top, &o.robot_urdf, &o.robot_yaml);
  ReadServer(top.Section("server"), &o.server);
  ReadPipeline(top.Section("pipeline"), &o.pipeline);
  top.Read("flush_hz", &o.flush_hz);
  top.Finish();
  CheckVizOptions(o, path);
  return o;
}

}  // namespace topay::viz
