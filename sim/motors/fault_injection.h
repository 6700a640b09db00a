#pragma once
// Fault injection of the motor simulator (docs/motorsim.md, "Fault injection"): what can be
// injected (FaultEvent), the scripted faults and link impairments from YAML
// (FaultInjectionOptions), and FaultInjector, which applies them at the nodes' side of the
// bus: frames lost at random in each direction (seeded), frames delayed (in bursts), a lost
// heartbeat of a drive, bus-off (an error frame on the bus, the nodes silent meanwhile) and the
// node faults (a drive's fault, the wheel controller's fault) it hands to MotorSim.
// Deterministic: the same options, seed, frames and times give the same losses.

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "core/common/random.h"
#include "drivers/can/can_error.h"
#include "drivers/can/can_frame.h"

namespace topay::sim::motors {

enum class FaultKind {
  kClear,          ///< run time only: clear loss, delay, heartbeat losses (not node faults)
  kDriveFault,     ///< joint's drive: EMCY + Fault (the host resets it)
  kHeartbeatLoss,  ///< joint's drive stops producing heartbeats for duration_s (0: for good)
  kBusOff,         ///< bus-off error frame, nodes silent for duration_s (> 0), restart frame
  kRxLoss,         ///< value percent of the frames to the nodes lost
  kTxLoss,         ///< value percent of the frames from the nodes lost
  kDelay,          ///< every frame (both ways) delayed by value ms for duration_s (0: for good)
  kBaseFault,      ///< the wheel controller raises fault `code` (1..10)
};

/// "clear", "drive_fault", "heartbeat_loss", "bus_off", "rx_loss", "tx_loss", "delay",
/// "base_fault" (the YAML names).
const char* FaultKindName(FaultKind kind);
/// The kind named `name`; false when it is none.
bool ParseFaultKind(const std::string& name, FaultKind* kind);

struct FaultEvent {
  FaultKind kind = FaultKind::kDriveFault;
  double at_s = 0.0;       ///< scripted: seconds after the simulator started (run time: now)
  int joint = 0;           ///< drive_fault, heartbeat_loss: joint 1..N
  double duration_s = 0.0; ///< heartbeat_loss, delay (0: until cleared); bus_off (> 0)
  double value = 0.0;      ///< rx_loss, tx_loss: percent 0..100; delay: ms >= 0
  int code = 0;            ///< drive_fault: EMCY error code (0: the drives' default); base_fault: 1..10
};

/// Empty when `event` is well formed for a robot with `num_joints` joints, else what is wrong
/// (e.g. "joint 9 is outside 1..7").
std::string CheckFaultEvent(const FaultEvent& event, int num_joints);

struct FaultInjectionOptions {
  std::uint64_t seed = 1;        ///< seed of the random frame losses
  double rx_loss_percent = 0.0;  ///< frames to the nodes lost, percent (0..100)
  double tx_loss_percent = 0.0;  ///< frames from the nodes lost, percent (0..100)
  double delay_ms = 0.0;         ///< added delay of every frame (both ways) while a burst is on, ms
  double delay_burst_s = 0.0;    ///< bursts of delay this long (0: always on) ...
  double delay_period_s = 1.0;   ///< ... one starting every period, s (> delay_burst_s)
  std::vector<FaultEvent> events;  ///< scripted faults, at their at_s
};

/// Empty when the options are valid for `num_joints` joints, else what is wrong.
std::string CheckFaultInjectionOptions(const FaultInjectionOptions& options, int num_joints);

/// Counts of one direction of the link.
struct LinkCounts {
  std::int64_t passed = 0;   ///< frames delivered
  std::int64_t lost = 0;     ///< dropped by the loss rate
  std::int64_t delayed = 0;  ///< delivered late (delay > 0)
  std::int64_t silenced = 0; ///< dropped while bus-off
};

/// One direction of the link: random loss and a FIFO delay (order kept).
class FrameLink {
 public:
  explicit FrameLink(std::uint64_t seed) : rng_(seed) {}
  /// A frame enters the link at now_s with the loss fraction and delay in force then.
  void Push(const can::CanFrame& frame, double now_s, double loss_fraction, double delay_s);
  /// The frames due at now_s, in the order pushed.
  std::vector<can::CanFrame> TakeDue(double now_s);
  /// Drops every frame in flight (bus-off), counted as silenced.
  void Silence();
  void CountSilenced() { ++counts_.silenced; }
  const LinkCounts& counts() const { return counts_; }

 private:
  struct InFlight {
    double due_s;
    can::CanFrame frame;
  };
  Rng rng_;
  std::deque<InFlight> queue_;
  double last_due_s_ = -1e300;
  LinkCounts counts_;
};

struct InjectorCounts {
  std::int64_t drive_faults = 0;
  std::int64_t base_faults = 0;
  std::int64_t heartbeat_losses = 0;
  std::int64_t bus_offs = 0;
  std::int64_t link_changes = 0;  ///< loss / delay changes and clears
  std::int64_t rejected = 0;      ///< malformed run-time faults
};

class FaultInjector {
 public:
  /// `options` must pass CheckFaultInjectionOptions (else std::invalid_argument).
  FaultInjector(const FaultInjectionOptions& options, int num_joints);

  /// A run-time fault, applied at now_s (its at_s is ignored). "" or why it was refused.
  std::string Inject(FaultEvent event, double now_s);

  /// What the nodes must do at now_s.
  struct Actions {
    std::vector<FaultEvent> node_faults;      ///< drive_fault / base_fault to apply now
    std::vector<can::CanFrame> error_frames;  ///< to put on the bus now (bus-off, restart)
  };
  /// Fires the scripted faults due by now_s, starts and ends bus-off and heartbeat losses.
  Actions Advance(double now_s);

  bool bus_off() const { return bus_off_; }
  /// True while joint's heartbeat is suppressed (1-based joint).
  bool HeartbeatSuppressed(int joint, double now_s) const;

  /// Frames towards the nodes (received from the bus) and from them (to send).
  void PushReceived(const can::CanFrame& frame, double now_s);
  std::vector<can::CanFrame> TakeReceived(double now_s) { return rx_.TakeDue(now_s); }
  void PushSent(const can::CanFrame& frame, double now_s);
  std::vector<can::CanFrame> TakeSent(double now_s) { return tx_.TakeDue(now_s); }

  double delay_s(double now_s) const;
  const LinkCounts& rx_counts() const { return rx_.counts(); }
  const LinkCounts& tx_counts() const { return tx_.counts(); }
  const InjectorCounts& counts() const { return counts_; }

 private:
  void Apply(const FaultEvent& event, double now_s, Actions* actions);

  FaultInjectionOptions options_;
  int num_joints_;
  std::vector<FaultEvent> scripted_;  // sorted by at_s
  std::size_t next_scripted_ = 0;
  FrameLink rx_, tx_;
  double rx_loss_ = 0.0, tx_loss_ = 0.0;      // fractions
  double runtime_delay_s_ = -1.0;             // < 0: none (the options' bursts apply)
  double runtime_delay_until_s_ = 0.0;        // 0: until cleared
  bool bus_off_ = false;
  double bus_off_until_s_ = 0.0;
  std::vector<double> heartbeat_lost_until_s_;  // per joint: < 0 none, 0 for good, else until
  std::vector<FaultEvent> pending_runtime_;     // node faults injected at run time
  InjectorCounts counts_;
};

}  // namespace topay::sim::motors
