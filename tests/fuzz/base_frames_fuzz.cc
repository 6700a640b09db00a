// Every decoder of the base controller's protocol (drivers/base/: status, odometry, fault, wheel
// speeds, mode request, velocity command, IdentifyFrame, CheckFrameShape, the rolling counter)
// on fuzzed frames with a fuzzed node id and last counter, and every encoder on fuzzed values.
// Checked: a refusal names why; the verdict does not depend on asking for the reason; a decoded
// frame has the shape of its kind and is the kind IdentifyFrame names; decoded values are in the
// protocol's ranges; every frame of this protocol carries all its bits (reserved bytes must be
// zero), so a decoded value encodes back to the very same frame; an encoded value decodes back
// to itself (to the protocol's rounding).
//
// Input: records until the input ends, each [op] then
//   op even: a frame record (can_fuzz.h; seal: byte 7 := the checksum; addressed: the id of
//            kind (id % 6) for the node), [node id][last counter][has last counter]: 18 bytes;
//   op odd:  an encoder record [kind][node id][double a][double b][u16 bits][x][y][counter]:
//            kind % 6 encodes (a, b, bits, x, y, counter) as its fields: 25 bytes.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "drivers/base/base_mode.h"
#include "drivers/base/fault_codes.h"
#include "drivers/base/fault_frame.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "tests/fuzz/can_fuzz.h"
#include "tests/fuzz/fuzz_check.h"

