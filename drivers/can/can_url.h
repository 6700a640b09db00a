#pragma once
// CAN bus URLs (`--can URL` of every CAN process) and the factory that opens the bus they name.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "drivers/can/can_bus.h"

namespace topay::can {

/// A parsed CAN bus URL:
///   socketcan://IFACE       the SocketCAN interface IFACE (e.g. can0, vcan0);
///   udp://GROUP:PORT        the user-space bus on IPv4 multicast group GROUP (224.0.0.0/4),
///                           UDP port PORT (1-65535), e.g. udp://239.255.1.1:9000.
struct CanUrl {
  enum class Scheme { kSocketCan, kUdp };
  Scheme scheme = Scheme::kSocketCan;
  std::string interface;       ///< socketcan: the interface name (1-15 characters).
  std::string group;           ///< udp: the multicast group, dotted quad.
  std::uint16_t port = 0;      ///< udp: the UDP port.

  /// The canonical text form, e.g. "socketcan://can0".
  std::string ToString() const;
};

/// Parses `text`; nullopt with *error (when not null) naming the bad part, e.g.
/// "udp://10.0.0.1:9000: group 10.0.0.1 is not an IPv4 multicast address (224.0.0.0/4)".
std::optional<CanUrl> ParseCanUrl(std::string_view text, std::string* error);

/// Opens the bus `url` names with `options`. Returns nullptr with *error (when not null) saying
/// why: a bad URL, bad options, or the backend's failure (e.g. "socketcan://can0: AF_CAN not
/// supported by this kernel ...").
///
/// A udp:// bus joins a multicast group: open it only inside a private network namespace (a
/// graph's or a test's, docs/can.md), never in a machine's own namespace.
std::unique_ptr<CanBus> OpenCanBus(std::string_view url, const CanBusOptions& options, std::string* error);

}  // namespace topay::can
