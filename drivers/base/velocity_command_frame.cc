#include "drivers/base/velocity_command_frame.h"

#include "drivers/base/frame_bytes.h"

namespace topay::base {
namespace {

constexpr BaseFrameKind kKind = BaseFrameKind::kVelocityCommand;
constexpr double kMmPerM = 1000.0;
constexpr double kMradPerRad = 1000.0;

}  // namespace

std::optional<can::CanFrame> EncodeVelocityCommand(const VelocityCommand& command, int node_id,
                                                   std::string* error) {
  if (const std::string bad = CheckNodeId(node_id); !bad.empty()) {
    SetError(error, std::string(FrameName(kKind)) + ": " + bad);
    return std::nullopt;
  }
  std::string why;
  const auto v = ScaleToRaw(command.v_m_per_s, kMmPerM, -kMaxLinearSpeedRaw, kMaxLinearSpeedRaw,
                            "v [m/s]", &why);
  const auto omega = v ? ScaleToRaw(command.omega_rad_per_s, kMradPerRad, -kMaxAngularSpeedRaw,
                                    kMaxAngularSpeedRaw, "omega [rad/s]", &why)
                       : std::nullopt;
  if (!v || !omega) {
    SetError(error, FrameLabel(kKind, node_id) + ": " + why);
    return std::nullopt;
  }
  can::CanFrame frame = MakeEmptyFrame(kKind, node_id);
  PutInt16Le(frame, 0, static_cast<std::int16_t>(*v));
  PutInt16Le(frame, 2, static_cast<std::int16_t>(*omega));
  SealFrame(frame, command.counter);
  return frame;
}

std::optional<VelocityCommand> DecodeVelocityCommand(const can::CanFrame& frame, int node_id,
                                                     std::optional<std::uint8_t> last_counter,
                                                     std::string* error) {
  if (std::string bad = CheckFrameShape(frame, kKind, node_id); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  const std::string label = FrameLabel(kKind, node_id);
  if (GetUint16Le(frame, 4) != 0) {
    SetError(error, label + ": reserved bytes 4-5 are not zero");
    return std::nullopt;
  }
  const std::int16_t v = GetInt16Le(frame, 0);
  const std::int16_t omega = GetInt16Le(frame, 2);
  std::string bad = CheckRawRange(v, -kMaxLinearSpeedRaw, kMaxLinearSpeedRaw, "v [mm/s]");
  if (bad.empty()) {
    bad = CheckRawRange(omega, -kMaxAngularSpeedRaw, kMaxAngularSpeedRaw, "omega [mrad/s]");
  }
  if (!bad.empty()) {
    SetError(error, label + ": " + bad);
    return std::nullopt;
  }
  if (bad = CheckRollingCounter(label, last_counter, frame.data[kCounterByte]); !bad.empty()) {
    SetError(error, std::move(bad));
    return std::nullopt;
  }
  VelocityCommand command;
  command.v_m_per_s = v / kMmPerM;
  command.omega_rad_per_s = omega / kMradPerRad;
  command.counter = frame.data[kCounterByte];
  return command;
}

}  // namespace topay::base
