// Property, "limits at the edge": over 200 seeded adversarial command streams of 2-4 s each, on
// the in-memory bus with the base and drive peers (canbridge_rig.h) and the shipped options
// (config/canbridge/canbridge.yaml, the robot of config/robot/), every frame topay-canbridge sends,
// in every state it passes through (starting, enabling, running, stopped, fault, recovering),
// keeps the envelope of sent_frame_limits.h: velocities within the robot's limits, changes
// between consecutive frames within the acceleration limits over the time between them, zero
// outside RUNNING and after the command timeout. The streams mix uniform and extreme values
// (NaN, +-inf, denormals, 1e300, exactly and just beyond the limits), sign flips every cycle,
// bursts of commands within one cycle, timestamps going backwards, wrong joint counts, gaps
// longer than the command timeout, and drive faults (with operator resets), bus-off and restart,
// lost drive heartbeats, a silent or faulted base, drive power cycles and the interface going
// down. Also: after every gap the zero commands and quick stops were on the bus within
// command_timeout_s of the last valid command, no NaN ever reached the limiter's output, and
// every state and disturbance was actually exercised.
#include <gtest/gtest.h>
#include <linux/can/error.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_drive_model.h"
#include "drivers/arm/cia402_state.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/can/can_error.h"
#include "procs/canbridge/canbridge_node.h"
#include "procs/canbridge/canbridge_options.h"
#include "tests/procs/canbridge/canbridge_rig.h"
#include "tests/procs/canbridge/sent_frame_limits.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"

namespace topay::canbridge::test {
namespace {

constexpr int kSeeds = 200;
// Healed, with zero commands: hold 0.5 s, start-up (a retry after 1 s at worst), enable.
constexpr double kRecoveryLimitS = 4.0;

CanbridgeOptions ShippedOptions() {
  return LoadCanbridgeOptions(std::string(TOPAY_SOURCE_DIR) + "/config/canbridge/canbridge.yaml");
}

// What the runs exercised, summed over the seeds.
struct Coverage {
  std::int64_t frames[7] = {};
  std::int64_t stale_values = 0;
  std::int64_t stops = 0;
  std::int64_t gaps_checked = 0;
  std::int64_t commands_rejected = 0;
  std::int64_t clamps = 0;
  std::int64_t faults_reset = 0;
  std::int64_t bus_offs = 0;
  std::int64_t recoveries = 0;
};

// One frame the bridge sent, with the time it was given.
struct SentFrame {
  double time_s;
  can::CanFrame frame;
};

// The rig with every frame the bridge sends checked against the envelope (ADD_FAILURE on a
// violation) and kept with the time it was sent at.
class CheckedRig {
 public:
  explicit CheckedRig(const CanbridgeOptions& options) : rig(options), limits_(options, rig.node.limiter().limits()) {}

  void Tick() {
    const double now_s = rig.t;
    rig.node.Cycle(now_s, static_cast<std::int64_t>(now_s * 1e6));
    CheckSent(now_s);
    rig.peers.Step(now_s);
    rig.t += rig.options.cycle_period_s;
  }

  void Command(const control_command_t& msg, double now_s) {
    const std::int64_t before = rig.node.commands_received();
    rig.node.OnCommand(msg, now_s);
    if (rig.node.commands_received() != before) {
      limits_.OnValidCommand(now_s);
      last_valid_command_s = now_s;
    }
    CheckSent(now_s);
  }

  /// A FAULT_RESET from the operator: "" when accepted.
  std::string FaultReset() {
    drive_command_t msg{};
    msg.command = drive_command_t::FAULT_RESET;
    msg.source = "property test";
    return rig.node.OnDriveCommand(msg, rig.t);
  }

  bool failed() const { return violations_ > 0; }
  const SentFrameLimits& limits() const { return limits_; }

  Rig rig;
  std::vector<SentFrame> sent;
  double last_valid_command_s = -1.0;

