#include "drivers/can/can_error.h"

#include <linux/can/error.h>

#include <algorithm>

namespace topay::can {
namespace {

void Append(std::string* text, const std::string& part) {
  if (!text->empty()) *text += "; ";
  *text += part;
}

// "controller: rx warning, tx passive".
std::string ControllerText(std::uint8_t bits) {
  static constexpr struct {
    std::uint8_t bit;
    const char* name;
  } kNames[] = {{CAN_ERR_CRTL_RX_OVERFLOW, "rx overflow"}, {CAN_ERR_CRTL_TX_OVERFLOW, "tx overflow"},
                {CAN_ERR_CRTL_RX_WARNING, "rx warning"},   {CAN_ERR_CRTL_TX_WARNING, "tx warning"},
                {CAN_ERR_CRTL_RX_PASSIVE, "rx passive"},   {CAN_ERR_CRTL_TX_PASSIVE, "tx passive"},
                {CAN_ERR_CRTL_ACTIVE, "back to error-active"}};
  std::string text;
  for (const auto& entry : kNames) {
    if ((bits & entry.bit) != 0) text += (text.empty() ? "" : ", ") + std::string(entry.name);
  }
  return "controller: " + (text.empty() ? std::string("unspecified") : text);
}

void DecodeController(std::uint8_t bits, CanErrorReport* report) {
  report->controller = true;
  report->rx_overflow = (bits & CAN_ERR_CRTL_RX_OVERFLOW) != 0;
  report->tx_overflow = (bits & CAN_ERR_CRTL_TX_OVERFLOW) != 0;
  report->warning = (bits & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) != 0;
  report->passive = (bits & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0;
  report->back_to_active = (bits & CAN_ERR_CRTL_ACTIVE) != 0;
  Append(&report->description, ControllerText(bits));
}

}  // namespace

const char* ToString(CanBusState state) {
  switch (state) {
    case CanBusState::kErrorActive: return "error-active";
    case CanBusState::kErrorWarning: return "error-warning";
    case CanBusState::kErrorPassive: return "error-passive";
    case CanBusState::kBusOff: return "bus-off";
  }
  return "unknown";
}

CanErrorReport DecodeCanErrorFrame(const CanFrame& frame) {
  CanErrorReport report;
  if (!frame.error) return report;
  const std::uint32_t bits = frame.id;
  const auto has = [bits](std::uint32_t bit) { return (bits & bit) != 0; };
  report.tx_timeout = has(CAN_ERR_TX_TIMEOUT);
  if (report.tx_timeout) Append(&report.description, "tx timeout");
  report.lost_arbitration = has(CAN_ERR_LOSTARB);
  if (report.lost_arbitration) Append(&report.description, "lost arbitration");
  if (has(CAN_ERR_CRTL)) DecodeController(frame.data[1], &report);
  report.protocol = has(CAN_ERR_PROT);
  if (report.protocol) Append(&report.description, "protocol violation");
  report.transceiver = has(CAN_ERR_TRX);
  if (report.transceiver) Append(&report.description, "transceiver");
  report.no_ack = has(CAN_ERR_ACK);
  if (report.no_ack) Append(&report.description, "no ACK");
  report.bus_off = has(CAN_ERR_BUSOFF);
  if (report.bus_off) Append(&report.description, "bus-off");
  report.bus_error = has(CAN_ERR_BUSERROR);
  if (report.bus_error) Append(&report.description, "bus error");
  report.restarted = has(CAN_ERR_RESTARTED);
  if (report.restarted) Append(&report.description, "controller restarted");
  if (has(CAN_ERR_CNT)) {
    report.tx_error_counter = frame.data[6];
    report.rx_error_counter = frame.data[7];
    Append(&report.description, "tec " + std::to_string(frame.data[6]) + ", rec " +
                                    std::to_string(frame.data[7]));
  }
  if (report.description.empty()) report.description = "unspecified error";
  return report;
}

CanBusState NextBusState(CanBusState state, const CanErrorReport& report) {
  if (report.bus_off) return CanBusState::kBusOff;
  if (report.restarted || report.back_to_active) return CanBusState::kErrorActive;
  if (state == CanBusState::kBusOff) return state;
  if (report.passive) return CanBusState::kErrorPassive;
  if (report.warning) return CanBusState::kErrorWarning;
  if (report.tx_error_counter && report.rx_error_counter) {
    const int worst = std::max(*report.tx_error_counter, *report.rx_error_counter);
    if (worst >= CAN_ERROR_PASSIVE_THRESHOLD) return CanBusState::kErrorPassive;
    if (worst >= CAN_ERROR_WARNING_THRESHOLD) return CanBusState::kErrorWarning;
    return CanBusState::kErrorActive;
  }
  return state;
}

CanFrame MakeCanErrorFrame(std::uint32_t class_bits, std::uint8_t controller_bits,
                           std::optional<int> tx_error_counter, std::optional<int> rx_error_counter) {
  CanFrame frame;
  frame.error = true;
  frame.id = class_bits & CAN_ERR_MASK;
  frame.dlc = CAN_ERR_DLC;
  frame.data[1] = controller_bits;
  if (controller_bits != 0) frame.id |= CAN_ERR_CRTL;
  if (tx_error_counter || rx_error_counter) {
    frame.id |= CAN_ERR_CNT;
    frame.data[6] = static_cast<std::uint8_t>(std::clamp(tx_error_counter.value_or(0), 0, 255));
    frame.data[7] = static_cast<std::uint8_t>(std::clamp(rx_error_counter.value_or(0), 0, 255));
  }
  return frame;
}

}  // namespace topay::can
