#pragma once
// The bridge node on an in-memory bus with the base and drive peers, on a simulated clock: each
// Tick runs the bridge's cycle, then the peers, then advances the clock by one cycle (5 ms).

#include <memory>
#include <string>

#include "core/io/robot_loader.h"
#include "procs/canbridge/canbridge_node.h"
#include "tests/procs/canbridge/bus_peers.h"
#include "tests/procs/canbridge/memory_can_bus.h"

namespace topay::canbridge::test {

inline RobotModel ShippedRobot() {
  // Parsed once per process (the fuzz target builds a rig per input); each rig gets a copy.
  static const RobotModel model = [] {
    const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
    return LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
  }();
  return model;
}

struct Rig {
  explicit Rig(CanbridgeOptions o = {}, bool listen_only = false)
      : options(std::move(o)),
        wire(std::make_shared<MemoryWire>()),
        bridge_bus(wire, "bridge"),
        peer_bus(wire, "peers"),
        model(ShippedRobot()),
        node(options, model, &bridge_bus, listen_only),
        peers(&peer_bus, options.base.node_id, options.drives.node_ids) {
    wire->now_ns = [this] { return static_cast<std::int64_t>(t * 1e9); };
    peers.PowerOn();
  }

  const CanbridgeOutputs& Tick() {
    const CanbridgeOutputs& out = node.Cycle(t, static_cast<std::int64_t>(t * 1e6));
    if (out.status) last_status = *out.status;
    if (out.joint_state) last_joint_state = *out.joint_state;
    if (out.base_velocity) last_base_velocity = *out.base_velocity;
    peers.Step(t);
    t += options.cycle_period_s;
    return out;
  }
  template <class Pred>
  bool TickUntil(Pred pred, double max_s) {
    const double end = t + max_s;
    while (t < end) {
      Tick();
      if (pred()) return true;
    }
    return pred();
  }
  void TickFor(double seconds) {
    const double end = t + seconds;
    while (t < end) Tick();
  }
  control_command_t Command(double v, double omega, double qdot) const {
    control_command_t msg{};
    msg.utime = static_cast<std::int64_t>(t * 1e6);
    msg.v_mps = v;
    msg.omega_radps = omega;
    msg.num_joints = model.num_joints();
    msg.qdot_radps.assign(model.num_joints(), qdot);
    return msg;
  }
  /// Ticks for `seconds`, sending `msg` every 4th cycle (the tracker's 50 Hz).
  void CommandFor(const control_command_t& msg, double seconds) {
    const double end = t + seconds;
    for (int i = 0; t < end; ++i) {
      if (i % 4 == 0) node.OnCommand(msg, t);
      Tick();
    }
  }
  /// Ticks sending `msg` every 4th cycle until pred() or max_s.
  template <class Pred>
  bool CommandUntil(const control_command_t& msg, Pred pred, double max_s) {
    const double end = t + max_s;
    for (int i = 0; t < end; ++i) {
      if (i % 4 == 0) node.OnCommand(msg, t);
      Tick();
      if (pred()) return true;
    }
    return pred();
  }
  bool Running() { return TickUntil([this] { return node.state() == BridgeState::kRunning; }, 3.0); }

  CanbridgeOptions options;
  double t = 1000.0;
  std::shared_ptr<MemoryWire> wire;
  MemoryCanBus bridge_bus;
  MemoryCanBus peer_bus;
  RobotModel model;
  CanbridgeNode node;
  Peers peers;
  drive_status_t last_status{};
  joint_state_t last_joint_state{};
  base_velocity_t last_base_velocity{};
};

}  // namespace topay::canbridge::test