 private:
  void CheckSent(double now_s) {
    for (const auto& [stamp_ns, frame] : rig.bridge_bus.sent) {
      const std::string problem = limits_.Check(frame, now_s, rig.node.state());
      if (!problem.empty() && ++violations_ <= 5) ADD_FAILURE() << problem;
      sent.push_back({now_s, frame});
    }
    rig.bridge_bus.sent.clear();
    limits_.OnState(rig.node.state(), now_s);
    const DeviceCommand& last = rig.node.limiter().last();
    bool finite = std::isfinite(last.v_mps) && std::isfinite(last.omega_radps);
    for (const double q : last.qdot_radps) finite = finite && std::isfinite(q);
    if (!finite && ++violations_ <= 5) ADD_FAILURE() << "a non-finite value reached the limiter's output";
  }

  SentFrameLimits limits_;
  int violations_ = 0;
};

// How the commands of an episode are made.
enum class Content {
  kUniform,      // every value uniform in +-2x its limit
  kExtreme,      // NaN, +-inf, denormals, 1e300, +-0, exactly and just beyond the limits
  kSignFlip,     // +-2x the limits, the sign flipping every cycle
  kBurst,        // 2-6 commands within one cycle, extreme values, times in any order
  kBackwards,    // timestamps (and utime) going backwards, up to 50 ms
  kWrongJoints,  // malformed messages among good ones
  kZero,         // zero commands (what every recovery waits for)
  kNone,         // a gap: no command at all
};

// What happens to the devices or the bus at an episode's start (and is undone within it).
enum class Disturbance {
  kNone,
  kDriveFault,     // EMCY + Fault; the operator resets it at the episode's end
  kBaseFault,      // the base's fault frame; reset likewise
  kBusOff,         // bus-off error frame, restart after 50-300 ms
  kHeartbeatLoss,  // a drive silent for 0.2-0.7 s
  kBaseSilent,     // the base silent for 0.1-0.4 s
  kPowerCycle,     // a drive restarts (boot-up while operational)
  kInterfaceDown,  // the bridge's interface down for 50-200 ms
};

class AdversarialRun {
 public:
  AdversarialRun(unsigned seed, const CanbridgeOptions& options)
      : checked_(options), rng_(seed), limits_(rig().node.limiter().limits()) {}

  void Run(Coverage* coverage) {
    // Start-up (starting, enabling) checked like the rest; a stream meant for a stopped robot
    // gets zeros, so that it starts.
    for (int i = 0; i < 600 && rig().node.state() != BridgeState::kRunning; ++i) checked_.Tick();
    ASSERT_EQ(rig().node.state(), BridgeState::kRunning) << rig().node.stop_reason();
    const double end_s = rig().t + std::uniform_real_distribution<double>(2.0, 4.0)(rng_);
    while (rig().t < end_s && !checked_.failed()) Episode(coverage);
    for (int s = 0; s < 7; ++s) coverage->frames[s] += checked_.limits().frames_in(static_cast<BridgeState>(s));
    coverage->stale_values += checked_.limits().stale_values_checked();
    coverage->stops += checked_.limits().stops_seen();
    coverage->commands_rejected += rig().node.commands_rejected();
    coverage->clamps += rig().node.limiter().clamp_count();
  }

 private:
  Rig& rig() { return checked_.rig; }
  double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int Pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  bool Chance(double p) { return std::bernoulli_distribution(p)(rng_); }

