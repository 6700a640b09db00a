#pragma once
// This robot's process data objects for one arm joint drive (docs/cia402.md): the objects they
// map, the units the values travel in, and their encoders/decoders with DLC and range checks.
//
//   RPDO1 (0x200 + node, DLC 6): controlword 0x6040 (uint16) + target velocity 0x60FF (int32)
//   RPDO2 (0x300 + node, DLC 4): target position 0x607A (int32)   [optional, for CSP]
//   TPDO1 (0x180 + node, DLC 6): statusword 0x6041 (uint16) + position actual 0x6064 (int32)
//   TPDO2 (0x280 + node, DLC 4): velocity actual 0x606C (int32)
// All little-endian (CiA 301 §7.1.2), packed in mapping order; all synchronous (sent or acted
// on at each SYNC, transmission type 1).

#include <cstdint>
#include <numbers>
#include <optional>
#include <string>

#include "drivers/arm/sdo.h"
#include "drivers/can/can_frame.h"

namespace topay::cia402 {

/// CiA 402-2 objects mapped or written by this stack.
namespace object {
inline constexpr canopen::ObjectAddress kControlword{0x6040, 0};      ///< uint16
inline constexpr canopen::ObjectAddress kStatusword{0x6041, 0};       ///< uint16
inline constexpr canopen::ObjectAddress kModesOfOperation{0x6060, 0}; ///< int8
inline constexpr canopen::ObjectAddress kPositionActual{0x6064, 0};   ///< int32
inline constexpr canopen::ObjectAddress kVelocityActual{0x606C, 0};   ///< int32
inline constexpr canopen::ObjectAddress kTargetPosition{0x607A, 0};   ///< int32
inline constexpr canopen::ObjectAddress kTargetVelocity{0x60FF, 0};   ///< int32
}  // namespace object

/// The units position and velocity travel in, as joint (output side) angles, and the bounds
/// the codecs enforce. The drive's factor group (0x608F encoder resolution, 0x6091 gear ratio,
/// 0x6092 feed constant) must be set so that one drive unit is this much joint motion; that
/// setting is drive-specific and not part of the start-up writes (docs/cia402.md).
struct JointUnits {
  /// One position unit (0x6064, 0x607A): 1 microradian (int32: +-2147 rad).
  double rad_per_position_unit = 1e-6;
  /// One velocity unit (0x606C, 0x60FF): 0.1 mrad/s (int32: +-214748 rad/s).
  double rad_per_s_per_velocity_unit = 1e-4;
  /// Largest |target velocity| (RPDO1): the joint velocity limit of config/robot/topay_mm.yaml
  /// (joint_limits.velocity, 2.35 rad/s for q1..q7).
  double max_target_velocity_rad_per_s = 2.35;
  /// Largest |actual velocity| believed in a TPDO2: twice the limit (an overshoot is reported,
  /// a value beyond this is a garbled frame or a runaway drive).
  double max_actual_velocity_rad_per_s = 4.7;
  /// Largest |position| (target or actual): one turn each way, wider than any URDF joint limit.
  double max_position_rad = 2.0 * std::numbers::pi;
};

struct Rpdo1 {
  int node_id = 1;
  std::uint16_t controlword = 0;
  double target_velocity_rad_per_s = 0.0;
};
struct Rpdo2 {
  int node_id = 1;
  double target_position_rad = 0.0;
};
struct Tpdo1 {
  int node_id = 1;
  std::uint16_t statusword = 0;  ///< Encodes a CiA 402 state (checked by the decoder).
  double position_rad = 0.0;
};
struct Tpdo2 {
  int node_id = 1;
  double velocity_rad_per_s = 0.0;
};

// Encoders: nullopt with *error (when not null) for a node id outside 1..127, a non-finite
// value or one beyond the JointUnits bound (values are rounded to the nearest unit).
std::optional<can::CanFrame> EncodeRpdo1(const Rpdo1& pdo, const JointUnits& units,
                                         std::string* error);
std::optional<can::CanFrame> EncodeRpdo2(const Rpdo2& pdo, const JointUnits& units,
                                         std::string* error);
std::optional<can::CanFrame> EncodeTpdo1(const Tpdo1& pdo, const JointUnits& units,
                                         std::string* error);
std::optional<can::CanFrame> EncodeTpdo2(const Tpdo2& pdo, const JointUnits& units,
                                         std::string* error);

// Decoders: nullopt with *error naming the frame for another id, a DLC other than the layout's,
// a value beyond the JointUnits bound, or (TPDO1) a statusword that encodes no CiA 402 state.
std::optional<Rpdo1> DecodeRpdo1(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error);
std::optional<Rpdo2> DecodeRpdo2(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error);
std::optional<Tpdo1> DecodeTpdo1(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error);
std::optional<Tpdo2> DecodeTpdo2(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error);

}  // namespace topay::cia402
