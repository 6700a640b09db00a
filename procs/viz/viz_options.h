#pragma once
// topay-viz's options (config/viz/viz.yaml, every key optional; docs/viewer.md): where it
// listens, what it serves, how fast each channel goes to the browser, and the bounds that keep
// a slow or hostile client from costing the process memory or time.

#include <cstddef>
#include <string>

#include "procs/viz/server/ws_server_options.h"
#include "procs/viz/viz_pipeline.h"

namespace topay::viz {

struct VizOptions {
  std::string robot_urdf;  ///< "" = the shipped robot (config/robot/topay_mm.urdf)
  std::string robot_yaml;  ///< "" = config/robot/topay_mm.yaml
  /// Where it listens and the bounds on clients (procs/viz/server/ws_server_options.h); the
  /// web_root "" is replaced by the build's web/ bundle in main.
  WsServerOptions server;
  VizPipelineOptions pipeline;
  double flush_hz = 30.0;  ///< how often waiting payloads and latched requests are served
};

/// Loads options from YAML (relative robot paths from the file's folder). Throws ConfigError
/// naming the file and the field for a misspelt key, a wrong type or a bad value.
VizOptions LoadVizOptions(const std::string& path);

/// Throws ConfigError(source, field, why) for values that make no sense (a port out of
/// 0..65535, a rate < 0, a bound < 1; CheckWsServerOptions for the server).
void CheckVizOptions(const VizOptions& options, const std::string& source);

}  // namespace topay::viz