  void Episode(Coverage* coverage) {
    const Content content = static_cast<Content>(Pick(8));
    const Disturbance disturbance = Chance(0.4) ? static_cast<Disturbance>(1 + Pick(7)) : Disturbance::kNone;
    const double duration_s =
        content == Content::kNone ? Uniform(rig().options.command_timeout_s + 0.02, 0.6) : Uniform(0.1, 0.6);
    const double start_s = rig().t;
    const double undo_s = start_s + Uniform(0.05, std::min(duration_s, 0.7));
    const bool was_running = rig().node.state() == BridgeState::kRunning;
    const double gap_from_s = checked_.last_valid_command_s;
    const std::size_t sent_before = checked_.sent.size();
    const int drive = Pick(static_cast<int>(rig().peers.drives.size()));
    Disturb(disturbance, drive, coverage);
    bool undone = false;
    for (int cycle = 0; rig().t < start_s + duration_s; ++cycle) {
      if (!undone && rig().t >= undo_s) {
        Undo(disturbance, drive);
        undone = true;
      }
      Commands(content, cycle);
      checked_.Tick();
    }
    if (!undone) Undo(disturbance, drive);
    if (content == Content::kNone && was_running && disturbance == Disturbance::kNone && gap_from_s >= 0.0) {
      CheckStoppedWithinTimeout(gap_from_s, sent_before);
      ++coverage->gaps_checked;
    }
    // Recovery needs zero commands (a fault the operator's reset too): mostly given, so that the
    // runs keep coming back to RUNNING through RECOVERING.
    if (rig().node.state() != BridgeState::kRunning && Chance(0.8)) Recover(coverage);
  }

  // Zero commands (and the operator's reset in FAULT) after the disturbance was undone: the
  // bridge runs again within kRecoveryLimitS.
  void Recover(Coverage* coverage) {
    const double until_s = rig().t + kRecoveryLimitS;
    bool reset = false;
    while (rig().t < until_s && rig().node.state() != BridgeState::kRunning && !checked_.failed()) {
      Commands(Content::kZero, 0);
      if (!reset && rig().node.state() == BridgeState::kFault && checked_.FaultReset().empty()) {
        reset = true;
        ++coverage->faults_reset;
      }
      checked_.Tick();
    }
    EXPECT_EQ(rig().node.state(), BridgeState::kRunning)
        << "not running again " << kRecoveryLimitS
        << " s after the disturbance was undone: " << rig().node.stop_reason();
    ++coverage->recoveries;
  }

  void Disturb(Disturbance disturbance, int drive, Coverage* coverage) {
    std::vector<can::CanFrame> out;
    switch (disturbance) {
      case Disturbance::kNone:
        break;
      case Disturbance::kDriveFault:
        rig().peers.drives[drive].Fault(0x2310, &out);
        break;
      case Disturbance::kBaseFault:
        rig().peers.base.RaiseFault(base::BaseFault::kOverCurrent, rig().t, &out);
        break;
      case Disturbance::kBusOff:
        rig().bridge_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_BUSOFF));
        ++coverage->bus_offs;
        break;
      case Disturbance::kHeartbeatLoss:
        rig().peers.drives[drive].silent = true;
        break;
      case Disturbance::kBaseSilent:
        rig().peers.base.silent = true;
        break;
      case Disturbance::kPowerCycle:
        rig().peers.drives[drive].model = cia402::DriveModel{};
        rig().peers.drives[drive].PowerOn(&out);
        break;
      case Disturbance::kInterfaceDown:
        rig().bridge_bus.down = true;
        break;
    }
    rig().peers.Send(out);
  }

