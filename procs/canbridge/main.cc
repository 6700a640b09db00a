// topay-canbridge: the CAN bridge of the graph (docs/canbridge.md). CONTROL_COMMAND in, CAN
// frames out every 200 Hz cycle (base velocity command, the drives' RPDO1, SYNC) and at once on a
// new command; CAN feedback in, BASE_VELOCITY, JOINT_STATE and DRIVE_STATUS out. The same binary
// on the robot (--can socketcan://can0) and against topay-motorsim (--can udp://239.255.1.1:9000).
// --record FILE writes the bus traffic as a candump -l log; --replay FILE decodes a recorded log
// instead of a bus (sending nothing). Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "core/io/robot_loader.h"
#include "drivers/can/can_url.h"
#include "procs/canbridge/canbridge_node.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/canbridge/recording_can_bus.h"
#include "procs/canbridge/replay_can_bus.h"
#include "procs/runtime/process_loop.h"

using namespace topay;
using namespace topay::canbridge;

namespace {

struct Flags {
  std::string can_url;
  std::string record_path;
  std::string replay_path;
  double replay_speed = 1.0;
};

CanbridgeOptions ResolveOptions(const procs::ProcessOptions& process, const Flags& flags) {
  CanbridgeOptions o = process.config_path.empty() ? CanbridgeOptions{} : LoadCanbridgeOptions(process.config_path);
  procs::DefaultRobotFiles(procs::ConfigDir(TOPAY_CONFIG_DIR), &o.robot_urdf, &o.robot_yaml);
  if (!flags.can_url.empty()) o.can_url = flags.can_url;
  o.Check();
  return o;
}

double SteadyNowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::int64_t SteadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The bus the flags name: a replayed log, or the URL's bus; recorded when asked. Throws
// std::runtime_error saying why it cannot be opened.
std::unique_ptr<can::CanBus> OpenBus(const CanbridgeOptions& options, const Flags& flags, ReplayCanBus** replay) {
  std::unique_ptr<can::CanBus> bus;
  if (!flags.replay_path.empty()) {
    auto replay_bus = std::make_unique<ReplayCanBus>(ReplayCanBus::ReadLog(flags.replay_path), flags.replay_path,
                                                     flags.replay_speed, SteadyNowNs);
    *replay = replay_bus.get();
    bus = std::move(replay_bus);
  } else {
    std::string error;
    bus = can::OpenCanBus(options.can_url, can::CanBusOptions{}, &error);
    if (!bus) throw std::runtime_error(error);
  }
  if (!flags.record_path.empty()) {
    bus = std::make_unique<RecordingCanBus>(std::move(bus), flags.record_path, options.record_interface);
  }
  return bus;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-canbridge: CONTROL_COMMAND -> CAN (base + CiA 402 drives), feedback -> LCM, 200 Hz"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-canbridge", &process);
  Flags flags;
  app.add_option("--can", flags.can_url, "CAN bus URL: socketcan://can0 or udp://GROUP:PORT (default: the config's can_url)");
  app.add_option("--record", flags.record_path, "write every frame sent and received to FILE (candump -l format)");
  auto* replay = app.add_option("--replay", flags.replay_path,
                                "decode a recorded candump -l log instead of a bus, publish its feedback, send nothing");
  app.add_option("--replay-speed", flags.replay_speed, "replay speed factor (default 1: the log's timing)")
      ->check(CLI::PositiveNumber)
      ->needs(replay);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  CanbridgeOptions options;
  std::unique_ptr<can::CanBus> bus;
  ReplayCanBus* replay_bus = nullptr;
  std::unique_ptr<CanbridgeNode> node;
  try {
    options = ResolveOptions(process, flags);
    const RobotModel model = LoadRobotModel(options.robot_urdf, options.robot_yaml);
    bus = OpenBus(options, flags, &replay_bus);
    node = std::make_unique<CanbridgeNode>(options, model, bus.get(), replay_bus != nullptr);
  } catch (const std::exception& e) {  // ConfigError, the robot files', the bus's and the log's errors
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  std::function<bool()> finished;
  if (replay_bus != nullptr) finished = [replay_bus] { return replay_bus->finished(); };
  ConnectCanbridgeNode(&loop, node.get(), options.cycle_period_s, finished);
  spdlog::info("{}: {} at {:.0f} Hz, base node {}, {} drives, command timeout {:.3f} s{}{}", process.name, bus->url(),
               1.0 / options.cycle_period_s, options.base.node_id, options.drives.node_ids.size(),
               options.command_timeout_s, flags.record_path.empty() ? "" : ", recording to ",
               flags.record_path);
  const int code = loop.Run();
  std::printf("%s", node->Report(SteadyNowS()).c_str());
  std::fflush(stdout);
  return code;
}
