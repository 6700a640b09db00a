#pragma once
// The base protocol's frame identifiers (docs/base_protocol.md): 11-bit ids made of a function
// base plus the controller's node id (1..127), as in CANopen's predefined connection set.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::base {

/// Every frame of the protocol. The numeric value is the function base of the 11-bit id.
enum class BaseFrameKind : std::uint32_t {
  kFault = 0x080,            ///< base -> host, on event: a fault was raised.
  kModeRequest = 0x100,      ///< host -> base, on demand: mode switch.
  kStatus = 0x180,           ///< base -> host, 20 Hz and on change: mode, faults, battery.
  kVelocityCommand = 0x200,  ///< host -> base, at the control rate (200 Hz): v, omega.
  kWheelSpeeds = 0x280,      ///< base -> host, 100 Hz: measured wheel speeds.
  kOdometry = 0x300,         ///< base -> host, 100 Hz: wheel encoder tick counts.
};

inline constexpr int kMinNodeId = 1;    ///< Node ids are 1..127 (7 bits), as in CANopen.
inline constexpr int kMaxNodeId = 127;
inline constexpr int kDefaultNodeId = 1;  ///< The base controller's factory node id.

/// True when `node_id` is in 1..127 (CheckNodeId says what is wrong otherwise).
constexpr bool ValidNodeId(int node_id) { return node_id >= kMinNodeId && node_id <= kMaxNodeId; }

/// Empty when `node_id` is in 1..127, else what is wrong.
std::string CheckNodeId(int node_id);

/// The 11-bit id of `kind` for `node_id` (function base + node id). `node_id` must be valid
/// (CheckNodeId); an invalid one gives 0, which no frame of the protocol uses.
std::uint32_t FrameId(BaseFrameKind kind, int node_id);

/// The frame's name as used in every error message, e.g. "velocity command".
const char* FrameName(BaseFrameKind kind);

/// The exact data length of `kind` (8, or 2 for the mode request).
int FrameDlc(BaseFrameKind kind);

/// Which frame of the protocol `frame` is for `node_id`, from its id alone; nullopt with
/// *error (when not null) for error, remote and extended frames and for ids that are not the
/// protocol's for this node (e.g. "id 0x205 is not a base protocol frame of node 1").
std::optional<BaseFrameKind> IdentifyFrame(const can::CanFrame& frame, int node_id,
                                           std::string* error);

}  // namespace topay::base
