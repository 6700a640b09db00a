// MotorSim (sim/motors/motor_sim.h): the wheel controller and the seven drives on one bus,
// driven by a host made of drivers/base and drivers/arm helpers: the actuator command follows
// the base's velocity command and the enabled drives' targets, the feedback carries the plant's
// state, a scripted drive fault gives EMCY + Fault, injected bus-off silences every node and
// the base's watchdog stops it.

#include "sim/motors/motor_sim.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_host.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sync.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/can/can_error.h"

namespace topay::sim::motors {
namespace {

using cia402::DriveState;
constexpr int kBaseNode = 16;

PlantState Plant(double v, double q1) {
  PlantState p;
  p.state.q_rad = Eigen::VectorXd::Zero(7);
  p.state.q_rad[0] = q1;
  p.qdot_radps = Eigen::VectorXd::Zero(7);
  p.v_mps = v;
  return p;
}

// A host on the bus: NMT start, the enable sequence per drive from its TPDO1, SYNC, the base's
// mode request and velocity commands.
class Host {
 public:
  explicit Host(MotorSim* sim) : sim_(sim) {}
  double t = 0.0;
  std::vector<can::CanFrame> received;  // every frame the nodes sent
  std::array<std::optional<DriveState>, 8> states{};
  std::array<std::uint16_t, 8> previous{};
  std::array<double, 8> targets{};
  double v = 0.0;
  bool send_base_commands = true;
  bool reset_faults = true;  // false: a drive in a fault state gets no RPDO (the host leaves it)

  void Cycle(const PlantState& plant) {
    auto send = [&](const can::CanFrame& f) { sim_->Receive(f, t); };
    for (int j = 1; j <= 7; ++j) {
      if (!states[j]) continue;
      if (!reset_faults && (states[j] == DriveState::kFault || states[j] == DriveState::kFaultReactionActive)) continue;
      const cia402::HostStep step = cia402::NextStepTowardsOperationEnabled(*states[j], previous[j]);
      previous[j] = step.controlword;
      send(*cia402::EncodeRpdo1({j, step.controlword, targets[j]}, {}, nullptr));
    }
    send(*canopen::EncodeSync({}, nullptr));
    if (send_base_commands) {
      if (step_ % 20 == 0) send(*base::EncodeModeRequest(base::ModeRequest::kCanCommand, kBaseNode, nullptr));
      send(*base::EncodeVelocityCommand({v, 0.0, counter_++}, kBaseNode, nullptr));
    }
    std::vector<can::CanFrame> out;
    sim_->Step(t, &plant, &out);
    for (const can::CanFrame& f : out) {
      received.push_back(f);
      const auto cob = canopen::ClassifyCobId(f.id, nullptr);
      if (!f.error && cob && cob->function == canopen::CanopenFunction::kTpdo1 && cob->node_id <= 7) {
        if (const auto tpdo = cia402::DecodeTpdo1(f, {}, nullptr)) {
          states[cob->node_id] = cia402::DecodeStatusword(tpdo->statusword, nullptr);
          positions[cob->node_id] = tpdo->position_rad;
        }
      }
    }
    t += 0.005;
    ++step_;
  }
  void Start() { sim_->Receive(*canopen::EncodeNmt({canopen::NmtCommand::kStartRemoteNode, 0}, nullptr), t); }
  std::array<double, 8> positions{};

