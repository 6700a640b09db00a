#pragma once
// Every CANopen function and every base protocol frame kind, for the CAN fuzz targets that pick
// one from a fuzzed byte, and the frame a node of the bus may receive built from a frame record
// (can_fuzz.h): an addressed record becomes a base protocol frame of the robot's base node
// (flag kFrameBaseProtocol; sealed with its checksum if asked) or a CANopen frame of node 0-7.

#include <array>
#include <cstdint>

#include "drivers/arm/canopen_ids.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/protocol_ids.h"
#include "tests/fuzz/can_fuzz.h"

namespace topay::fuzz {

inline constexpr std::array<canopen::CanopenFunction, 14> kFunctions = {
    canopen::CanopenFunction::kNmt,   canopen::CanopenFunction::kSync,     canopen::CanopenFunction::kEmcy,
    canopen::CanopenFunction::kTpdo1, canopen::CanopenFunction::kRpdo1,    canopen::CanopenFunction::kTpdo2,
    canopen::CanopenFunction::kRpdo2, canopen::CanopenFunction::kTpdo3,    canopen::CanopenFunction::kRpdo3,
    canopen::CanopenFunction::kTpdo4, canopen::CanopenFunction::kRpdo4,    canopen::CanopenFunction::kSdoTx,
    canopen::CanopenFunction::kSdoRx, canopen::CanopenFunction::kHeartbeat};

inline constexpr std::array<base::BaseFrameKind, 6> kBaseKinds = {
    base::BaseFrameKind::kFault,           base::BaseFrameKind::kModeRequest, base::BaseFrameKind::kStatus,
    base::BaseFrameKind::kVelocityCommand, base::BaseFrameKind::kWheelSpeeds, base::BaseFrameKind::kOdometry};

/// FrameRecord flag: an addressed record is a base protocol frame (else a CANopen one).
inline constexpr std::uint8_t kFrameBaseProtocol = 1u << 5;

inline can::CanFrame ReceivableFrame(FuzzReader& in, int base_node_id) {
  FrameRecord record = NextFrameRecord(in);
  can::CanFrame& frame = record.frame;
  if (record.addressed() && (record.flags & kFrameBaseProtocol) != 0) {
    frame.id = base::FrameId(kBaseKinds[frame.id % kBaseKinds.size()], base_node_id);
    if (record.seal()) frame.data[base::kChecksumByte] = base::ComputeChecksum(frame);
  } else if (record.addressed()) {
    const canopen::CanopenFunction function = kFunctions[frame.id % kFunctions.size()];
    const int node = static_cast<int>((frame.id >> 8) % 8);
    frame.id = canopen::FunctionBaseCobId(function) + (canopen::HasNodeId(function) ? node : 0);
  }
  return frame;
}

}  // namespace topay::fuzz
