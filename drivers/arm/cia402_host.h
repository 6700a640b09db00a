#pragma once
// The host side of the CiA 402 power state machine: which controlword moves a drive from the
// state its statusword reports towards Operation enabled (for the bridge), one step per cycle.

#include <cstdint>
#include <string_view>

#include "drivers/arm/cia402_state.h"

namespace topay::cia402 {

struct HostStep {
  std::uint16_t controlword = 0;
  /// Why: "shutdown (transition 2)", "wait: fault reaction in progress", ...
  std::string_view action;
  /// True when the drive must change state by itself first (initialising, fault reaction).
  bool waiting = false;
};

/// The controlword to send to a drive in `state` to bring it towards Operation enabled, given
/// the controlword sent the cycle before (`previous_controlword`, for the fault reset edge):
///   Not ready to switch on   -> 0x0000, wait (the drive initialises by itself)
///   Switch on disabled       -> shutdown 0x0006 (transition 2)
///   Ready to switch on       -> switch on 0x0007 (transition 3)
///   Switched on              -> enable operation 0x000F (transition 4)
///   Operation enabled        -> enable operation 0x000F (hold)
///   Quick stop active        -> disable voltage 0x0000 (transition 12), then from the start
///   Fault reaction active    -> 0x0000, wait (transition 14 comes by itself)
///   Fault                    -> fault reset 0x0080 (transition 15), or 0x0000 first when the
///                               previous controlword already had bit 7 (a new edge is needed)
/// Going through Switched on (not 0x000F straight from Ready to switch on) follows the
/// standard's order and works on drives that do not implement transitions 3 + 4 at once.
HostStep NextStepTowardsOperationEnabled(DriveState state, std::uint16_t previous_controlword);

}  // namespace topay::cia402
