#pragma once
// CANopen COB-IDs of the predefined connection set (CiA 301 §7.3.3, Table 73): the base id of
// each function, the COB-ID of a node's object, and the classification of a received 11-bit id
// into (function, node id).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

inline constexpr int kMinNodeId = 1;    ///< CiA 301 §7.2.2: node ids 1..127.
inline constexpr int kMaxNodeId = 127;

/// The communication objects this stack uses. TIME (0x100) and the other ids are not used.
enum class CanopenFunction {
  kNmt,        ///< 0x000: NMT node control (master -> nodes).
  kSync,       ///< 0x080: SYNC.
  kEmcy,       ///< 0x080 + node: emergency.
  kTpdo1,      ///< 0x180 + node (drive -> host).
  kRpdo1,      ///< 0x200 + node (host -> drive).
  kTpdo2,      ///< 0x280 + node.
  kRpdo2,      ///< 0x300 + node.
  kTpdo3,      ///< 0x380 + node.
  kRpdo3,      ///< 0x400 + node.
  kTpdo4,      ///< 0x480 + node.
  kRpdo4,      ///< 0x500 + node.
  kSdoTx,      ///< 0x580 + node: SDO server -> client (the drive's replies).
  kSdoRx,      ///< 0x600 + node: SDO client -> server (the host's requests).
  kHeartbeat,  ///< 0x700 + node: NMT error control (heartbeat, boot-up).
};

/// "NMT", "SYNC", "EMCY", "TPDO1", ..., "SDO tx", "SDO rx", "heartbeat".
std::string_view ToString(CanopenFunction function);

/// The function code base: 0x000, 0x080, 0x080, 0x180, 0x200, ..., 0x700.
std::uint32_t FunctionBaseCobId(CanopenFunction function);

/// True for the functions whose COB-ID carries a node id (all but NMT and SYNC).
constexpr bool HasNodeId(CanopenFunction function) {
  return function != CanopenFunction::kNmt && function != CanopenFunction::kSync;
}

/// Empty when 1 <= node_id <= 127, else e.g. "node id 128 is outside 1..127".
std::string CheckNodeId(int node_id);

/// The COB-ID of `function` for `node_id`: the base id for NMT and SYNC (node_id ignored), else
/// base + node_id. nullopt with *error (when not null) for a node id outside 1..127.
std::optional<std::uint32_t> CobIdOf(CanopenFunction function, int node_id, std::string* error);

/// A classified COB-ID. node_id is 0 for NMT and SYNC.
struct CobIdClass {
  CanopenFunction function = CanopenFunction::kNmt;
  int node_id = 0;
};

/// The function and node of an 11-bit id. nullopt with *error for ids above 0x7FF, node 0 in a
/// node-addressed range (e.g. 0x180), and ids outside the predefined connection set this stack
/// uses (0x001-0x07F, TIME 0x100-0x17F, 0x680-0x6FF, above 0x77F).
std::optional<CobIdClass> ClassifyCobId(std::uint32_t cob_id, std::string* error);

/// Checks that `frame` is a CANopen frame of `function` with a DLC in [min_dlc, max_dlc]: a valid
/// standard data frame (not extended, remote or error), its id classified as `function`.
/// Returns the node id (0 for NMT and SYNC); nullopt with *error naming `what` and the frame,
/// e.g. "heartbeat frame '701#0500': DLC 2, expected 1".
std::optional<int> CheckCanopenFrame(const can::CanFrame& frame, CanopenFunction function,
                                     int min_dlc, int max_dlc, std::string_view what,
                                     std::string* error);

/// "<what> frame '<cansend text>': <problem>", the prefix of every decoder error.
std::string FrameError(std::string_view what, const can::CanFrame& frame,
                       std::string_view problem);

/// Sets *error (when not null) to `message`; returns nullopt of any type for `return Fail(..)`.
inline std::nullopt_t Fail(std::string* error, std::string message) {
  if (error != nullptr) *error = std::move(message);
  return std::nullopt;
}

}  // namespace topay::canopen
