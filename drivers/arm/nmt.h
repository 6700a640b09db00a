#pragma once
// NMT node control (CiA 301 §7.2.8.3.1): COB-ID 0x000, DLC 2, byte 0 the command specifier,
// byte 1 the addressed node id (0 = all nodes).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

/// NMT command specifiers (CiA 301 §7.2.8.3.1.1-5).
enum class NmtCommand : std::uint8_t {
  kStartRemoteNode = 0x01,        ///< -> Operational.
  kStopRemoteNode = 0x02,         ///< -> Stopped.
  kEnterPreOperational = 0x80,    ///< -> Pre-operational.
  kResetNode = 0x81,              ///< Application reset, then boot-up.
  kResetCommunication = 0x82,     ///< Communication reset, then boot-up.
};

inline constexpr int kNmtAllNodes = 0;  ///< Node id 0 in an NMT command addresses every node.

/// "start", "stop", "enter pre-operational", "reset node", "reset communication".
std::string_view ToString(NmtCommand command);

struct NmtMessage {
  NmtCommand command = NmtCommand::kStartRemoteNode;
  int node_id = kNmtAllNodes;  ///< 1..127, or 0 for all nodes.
};

/// The NMT frame; nullopt with *error for a node id outside 0..127 or an unknown command value.
std::optional<can::CanFrame> EncodeNmt(const NmtMessage& message, std::string* error);

/// The NMT command in `frame`; nullopt with *error naming the frame for another id, a DLC other
/// than 2, an unknown command specifier or a node id above 127.
std::optional<NmtMessage> DecodeNmt(const can::CanFrame& frame, std::string* error);

}  // namespace topay::canopen
