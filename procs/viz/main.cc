// topay-viz: the browser viewer's server (docs/viewer.md). Live: every LCM channel of the graph
// in; an HTTP page and a Foxglove WebSocket (foxglove.websocket.v1, JSON-schema channels) out,
// on loopback by default; read-only (it publishes only its heartbeat). Replay: `--log FILE`
// serves a recorded log with play / pause / speed / seek. Prints "topay-viz: serving
// http://ADDR:PORT/" once listening. Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "procs/runtime/net_namespace.h"
#include "procs/runtime/process_loop.h"
#include "procs/viz/foxglove_hub.h"
#include "procs/viz/live_source.h"
#include "procs/viz/log_replay.h"
#include "procs/viz/robot_view.h"
#include "procs/viz/server/ws_server.h"
#include "procs/viz/viz_feed.h"
#include "procs/viz/viz_options.h"

using namespace topay;
using namespace topay::viz;

namespace {

struct Flags {
  std::string log_path;
  bool paused = false;
  double speed = 1.0;
  std::optional<std::string> bind_address;
  std::optional<int> port;
  std::optional<std::string> web_root;
  bool host_network = false;
};

VizOptions ResolveOptions(const procs::ProcessOptions& process, const Flags& flags) {
  VizOptions o = process.config_path.empty() ? VizOptions{} : LoadVizOptions(process.config_path);
  procs::DefaultRobotFiles(procs::ConfigDir(TOPAY_CONFIG_DIR), &o.robot_urdf, &o.robot_yaml);
  if (flags.bind_address) o.server.bind_address = *flags.bind_address;
  if (flags.port) o.server.port = *flags.port;
  if (flags.web_root) o.server.web_root = *flags.web_root;
  if (o.server.web_root.empty()) o.server.web_root = TOPAY_WEB_DIR;
  CheckVizOptions(o, process.config_path.empty() ? "command line" : process.config_path);
  return o;
}

TransportCounts CountsOf(const WsServer& server) {
  const WsServerStats s = server.stats();
  return {static_cast<std::int64_t>(s.clients), static_cast<std::int64_t>(s.frames_sent),
          static_cast<std::int64_t>(s.frames_dropped), static_cast<std::int64_t>(s.bytes_sent)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-viz: the graph (or a recorded log) in a browser and in Foxglove"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-viz", &process);
  Flags flags;
  app.add_option("--log", flags.log_path, "replay this LCM log instead of the live graph")->check(CLI::ExistingFile);
  app.add_flag("--paused", flags.paused, "replay: start paused at the log's start");
  app.add_option("--speed", flags.speed, "replay: initial speed (log s per wall s)")->check(CLI::Range(0.01, 100.0));
  app.add_option("--bind", flags.bind_address, "address to listen on (default 127.0.0.1)");
  app.add_option("--port", flags.port, "TCP port (default 8765; 0: any free port)");
  app.add_option("--web-root", flags.web_root, "the page's folder (default: the build's web/)");
  app.add_flag("--host-network", flags.host_network,
               "in an isolated graph: listen in the machine's network namespace (TOPAY_HOST_NETNS_FD)");
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;
  const bool replay = !flags.log_path.empty();
  if (replay) process.lcm_url = "memq://";  // a replay listens to no graph

  VizOptions options;
  std::unique_ptr<RobotView> robot;
  try {
    options = ResolveOptions(process, flags);
    robot = std::make_unique<RobotView>(options.robot_urdf, options.robot_yaml);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  std::unique_ptr<WsServer> server;
  FoxgloveHub hub({.server_name = "topay-viz", .replay = replay},
                  [&server](HubClientId client, std::shared_ptr<const std::string> bytes, bool binary) {
                    server->Send(client, OutgoingFrame{std::move(bytes), binary});
                  });
  server = std::make_unique<WsServer>(
      options.server, WsServerCallbacks{[&hub](ClientId c) { hub.OnOpen(c); },
                                        [&hub](ClientId c, std::string_view t) { hub.OnText(c, t); },
                                        [&hub](ClientId c, std::string_view b) { hub.OnBinary(c, b); },
                                        [&hub](ClientId c) { hub.OnClose(c); }});
  VizFeed feed(*robot, options.pipeline, &hub);
  std::unique_ptr<LogReplay> log;
  try {
    if (replay) log = std::make_unique<LogReplay>(flags.log_path, &feed, flags.paused, flags.speed);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  if (log) hub.SetPlaybackHandler([&log](const PlaybackCommand& c) { log->Command(c); });
  if (!replay) SubscribeAllChannels(&loop.lcm(), &feed);

  std::string error;
  bool started = false;
  const auto start = [&] { started = server->Start(&error); };
  if (!flags.host_network) {
    start();
  } else if (!procs::RunInHostNetworkNamespace(start, &error)) {
    spdlog::warn("--host-network: {}; serving in the graph's own network namespace", error);
    error.clear();
    start();
  }
  if (!started) {
    spdlog::error("{}", error);
    return procs::kExitConfigError;
  }
  loop.AddTimer(1.0 / options.flush_hz, [&] {
    const std::int64_t now = procs::NowUtime();
    log ? log->Tick(now) : feed.Tick(now);
  });
  loop.AddTimer(0.25, [&] {
    const std::int64_t now = procs::NowUtime();
    const PlaybackState state = log ? log->State(now) : PlaybackState{.t = now * 1e-6};
    feed.PublishPlayback(static_cast<std::int64_t>(state.t * 1e6), state);
    if (log) hub.PublishTime(static_cast<std::int64_t>(state.t * 1e6));
  });
  loop.AddTimer(1.0, [&] {
    const TransportCounts counts = CountsOf(*server);
    feed.PublishStats(procs::NowUtime(), counts);
    loop.SetHealth(0, feed.StatusLine(counts));
  });
  std::printf("topay-viz: serving http://%s:%d/ (%s)\n", options.server.bind_address.c_str(), server->port(),
              replay ? flags.log_path.c_str() : "live graph");
  std::fflush(stdout);
  const int code = loop.Run();
  server->Stop();  // its last on_close calls reach the hub, which outlives it
  std::printf("topay-viz: %s\n", feed.StatusLine(CountsOf(*server)).c_str());
  server.reset();
  return code;
}
