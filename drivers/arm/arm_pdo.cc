#include "drivers/arm/arm_pdo.h"

#include <cmath>

#include "drivers/can/little_endian.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_state.h"

namespace topay::cia402 {
namespace {

using canopen::CanopenFunction;
using canopen::Fail;
using canopen::FrameError;

// The value in drive units, or an error naming `what` when it is not finite or beyond `bound`.
std::optional<std::int32_t> ToUnits(double value, double unit, double bound,
                                    std::string_view what, std::string* error) {
  if (!std::isfinite(value) || std::abs(value) > bound) {
    return Fail(error, std::string(what) + " " + std::to_string(value) +
                           " is not finite or beyond +-" + std::to_string(bound));
  }
  return static_cast<std::int32_t>(std::llround(value / unit));
}

// The value of `units` drive units, or an error naming the frame when beyond `bound`.
std::optional<double> FromUnits(std::int32_t units, double unit, double bound,
                                std::string_view what, std::string_view pdo,
                                const can::CanFrame& frame, std::string* error) {
  const long long max_units = std::llround(bound / unit);
  if (std::llabs(static_cast<long long>(units)) > max_units) {
    return Fail(error, FrameError(pdo, frame,
                                  std::string(what) + " " + std::to_string(units) +
                                      " units is beyond +-" + std::to_string(max_units) +
                                      " (+-" + std::to_string(bound) + ")"));
  }
  return units * unit;
}

std::optional<can::CanFrame> MakePdo(CanopenFunction function, int node_id, int dlc,
                                     std::string* error) {
  const auto id = canopen::CobIdOf(function, node_id, error);
  if (!id) return std::nullopt;
  can::CanFrame frame = can::CanFrame::Standard(*id);
  frame.dlc = static_cast<std::uint8_t>(dlc);
  return frame;
}

std::int32_t Int32At(const can::CanFrame& frame, int offset) {
  return static_cast<std::int32_t>(can::GetLittleEndian(frame.data, 4, offset));
}

std::uint16_t Uint16At(const can::CanFrame& frame, int offset) {
  return static_cast<std::uint16_t>(can::GetLittleEndian(frame.data, 2, offset));
}

}  // namespace

std::optional<can::CanFrame> EncodeRpdo1(const Rpdo1& pdo, const JointUnits& units,
                                         std::string* error) {
  const auto velocity = ToUnits(pdo.target_velocity_rad_per_s, units.rad_per_s_per_velocity_unit,
                                units.max_target_velocity_rad_per_s,
                                "RPDO1: target velocity (rad/s)", error);
  if (!velocity) return std::nullopt;
  auto frame = MakePdo(CanopenFunction::kRpdo1, pdo.node_id, 6, error);
  if (!frame) return std::nullopt;
  can::PutLittleEndian(pdo.controlword, 2, 0, &frame->data);
  can::PutLittleEndian(static_cast<std::uint32_t>(*velocity), 4, 2, &frame->data);
  return frame;
}

std::optional<can::CanFrame> EncodeRpdo2(const Rpdo2& pdo, const JointUnits& units,
                                         std::string* error) {
  const auto position = ToUnits(pdo.target_position_rad, units.rad_per_position_unit,
                                units.max_position_rad, "RPDO2: target position (rad)", error);
  if (!position) return std::nullopt;
  auto frame = MakePdo(CanopenFunction::kRpdo2, pdo.node_id, 4, error);
  if (!frame) return std::nullopt;
  can::PutLittleEndian(static_cast<std::uint32_t>(*position), 4, 0, &frame->data);
  return frame;
}

std::optional<can::CanFrame> EncodeTpdo1(const Tpdo1& pdo, const JointUnits& units,
                                         std::string* error) {
  const auto position = ToUnits(pdo.position_rad, units.rad_per_position_unit,
                                units.max_position_rad, "TPDO1: position actual (rad)", error);
  if (!position) return std::nullopt;
  auto frame = MakePdo(CanopenFunction::kTpdo1, pdo.node_id, 6, error);
  if (!frame) return std::nullopt;
  can::PutLittleEndian(pdo.statusword, 2, 0, &frame->data);
  can::PutLittleEndian(static_cast<std::uint32_t>(*position), 4, 2, &frame->data);
  return frame;
}

std::optional<can::CanFrame> EncodeTpdo2(const Tpdo2& pdo, const JointUnits& units,
                                         std::string* error) {
  const auto velocity = ToUnits(pdo.velocity_rad_per_s, units.rad_per_s_per_velocity_unit,
                                units.max_actual_velocity_rad_per_s,
                                "TPDO2: velocity actual (rad/s)", error);
  if (!velocity) return std::nullopt;
  auto frame = MakePdo(CanopenFunction::kTpdo2, pdo.node_id, 4, error);
  if (!frame) return std::nullopt;
  can::PutLittleEndian(static_cast<std::uint32_t>(*velocity), 4, 0, &frame->data);
  return frame;
}

std::optional<Rpdo1> DecodeRpdo1(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error) {
  const auto node_id =
      canopen::CheckCanopenFrame(frame, CanopenFunction::kRpdo1, 6, 6, "RPDO1", error);
  if (!node_id) return std::nullopt;
  const auto velocity = FromUnits(Int32At(frame, 2), units.rad_per_s_per_velocity_unit,
                                  units.max_target_velocity_rad_per_s, "target velocity",
                                  "RPDO1", frame, error);
  if (!velocity) return std::nullopt;
  return Rpdo1{*node_id, Uint16At(frame, 0), *velocity};
}

std::optional<Rpdo2> DecodeRpdo2(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error) {
  const auto node_id =
      canopen::CheckCanopenFrame(frame, CanopenFunction::kRpdo2, 4, 4, "RPDO2", error);
  if (!node_id) return std::nullopt;
  const auto position = FromUnits(Int32At(frame, 0), units.rad_per_position_unit,
                                  units.max_position_rad, "target position", "RPDO2", frame,
                                  error);
  if (!position) return std::nullopt;
  return Rpdo2{*node_id, *position};
}

std::optional<Tpdo1> DecodeTpdo1(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error) {
  const auto node_id =
      canopen::CheckCanopenFrame(frame, CanopenFunction::kTpdo1, 6, 6, "TPDO1", error);
  if (!node_id) return std::nullopt;
  const std::uint16_t statusword = Uint16At(frame, 0);
  std::string state_error;
  if (!DecodeStatusword(statusword, &state_error)) {
    return Fail(error, FrameError("TPDO1", frame, state_error));
  }
  const auto position = FromUnits(Int32At(frame, 2), units.rad_per_position_unit,
                                  units.max_position_rad, "position actual", "TPDO1", frame,
                                  error);
  if (!position) return std::nullopt;
  return Tpdo1{*node_id, statusword, *position};
}

std::optional<Tpdo2> DecodeTpdo2(const can::CanFrame& frame, const JointUnits& units,
                                 std::string* error) {
  const auto node_id =
      canopen::CheckCanopenFrame(frame, CanopenFunction::kTpdo2, 4, 4, "TPDO2", error);
  if (!node_id) return std::nullopt;
  const auto velocity = FromUnits(Int32At(frame, 0), units.rad_per_s_per_velocity_unit,
                                  units.max_actual_velocity_rad_per_s, "velocity actual",
                                  "TPDO2", frame, error);
  if (!velocity) return std::nullopt;
  return Tpdo2{*node_id, *velocity};
}

}  // namespace topay::cia402
