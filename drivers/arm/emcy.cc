#include "drivers/arm/emcy.h"

#include "drivers/can/little_endian.h"
#include "drivers/arm/canopen_ids.h"

namespace topay::canopen {

std::optional<can::CanFrame> EncodeEmcy(const Emcy& emcy, std::string* error) {
  const auto id = CobIdOf(CanopenFunction::kEmcy, emcy.node_id, error);
  if (!id) return std::nullopt;
  can::CanFrame frame = can::CanFrame::Standard(*id);
  frame.dlc = 8;
  can::PutLittleEndian(emcy.error_code, 2, 0, &frame.data);
  frame.data[2] = emcy.error_register;
  for (int i = 0; i < 5; ++i) frame.data[3 + i] = emcy.manufacturer_data[i];
  return frame;
}

std::optional<Emcy> DecodeEmcy(const can::CanFrame& frame, std::string* error) {
  const auto node_id = CheckCanopenFrame(frame, CanopenFunction::kEmcy, 8, 8, "EMCY", error);
  if (!node_id) return std::nullopt;
  Emcy emcy;
  emcy.node_id = *node_id;
  emcy.error_code = static_cast<std::uint16_t>(can::GetLittleEndian(frame.data, 2, 0));
  emcy.error_register = frame.data[2];
  for (int i = 0; i < 5; ++i) emcy.manufacturer_data[i] = frame.data[3 + i];
  return emcy;
}

}  // namespace topay::canopen