  void Undo(Disturbance disturbance, int drive) {
    switch (disturbance) {
      case Disturbance::kBusOff:
        rig().bridge_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_RESTARTED));
        break;
      case Disturbance::kHeartbeatLoss:
        rig().peers.drives[drive].silent = false;
        break;
      case Disturbance::kBaseSilent:
        rig().peers.base.silent = false;
        break;
      case Disturbance::kInterfaceDown:
        rig().bridge_bus.down = false;
        break;
      default:
        break;
    }
  }

  // A value for a field whose limit is `limit`.
  double Extreme(double limit) {
    const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             1e300,
                             -1e300,
                             0.0,
                             -0.0,
                             limit,
                             -limit,
                             std::nextafter(limit, 2 * limit),
                             -std::nextafter(limit, 2 * limit),
                             limit * (1 + 1e-9),
                             std::numeric_limits<double>::max()};
    return values[Pick(static_cast<int>(std::size(values)))];
  }

  control_command_t Message(double v, double omega, const std::vector<double>& qdot) {
    control_command_t msg{};
    msg.utime = static_cast<std::int64_t>(rig().t * 1e6);
    msg.v_mps = v;
    msg.omega_radps = omega;
    msg.num_joints = static_cast<std::int32_t>(qdot.size());
    msg.qdot_radps = qdot;
    return msg;
  }

  // A command with each value made by `value(limit)`.
  template <class Value>
  control_command_t Made(Value value) {
    std::vector<double> qdot;
    for (const double limit : limits_.qd_max_radps) qdot.push_back(value(limit));
    const double v = value(limits_.v_max_mps);
    const double omega = value(limits_.omega_max_radps);
    return Message(v, omega, qdot);
  }

  void Commands(Content content, int cycle) {
    const double now_s = rig().t;
    switch (content) {
      case Content::kUniform:
        checked_.Command(Made([&](double limit) { return Uniform(-2 * limit, 2 * limit); }), now_s);
        break;
      case Content::kExtreme:
        checked_.Command(Made([&](double limit) { return Chance(0.5) ? Extreme(limit) : Uniform(-limit, limit); }),
                         now_s);
        break;
      case Content::kSignFlip: {
        const double sign = cycle % 2 == 0 ? 2.0 : -2.0;
        checked_.Command(Made([&](double limit) { return sign * limit; }), now_s);
        break;
      }
      case Content::kBurst: {
        const int n = 2 + Pick(5);
        for (int k = 0; k < n; ++k) {
          const double at_s = now_s - rig().options.cycle_period_s + Uniform(0.0, 1.0) * rig().options.cycle_period_s;
          checked_.Command(
              Made([&](double limit) { return Chance(0.3) ? Extreme(limit) : (Chance(0.5) ? limit : -limit); }), at_s);
        }
        break;
      }
      case Content::kBackwards: {
        control_command_t msg = Made([&](double limit) { return Uniform(-1.5 * limit, 1.5 * limit); });
        msg.utime -= static_cast<std::int64_t>(Uniform(0.0, 1e6));
        checked_.Command(msg, now_s - Uniform(0.0, 0.05));
        break;
      }
      case Content::kWrongJoints: {
        control_command_t msg = Made([&](double limit) { return Uniform(-limit, limit); });
        switch (Pick(5)) {
          case 0:
            msg.num_joints += 1;
            msg.qdot_radps.push_back(0.1);
            break;
          case 1:
            msg.num_joints -= 1;
            msg.qdot_radps.pop_back();
            break;
          case 2:
            msg.qdot_radps.pop_back();
            break;  // the count right, the array short
          case 3:
            msg.qdot_radps[static_cast<std::size_t>(Pick(msg.num_joints))] = std::nan("");
            break;
          default:
            break;  // a good one among them
        }
        checked_.Command(msg, now_s);
        break;
      }
      case Content::kZero:
        checked_.Command(Made([](double) { return 0.0; }), now_s);
        break;
      case Content::kNone:
        break;
    }
  }

  // After a gap that started while running, the zero velocity command and each drive's zero,
  // non-enabling RPDO1 were on the bus within command_timeout_s of the last valid command.
  void CheckStoppedWithinTimeout(double last_command_s, std::size_t first) {
    const double deadline_s = last_command_s + rig().options.command_timeout_s + 1e-6;
    const std::uint32_t base_velocity_id =
        base::FrameId(base::BaseFrameKind::kVelocityCommand, rig().options.base.node_id);
    bool base_stopped = false;
    std::vector<bool> drive_stopped(rig().options.drives.node_ids.size(), false);
    for (std::size_t i = first; i < checked_.sent.size() && checked_.sent[i].time_s <= deadline_s; ++i) {
      const can::CanFrame& frame = checked_.sent[i].frame;
      if (frame.id == base_velocity_id) {
        const auto command = base::DecodeVelocityCommand(frame, rig().options.base.node_id, std::nullopt, nullptr);
        base_stopped = base_stopped || (command && command->v_m_per_s == 0.0 && command->omega_rad_per_s == 0.0);
      }
      for (std::size_t k = 0; k < drive_stopped.size(); ++k) {
        if (frame.id !=
            *canopen::CobIdOf(canopen::CanopenFunction::kRpdo1, rig().options.drives.node_ids[k], nullptr)) {
          continue;
        }
        const auto pdo = cia402::DecodeRpdo1(frame, rig().options.drives.units, nullptr);
        drive_stopped[k] = drive_stopped[k] ||
                           (pdo && pdo->target_velocity_rad_per_s == 0.0 &&
                            cia402::DecodeControlwordCommand(pdo->controlword) != cia402::Command::kEnableOperation);
      }
    }
    EXPECT_TRUE(base_stopped) << "no zero base velocity command within the command timeout of " << last_command_s;
    for (std::size_t k = 0; k < drive_stopped.size(); ++k) {
      EXPECT_TRUE(drive_stopped[k]) << "no quick stop RPDO1 to node " << rig().options.drives.node_ids[k]
                                    << " within the command timeout of " << last_command_s;
    }
  }

  CheckedRig checked_;
  std::mt19937 rng_;
  CommandLimits limits_;
};