namespace topay::fuzz {
namespace {

using base::BaseFrameKind;

constexpr std::array<BaseFrameKind, 6> kKinds = {BaseFrameKind::kFault,       BaseFrameKind::kModeRequest,
                                                 BaseFrameKind::kStatus,      BaseFrameKind::kVelocityCommand,
                                                 BaseFrameKind::kWheelSpeeds, BaseFrameKind::kOdometry};

// Half a unit of a fixed-point field, plus the double's own rounding.
constexpr double kHalfMilli = 0.5e-3 + 1e-12;
constexpr double kHalfTenMilliVolt = 0.5e-2 + 1e-12;

// A decoded frame has the shape of `kind`, IdentifyFrame says so, and it is a valid frame.
void CheckIsKind(const can::CanFrame& frame, BaseFrameKind kind, int node_id) {
  FuzzCheck(base::CheckFrameShape(frame, kind, node_id).empty(), "a decoded frame has its kind's shape");
  FuzzCheck(base::IdentifyFrame(frame, node_id, nullptr) == kind, "a decoded frame is identified as its kind");
  FuzzCheck(can::CheckCanFrame(frame).empty(), "a decoded frame is a valid CAN frame");
}

// Decodes with and without the error string: same verdict, and a refusal names why.
template <class Decode>
auto DecodeBothWays(Decode decode) {
  std::string error;
  auto decoded = decode(&error);
  FuzzCheck(decoded.has_value() || !error.empty(), "a refused frame comes with a reason");
  FuzzCheck(decode(nullptr).has_value() == decoded.has_value(), "the verdict does not depend on the error string");
  return decoded;
}

void CheckReEncodes(const std::optional<can::CanFrame>& again, const can::CanFrame& frame, const char* what) {
  FuzzCheck(again.has_value(), what);
  FuzzCheck(*again == frame, what);
}

void CheckIdentify(const can::CanFrame& frame, int node_id) {
  std::string error;
  const std::optional<BaseFrameKind> kind = base::IdentifyFrame(frame, node_id, &error);
  FuzzCheck(kind.has_value() || !error.empty(), "an unidentified frame comes with a reason");
  for (const BaseFrameKind k : kKinds) {
    const std::string shape = base::CheckFrameShape(frame, k, node_id);
    if (shape.empty()) FuzzCheck(kind == k, "a frame of a kind's shape is identified as that kind");
    if (kind != k) FuzzCheck(!shape.empty(), "a frame of another kind does not have this kind's shape");
    FuzzCheck(base::FrameName(k) != nullptr && base::FrameDlc(k) >= 2, "every kind has a name and a DLC");
  }
}

void CheckStatus(const can::CanFrame& frame, int node_id) {
  const auto status = DecodeBothWays([&](std::string* e) { return base::DecodeStatus(frame, node_id, e); });
  if (!status) return;
  CheckIsKind(frame, BaseFrameKind::kStatus, node_id);
  FuzzCheck(static_cast<std::uint8_t>(status->mode) <= base::kMaxBaseModeCode, "status: a defined mode");
  FuzzCheck(status->error_code <= base::kMaxFaultCode, "status: a defined error code");
  FuzzCheck((status->fault_bits & ~base::kDefinedFaultBits) == 0, "status: only defined fault bits");
  FuzzCheck(status->battery_voltage_v >= 0.0 && status->battery_voltage_v <= 100.0, "status: battery in 0..100 V");
  FuzzCheck(status->counter == frame.data[base::kCounterByte], "status: the frame's counter");
  FuzzCheck(base::ModeName(status->mode) != nullptr, "status: the mode has a name");
  CheckReEncodes(base::EncodeStatus(*status, node_id, nullptr), frame, "a decoded status encodes to the same frame");
}

void CheckOdometry(const can::CanFrame& frame, int node_id, std::optional<std::uint8_t> last_counter) {
  const auto odometry =
      DecodeBothWays([&](std::string* e) { return base::DecodeOdometry(frame, node_id, last_counter, e); });
  const auto without_counter = base::DecodeOdometry(frame, node_id, std::nullopt, nullptr);
  if (odometry) FuzzCheck(without_counter.has_value(), "odometry: the counter check only refuses more");
  if (without_counter && last_counter) {
    FuzzCheck(odometry.has_value() == (*last_counter != without_counter->counter),
              "odometry: refused with a last counter exactly when the counter repeats");
  }
  if (!odometry) return;
  CheckIsKind(frame, BaseFrameKind::kOdometry, node_id);
  FuzzCheck(odometry->left_ticks < base::kTickCountModulus && odometry->right_ticks < base::kTickCountModulus,
            "odometry: tick counts below 2^24");
  const std::int32_t delta = base::WheelTickDelta(odometry->left_ticks, odometry->right_ticks);
  constexpr auto kHalf = static_cast<std::int32_t>(base::kTickCountModulus / 2);
  FuzzCheck(delta >= -kHalf && delta < kHalf, "odometry: a tick delta is in [-2^23, 2^23)");
  FuzzCheck(
      (odometry->left_ticks + static_cast<std::uint32_t>(delta)) % base::kTickCountModulus == odometry->right_ticks,
      "odometry: last + delta is the current count modulo 2^24");
  CheckReEncodes(base::EncodeOdometry(*odometry, node_id, nullptr), frame,
                 "decoded odometry encodes to the same frame");
}

void CheckFault(const can::CanFrame& frame, int node_id) {
  const auto report = DecodeBothWays([&](std::string* e) { return base::DecodeFault(frame, node_id, e); });
  if (!report) return;
  CheckIsKind(frame, BaseFrameKind::kFault, node_id);
  const auto code = static_cast<std::uint8_t>(report->fault);
  FuzzCheck(code >= 1 && code <= base::kMaxFaultCode, "fault: a defined fault code");
  FuzzCheck((report->fault_bits & base::FaultBit(report->fault)) != 0, "fault: the word has the raised fault's bit");
  FuzzCheck((report->fault_bits & ~base::kDefinedFaultBits) == 0, "fault: only defined fault bits");
  FuzzCheck(!base::DescribeFaultBits(report->fault_bits).empty(), "fault: the bits have names");
  CheckReEncodes(base::EncodeFault(*report, node_id, nullptr), frame, "a decoded fault encodes to the same frame");
}

void CheckWheelSpeeds(const can::CanFrame& frame, int node_id) {
  const auto speeds = DecodeBothWays([&](std::string* e) { return base::DecodeWheelSpeeds(frame, node_id, e); });
  if (!speeds) return;
  CheckIsKind(frame, BaseFrameKind::kWheelSpeeds, node_id);
  const double max = base::kMaxWheelSpeedRaw * 1e-3;
  FuzzCheck(std::abs(speeds->left_rad_per_s) <= max && std::abs(speeds->right_rad_per_s) <= max,
            "wheel speeds: within +-30 rad/s");
  CheckReEncodes(base::EncodeWheelSpeeds(*speeds, node_id, nullptr), frame,
                 "decoded wheel speeds encode to the same frame");
}

void CheckModeRequest(const can::CanFrame& frame, int node_id) {
  const auto request = DecodeBothWays([&](std::string* e) { return base::DecodeModeRequest(frame, node_id, e); });
  if (!request) return;
  CheckIsKind(frame, BaseFrameKind::kModeRequest, node_id);
  FuzzCheck(static_cast<std::uint8_t>(*request) <= base::kMaxModeRequestCode, "mode request: a defined code");
  FuzzCheck(base::ModeRequestName(*request) != nullptr, "mode request: the request has a name");
  CheckReEncodes(base::EncodeModeRequest(*request, node_id, nullptr), frame,
                 "a decoded mode request encodes to the same frame");
}

void CheckVelocityCommand(const can::CanFrame& frame, int node_id, std::optional<std::uint8_t> last_counter) {
  const auto command =
      DecodeBothWays([&](std::string* e) { return base::DecodeVelocityCommand(frame, node_id, last_counter, e); });
  const auto without_counter = base::DecodeVelocityCommand(frame, node_id, std::nullopt, nullptr);
  if (command) FuzzCheck(without_counter.has_value(), "velocity command: the counter check only refuses more");
  if (without_counter && last_counter) {
    FuzzCheck(command.has_value() == (*last_counter != without_counter->counter),
              "velocity command: refused with a last counter exactly when the counter repeats");
  }
  if (!command) return;
  CheckIsKind(frame, BaseFrameKind::kVelocityCommand, node_id);
  FuzzCheck(std::abs(command->v_m_per_s) <= base::kMaxLinearSpeedRaw * 1e-3, "velocity command: |v| <= 3 m/s");
  FuzzCheck(std::abs(command->omega_rad_per_s) <= base::kMaxAngularSpeedRaw * 1e-3,
            "velocity command: |omega| <= 10 rad/s");
  CheckReEncodes(base::EncodeVelocityCommand(*command, node_id, nullptr), frame,
                 "a decoded velocity command encodes to the same frame");
}

void CheckCounterHelpers(std::uint8_t last, std::uint8_t current) {
  const int gap = base::CounterGap(last, current);
  FuzzCheck(gap >= 0 && gap <= 255, "counter gap in 0..255");
  FuzzCheck(static_cast<std::uint8_t>(last + gap + 1) == current, "last + gap + 1 is the current counter");
  FuzzCheck(base::CheckRollingCounter("x", last, current).empty() == (last != current),
            "a counter is stale exactly when it repeats");
}

void DecodeFrameRecord(FuzzReader& in) {
  FrameRecord record = NextFrameRecord(in);
  const int node_id = in.Byte();
  const std::uint8_t counter_byte = in.Byte();
  std::optional<std::uint8_t> last_counter;
  if (in.Bool()) last_counter.emplace(counter_byte);
  can::CanFrame& frame = record.frame;
  if (record.addressed()) frame.id = base::FrameId(kKinds[frame.id % kKinds.size()], node_id);
  if (record.seal()) frame.data[base::kChecksumByte] = base::ComputeChecksum(frame);

  CheckIdentify(frame, node_id);
  CheckStatus(frame, node_id);
  CheckOdometry(frame, node_id, last_counter);
  CheckFault(frame, node_id);
  CheckWheelSpeeds(frame, node_id);
  CheckModeRequest(frame, node_id);
  CheckVelocityCommand(frame, node_id, last_counter);
  CheckCounterHelpers(counter_byte, frame.data[base::kCounterByte]);
  FuzzCheck(base::FaultCodeName(frame.data[1]) != nullptr, "every fault code byte has a name");
  FuzzCheck(!base::DescribeFaultBits(base::GetUint16Le(frame, 2)).empty(), "every fault word has a description");
}

// An encoder's verdict on fuzzed values: a frame of its kind that decodes back to the values (to
// the protocol's rounding), or a refusal that names why.
void EncodeRecord(FuzzReader& in) {
  const BaseFrameKind kind = kKinds[in.Byte() % kKinds.size()];
  const int node_id = in.Byte();
  const double a = in.RawDouble();
  const double b = in.RawDouble();
  const std::uint16_t bits = in.U16();
  const std::uint8_t x = in.Byte();
  const std::uint8_t y = in.Byte();
  const std::uint8_t counter = in.Byte();
  std::string error;
  std::optional<can::CanFrame> frame;
  switch (kind) {
    case BaseFrameKind::kStatus: {
      const base::BaseStatus status{static_cast<base::BaseMode>(x), y, bits, a, counter};
      frame = base::EncodeStatus(status, node_id, &error);
      if (!frame) break;
      const auto back = base::DecodeStatus(*frame, node_id, nullptr);
      FuzzCheck(back && back->mode == status.mode && back->error_code == y && back->fault_bits == bits &&
                    back->counter == counter && std::abs(back->battery_voltage_v - a) <= kHalfTenMilliVolt,
                "an encoded status decodes back to its values");
      break;
    }
    case BaseFrameKind::kOdometry: {
      const base::OdometryFeedback odometry{bits | (std::uint32_t{x} << 16) | (std::uint32_t{y} << 24),
                                            static_cast<std::uint32_t>(std::abs(a) < 4e9 ? std::abs(a) : 0.0), counter};
      frame = base::EncodeOdometry(odometry, node_id, &error);
      if (!frame) break;
      const auto back = base::DecodeOdometry(*frame, node_id, std::nullopt, nullptr);
      FuzzCheck(back && back->left_ticks == odometry.left_ticks % base::kTickCountModulus &&
                    back->right_ticks == odometry.right_ticks % base::kTickCountModulus && back->counter == counter,
                "encoded odometry decodes back to its counts modulo 2^24");
      break;
    }
    case BaseFrameKind::kFault: {
      const base::FaultReport report{static_cast<base::BaseFault>(x), static_cast<base::BaseMode>(y), bits, counter};
      frame = base::EncodeFault(report, node_id, &error);
      if (!frame) break;
      const auto back = base::DecodeFault(*frame, node_id, nullptr);
      FuzzCheck(back && back->fault == report.fault && back->mode == report.mode && back->fault_bits == bits &&
                    back->counter == counter,
                "an encoded fault decodes back to its values");
      break;
    }
    case BaseFrameKind::kWheelSpeeds: {
      frame = base::EncodeWheelSpeeds({a, b, counter}, node_id, &error);
      if (!frame) break;
      const auto back = base::DecodeWheelSpeeds(*frame, node_id, nullptr);
      FuzzCheck(back && std::abs(back->left_rad_per_s - a) <= kHalfMilli &&
                    std::abs(back->right_rad_per_s - b) <= kHalfMilli && back->counter == counter,
                "encoded wheel speeds decode back to their values");
      break;
    }
    case BaseFrameKind::kModeRequest: {
      const auto request = static_cast<base::ModeRequest>(x);
      frame = base::EncodeModeRequest(request, node_id, &error);
      if (!frame) break;
      FuzzCheck(base::DecodeModeRequest(*frame, node_id, nullptr) == request,
                "an encoded mode request decodes back to itself");
      break;
    }
    case BaseFrameKind::kVelocityCommand: {
      frame = base::EncodeVelocityCommand({a, b, counter}, node_id, &error);
      if (!frame) break;
      const auto back = base::DecodeVelocityCommand(*frame, node_id, std::nullopt, nullptr);
      FuzzCheck(back && std::abs(back->v_m_per_s - a) <= kHalfMilli &&
                    std::abs(back->omega_rad_per_s - b) <= kHalfMilli && back->counter == counter,
                "an encoded velocity command decodes back to its values");
      break;
    }
  }
  if (!frame) {
    FuzzCheck(!error.empty(), "a refused value comes with a reason");
    return;
  }
  FuzzCheck(error.empty(), "an encoded value sets no error");
  CheckIsKind(*frame, kind, node_id);
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  while (!in.empty()) {
    if (in.Byte() % 2 == 0) {
      DecodeFrameRecord(in);
    } else {
      EncodeRecord(in);
    }
  }
  return 0;
}
