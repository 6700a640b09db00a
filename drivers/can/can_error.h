#pragma once
// Decoding of SocketCAN error frames (linux/can/error.h) and the bus state they imply.

#include <cstdint>
#include <optional>
#include <string>

#include "drivers/can/can_frame.h"

namespace topay::can {

/// The fault confinement state of the controller (ISO 11898-1), as reported by error frames.
enum class CanBusState {
  kErrorActive,   ///< Normal operation (error counters below 96).
  kErrorWarning,  ///< An error counter reached the warning level (96).
  kErrorPassive,  ///< An error counter reached 128: the node sends passive error flags only.
  kBusOff,        ///< The transmit error counter passed 255: the controller is off the bus.
};

/// "error-active", "error-warning", "error-passive" or "bus-off".
const char* ToString(CanBusState state);

/// What one error frame says (the CAN_ERR_* class bits of its id and the detail bytes).
struct CanErrorReport {
  bool tx_timeout = false;        ///< CAN_ERR_TX_TIMEOUT.
  bool lost_arbitration = false;  ///< CAN_ERR_LOSTARB.
  bool controller = false;        ///< CAN_ERR_CRTL (details in the flags below).
  bool rx_overflow = false;       ///< Controller: receive buffer overflow.
  bool tx_overflow = false;       ///< Controller: transmit buffer overflow.
  bool warning = false;           ///< Controller: rx or tx warning level reached.
  bool passive = false;           ///< Controller: rx or tx error-passive level reached.
  bool back_to_active = false;    ///< Controller: recovered to error-active (CAN_ERR_CRTL_ACTIVE).
  bool protocol = false;          ///< CAN_ERR_PROT: bit, form, stuff... error.
  bool transceiver = false;       ///< CAN_ERR_TRX.
  bool no_ack = false;            ///< CAN_ERR_ACK: nobody acknowledged a transmission.
  bool bus_off = false;           ///< CAN_ERR_BUSOFF.
  bool bus_error = false;         ///< CAN_ERR_BUSERROR.
  bool restarted = false;         ///< CAN_ERR_RESTARTED: the controller was restarted.
  /// Error counters (data[6] tx, data[7] rx) when the frame carries them (CAN_ERR_CNT).
  std::optional<int> tx_error_counter;
  std::optional<int> rx_error_counter;

  /// Readable summary, e.g. "bus-off" or "controller: tx passive; no ACK".
  std::string description;
};

/// Decodes an error frame. Frames that are not error frames give an empty report.
CanErrorReport DecodeCanErrorFrame(const CanFrame& frame);

/// The bus state after `report`, starting from `state`:
///  - bus-off when the report says so;
///  - error-active after a restart or an explicit recovery (CAN_ERR_CRTL_ACTIVE);
///  - otherwise bus-off is kept (only a restart leaves it);
///  - error-passive / error-warning from the controller flags;
///  - else, when the frame carries error counters, the level they imply (96 warning,
///    128 passive, as linux/can/error.h's thresholds);
///  - else unchanged (e.g. a protocol error alone says nothing about the level).
CanBusState NextBusState(CanBusState state, const CanErrorReport& report);

/// An error frame as a controller driver would report it, for simulators and tests (the UDP bus
/// carries error frames like data frames): `class_bits` are CAN_ERR_* id bits, `controller_bits`
/// data[1] (CAN_ERR_CRTL_*), and the counters go to data[6]/data[7] with CAN_ERR_CNT when given.
CanFrame MakeCanErrorFrame(std::uint32_t class_bits, std::uint8_t controller_bits = 0,
                           std::optional<int> tx_error_counter = std::nullopt,
                           std::optional<int> rx_error_counter = std::nullopt);

}  // namespace topay::can