TEST(CommandLimitsPropertyTest, EveryFrameInEveryStateKeepsTheLimits) {
  spdlog::set_level(spdlog::level::off);  // the bridge reports every stop, recovery and refused send
  const CanbridgeOptions options = ShippedOptions();
  const auto started = std::chrono::steady_clock::now();
  Coverage coverage;
  for (int seed = 1; seed <= kSeeds && !HasFailure(); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    AdversarialRun(static_cast<unsigned>(seed), options).Run(&coverage);
  }
  spdlog::set_level(spdlog::level::info);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf(
      "%d seeds in %.1f s: frames starting %lld, enabling %lld, running %lld, stopped %lld, fault %lld, "
      "recovering %lld; stops %lld, gaps checked %lld, zero values after the timeout %lld, commands "
      "rejected %lld, clamps %lld, fault resets %lld, bus-offs %lld, recoveries %lld\n",
      kSeeds, seconds, static_cast<long long>(coverage.frames[0]), static_cast<long long>(coverage.frames[1]),
      static_cast<long long>(coverage.frames[2]), static_cast<long long>(coverage.frames[3]),
      static_cast<long long>(coverage.frames[4]), static_cast<long long>(coverage.frames[5]),
      static_cast<long long>(coverage.stops), static_cast<long long>(coverage.gaps_checked),
      static_cast<long long>(coverage.stale_values), static_cast<long long>(coverage.commands_rejected),
      static_cast<long long>(coverage.clamps), static_cast<long long>(coverage.faults_reset),
      static_cast<long long>(coverage.bus_offs), static_cast<long long>(coverage.recoveries));
  // Every state and every kind of trouble was exercised (else the property says little).
  for (const BridgeState state : {BridgeState::kStarting, BridgeState::kEnabling, BridgeState::kRunning,
                                  BridgeState::kStopped, BridgeState::kFault, BridgeState::kRecovering}) {
    EXPECT_GT(coverage.frames[static_cast<int>(state)], 1000) << ToString(state);
  }
  EXPECT_GT(coverage.stops, 100);
  EXPECT_GT(coverage.gaps_checked, 20);
  EXPECT_GT(coverage.stale_values, 1000);
  EXPECT_GT(coverage.commands_rejected, 1000);
  EXPECT_GT(coverage.clamps, 1000);
  EXPECT_GT(coverage.faults_reset, 20);
  EXPECT_GT(coverage.bus_offs, 20);
  EXPECT_GT(coverage.recoveries, 200);
}

}  // namespace
}  // namespace topay::canbridge::test