 private:
  MotorSim* sim_;
  int step_ = 0;
  std::uint8_t counter_ = 0;
};

TEST(MotorSimTest, HostEnablesDrivesAndDrivesTheBase) {
  MotorSim sim({}, 0.0);
  Host host(&sim);
  const PlantState plant = Plant(0.3, 0.25);
  host.Cycle(plant);  // boot-up
  host.Start();
  host.v = 0.4;
  host.targets[1] = 0.7;
  host.targets[5] = -0.2;
  for (int i = 0; i < 40; ++i) host.Cycle(plant);
  for (int j = 1; j <= 7; ++j) EXPECT_EQ(sim.drive(j).state(), DriveState::kOperationEnabled) << "joint " << j;
  const ActuatorCommand command = sim.command();
  EXPECT_NEAR(command.v_mps, 0.4, 1e-9);
  EXPECT_NEAR(command.omega_radps, 0.0, 1e-9);
  ASSERT_EQ(command.qdot_radps.size(), 7);
  EXPECT_NEAR(command.qdot_radps[0], 0.7, 1e-4);
  EXPECT_NEAR(command.qdot_radps[4], -0.2, 1e-4);
  EXPECT_EQ(command.qdot_radps[1], 0.0);
  EXPECT_NEAR(host.positions[1], 0.25, 1e-6) << "TPDO1 carries the plant's joint";
  EXPECT_EQ(sim.base().mode(), base::BaseMode::kCanCommand);
  EXPECT_LE(sim.counts().frames_unhandled, 1) << "only the SYNC before the boot-up";
}

TEST(MotorSimTest, ScriptedDriveFaultGivesEmcyAndStopsThatJoint) {
  MotorSimOptions options;
  FaultEvent fault;
  fault.kind = FaultKind::kDriveFault;
  fault.joint = 2;
  fault.at_s = 0.3;
  options.faults.events = {fault};
  MotorSim sim(options, 0.0);
  Host host(&sim);
  const PlantState plant = Plant(0.0, 0.0);
  host.Cycle(plant);
  host.Start();
  host.targets[1] = host.targets[2] = 0.5;
  host.reset_faults = false;
  for (int i = 0; i < 50; ++i) host.Cycle(plant);  // to 0.25 s
  ASSERT_EQ(sim.drive(2).state(), DriveState::kOperationEnabled);
  const std::size_t before = host.received.size();
  for (int i = 0; i < 12; ++i) host.Cycle(plant);  // past 0.3 s
  int emcy_of_node2 = 0;
  for (std::size_t k = before; k < host.received.size(); ++k) {
    if (const auto emcy = canopen::DecodeEmcy(host.received[k], nullptr); emcy && emcy->node_id == 2) {
      ++emcy_of_node2;
      EXPECT_EQ(emcy->error_code, 0x5000);
    }
  }
  EXPECT_EQ(emcy_of_node2, 1);
  EXPECT_NE(sim.drive(2).state(), DriveState::kOperationEnabled);
  EXPECT_EQ(sim.drive(1).state(), DriveState::kOperationEnabled);
  for (int i = 0; i < 40; ++i) host.Cycle(plant);
  EXPECT_EQ(sim.command().qdot_radps[1], 0.0);
  EXPECT_NEAR(sim.command().qdot_radps[0], 0.5, 1e-4);
}

TEST(MotorSimTest, BusOffSilencesTheNodesAndTheBaseWatchdogStops) {
  MotorSim sim({}, 0.0);
  Host host(&sim);
  const PlantState plant = Plant(0.0, 0.0);
  host.Cycle(plant);
  host.Start();
  host.v = 0.5;
  for (int i = 0; i < 20; ++i) host.Cycle(plant);
  ASSERT_NEAR(sim.command().v_mps, 0.5, 1e-9);
  FaultEvent bus_off;
  bus_off.kind = FaultKind::kBusOff;
  bus_off.duration_s = 0.3;
  ASSERT_EQ(sim.Inject(bus_off, host.t), "");
  const std::size_t before = host.received.size();
  for (int i = 0; i < 50; ++i) host.Cycle(plant);  // 0.25 s
  ASSERT_GE(host.received.size(), before + 1);
  EXPECT_TRUE(host.received[before].error);
  EXPECT_TRUE(can::DecodeCanErrorFrame(host.received[before]).bus_off);
  EXPECT_EQ(host.received.size(), before + 1) << "nothing but the error frame while bus-off";
  EXPECT_EQ(sim.base().mode(), base::BaseMode::kQuickStop) << "no command reached the base: watchdog";
  for (int i = 0; i < 20; ++i) host.Cycle(plant);
  bool restarted = false;
  for (std::size_t k = before + 1; k < host.received.size(); ++k) {
    restarted = restarted || (host.received[k].error && can::DecodeCanErrorFrame(host.received[k]).restarted);
  }
  EXPECT_TRUE(restarted);
  EXPECT_GT(host.received.size(), before + 10) << "traffic resumes after the restart";
}

TEST(MotorSimTest, LostHeartbeatOfOneNodeOnly) {
  MotorSimOptions options;
  FaultEvent loss;
  loss.kind = FaultKind::kHeartbeatLoss;
  loss.joint = 3;
  loss.at_s = 0.5;
  loss.duration_s = 0.5;
  options.faults.events = {loss};
  MotorSim sim(options, 0.0);
  std::array<std::vector<double>, 8> heartbeats;  // per node: times
  std::vector<can::CanFrame> out;
  for (int k = 0; k <= 300; ++k) {  // 1.5 s, no host at all
    out.clear();
    const double t = k * 0.005;
    sim.Step(t, nullptr, &out);
    for (const can::CanFrame& f : out) {
      const auto hb = canopen::DecodeHeartbeat(f, nullptr);
      if (hb && hb->state != canopen::NmtState::kBootUp) heartbeats[hb->node_id].push_back(t);
    }
  }
  auto in_window = [](const std::vector<double>& times, double from, double to) {
    return std::count_if(times.begin(), times.end(), [&](double t) { return t >= from && t < to; });
  };
  EXPECT_EQ(in_window(heartbeats[3], 0.5, 1.0), 0);
  EXPECT_GE(in_window(heartbeats[4], 0.5, 1.0), 4);
  EXPECT_GE(in_window(heartbeats[3], 1.0, 1.5), 4) << "it produces again after the loss";
}

TEST(MotorSimTest, RejectsClashingNodeIds) {
  MotorSimOptions options;
  options.base.node_id = 3;
  EXPECT_NE(CheckMotorSimOptions(options), "");
  options = {};
  options.joint_node_ids = {1, 2, 3, 4, 5, 6, 6};
  EXPECT_NE(CheckMotorSimOptions(options), "");
  options = {};
  options.joint_node_ids[6] = 127;
  EXPECT_NE(CheckMotorSimOptions(options), "");
  EXPECT_THROW(MotorSim(options, 0.0), std::invalid_argument);
  EXPECT_EQ(CheckMotorSimOptions({}), "");
}

}  // namespace
}  // namespace topay::sim::motors
