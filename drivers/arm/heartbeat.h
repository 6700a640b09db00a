#pragma once
// Heartbeat (CiA 301 §7.2.8.3.2.2): COB-ID 0x700 + node, DLC 1, the producer's NMT state; the
// boot-up message (§7.2.8.3.3) is the same frame with state 0x00. HeartbeatConsumer checks a
// producer's heartbeats against the consumer heartbeat time (object 0x1016).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

/// NMT states as coded in the heartbeat byte (CiA 301 Table 62).
enum class NmtState : std::uint8_t {
  kBootUp = 0x00,
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
};

/// "boot-up", "stopped", "operational", "pre-operational".
std::string_view ToString(NmtState state);

struct Heartbeat {
  int node_id = 1;  ///< 1..127.
  NmtState state = NmtState::kBootUp;
};

/// nullopt with *error for a node id outside 1..127 or an unknown state value.
std::optional<can::CanFrame> EncodeHeartbeat(const Heartbeat& heartbeat, std::string* error);

/// nullopt with *error naming the frame for another id, DLC other than 1, or a state byte that is
/// none of 0x00, 0x04, 0x05, 0x7F (the node-guarding toggle bit 7 is not used by heartbeats).
std::optional<Heartbeat> DecodeHeartbeat(const can::CanFrame& frame, std::string* error);

/// Heartbeat production (CiA 301 §7.2.8.2.2.1, object 0x1017): a heartbeat is due every
/// producer time; a producer time of 0 disables it. The first one is due at once (after the
/// boot-up message the caller sends itself). Times are seconds on a monotonic clock.
class HeartbeatProducer {
 public:
  /// `producer_time_s` >= 0 (0 disables production).
  explicit HeartbeatProducer(double producer_time_s) : producer_time_s_(producer_time_s) {}

  /// True when a heartbeat should be sent at `now_s`.
  bool IsDue(double now_s) const;
  /// Records that a heartbeat was sent at `now_s`; the next one is due a period later.
  void OnSent(double now_s) { last_sent_s_ = now_s; }

 private:
  double producer_time_s_ = 0.0;
  std::optional<double> last_sent_s_;
};

/// Heartbeat consumption for one producer (CiA 301 §7.2.8.2.2.2): the producer is lost when no
/// heartbeat came within the consumer time since the previous one. Monitoring starts with the
/// first heartbeat received; a consumer time of 0 disables it (never lost). Times are seconds on
/// any monotonic clock the caller uses.
class HeartbeatConsumer {
 public:
  /// `consumer_time_s` >= 0 (0 disables the check).
  explicit HeartbeatConsumer(double consumer_time_s) : consumer_time_s_(consumer_time_s) {}

  /// Records a heartbeat (or boot-up) of the producer received at `time_s`.
  void OnHeartbeat(NmtState state, double time_s);

  /// True when monitoring started and more than the consumer time passed since the last
  /// heartbeat at `now_s` (a heartbeat event, CiA 301 EMCY 0x8130 on the consumer).
  bool IsLost(double now_s) const;

  /// The producer's last reported state, if any heartbeat came.
  std::optional<NmtState> last_state() const { return last_state_; }
  /// True when the last message was a boot-up (the producer restarted: it must be configured).
  bool rebooted() const { return last_state_ == NmtState::kBootUp; }

 private:
  double consumer_time_s_ = 0.0;
  std::optional<double> last_time_s_;
  std::optional<NmtState> last_state_;
};

}  // namespace topay::canopen
