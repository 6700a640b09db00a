#pragma once
// The SDO writes that configure one arm joint drive at start-up, as data (docs/cia402.md): the
// host sends them in order, in NMT Pre-operational, one expedited download each, waiting for
// each confirmation (an abort stops the sequence), then starts the node (NMT start).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/arm/sdo.h"

namespace topay::cia402 {

/// One write: object, value and its size in bytes (the object's data type).
struct SdoWrite {
  canopen::ObjectAddress address;
  std::uint32_t value = 0;
  int size_bytes = 4;      ///< 1, 2 or 4.
  std::string_view what;   ///< e.g. "TPDO1 mapping 1: statusword 0x6041".
};

/// Modes of operation (object 0x6060, CiA 402-2 §6.3.1).
namespace mode {
inline constexpr std::int8_t kProfilePosition = 1;
inline constexpr std::int8_t kProfileVelocity = 3;
inline constexpr std::int8_t kCyclicSynchronousPosition = 8;
inline constexpr std::int8_t kCyclicSynchronousVelocity = 9;
}  // namespace mode

struct StartupOptions {
  /// Producer heartbeat time (0x1017) of the drive: 100 ms.
  int producer_heartbeat_ms = 100;
  /// Consumer heartbeat time (0x1016:01) of the host's heartbeat: 3 host periods (the host
  /// produces every 100 ms), so one lost frame is not a heartbeat event.
  int consumer_heartbeat_ms = 300;
  /// The host's (bridge's) node id, whose heartbeat the drive consumes.
  int host_node_id = 127;
  /// The SYNC period (the control cycle), written to the interpolation time period 0x60C2 that
  /// the cyclic synchronous modes use: 10 ms (100 Hz).
  int sync_period_ms = 10;
  /// Mode of operation 0x6060: cyclic synchronous velocity (9), see docs/cia402.md.
  std::int8_t mode_of_operation = mode::kCyclicSynchronousVelocity;
  /// Map RPDO2 (target position 0x607A) too; disabled by default (velocity control only).
  bool map_target_position = false;
  /// TPDO2 (velocity actual) goes out on every n-th SYNC: its transmission type (CiA 301 §7.5.2.37,
  /// 1..240 = synchronous, every n-th SYNC). 2: velocity at half the SYNC rate (100 Hz at a 5 ms
  /// cycle), which keeps the bus load of base + 7 drives at 200 Hz under 50 % at 1 Mbit/s
  /// (docs/cia402.md); statusword and position (TPDO1) stay on every SYNC.
  int tpdo2_every_n_syncs = 2;
  /// RPDO1's deadline monitoring (its event timer 0x1400:05, CiA 301 §7.5.2.35): a drive that
  /// has had no RPDO1 for this long signals EMCY 0x8250 (RPDO timeout) and stops by its fault
  /// reaction. 50 ms: ten 5 ms host cycles, so 10 % frame loss or a 20 ms delay never trips it,
  /// while a dead host stops the arm within 100 ms (the heartbeat event alone takes
  /// consumer_heartbeat_ms). 0: not monitored.
  int rpdo_deadline_ms = 50;
};

/// The start-up writes for a drive, in order:
///  1. for RPDO1, RPDO2, TPDO1, TPDO2 (CiA 301 §7.5.2.35-38, objects 0x1400/0x1600,
///     0x1800/0x1A00, and the PDO mapping procedure of §7.2.2.2.4): invalidate the PDO (COB-ID bit 31 set), clear the mapping
///     (sub 0 = 0), write the mapped objects, set their number, set the transmission type to
///     synchronous (1: every SYNC; TPDO2: every tpdo2_every_n_syncs-th SYNC), RPDO1's event
///     timer (sub 5) to rpdo_deadline_ms, make the PDO valid again with the default COB-ID
///     (TPDOs with bit 30, no RTR); an unused RPDO2 stays invalid;
///  2. RPDO3/4 and TPDO3/4 invalid;
///  3. producer heartbeat time 0x1017, consumer heartbeat time 0x1016:01 (host node << 16 | ms);
///  4. interpolation time period 0x60C2:01/02 (sync_period_ms, exponent -3);
///  5. mode of operation 0x6060.
/// nullopt with *error (when not null) for a node id or host node id outside 1..127, equal node
/// ids, heartbeat times or an RPDO deadline outside 0..65535 ms, a SYNC period outside 1..255 ms, or a mode other
/// than 3, 8 or 9 (the modes whose setpoints this layout carries).
std::optional<std::vector<SdoWrite>> StartupSdoWrites(int node_id, const StartupOptions& options,
                                                      std::string* error);

/// The download request of `write` to `node_id` (for EncodeSdoDownloadRequest).
canopen::SdoDownloadRequest ToDownloadRequest(int node_id, const SdoWrite& write);

/// A PDO mapping entry (CiA 301 §7.5.2.36): index << 16 | subindex << 8 | length in bits.
std::uint32_t PdoMappingEntry(canopen::ObjectAddress address, int size_bits);

}  // namespace topay::cia402
