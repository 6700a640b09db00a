#pragma once
// The drive side of the CiA 402 power state machine (CiA 402-2 §6.2.1, Figure 25): the state a
// drive is in, the transitions a controlword triggers and the ones the drive makes by itself
// (initialisation done, fault detected, fault reaction done, quick stop done). A pure class
// for the motor simulator; no timing, no motion.

#include <cstdint>
#include <string>

#include "drivers/arm/cia402_state.h"

namespace topay::cia402 {

/// What applying a controlword did.
struct TransitionResult {
  bool accepted = false;   ///< False: the drive ignored the command (illegal here).
  DriveState state = DriveState::kNotReadyToSwitchOn;  ///< The state after it.
  int transition = 0;      ///< CiA 402 transition number, 0 when the state did not change.
  std::string reason;      ///< Why it was refused (empty when accepted).
};

/// Options of the drive model.
struct DriveModelOptions {
  /// Quick stop option code (object 0x605A) 5..8: the drive stays in Quick stop active after
  /// stopping, and enable operation returns to Operation enabled (transition 16). With false
  /// (codes 1..4, the default) the drive passes to Switch on disabled when the stop is done
  /// (transition 12) and transition 16 is refused.
  bool quick_stop_stays_active = false;
};

class DriveModel {
 public:
  /// A drive at power-on: Not ready to switch on (transition 0), previous controlword 0.
  explicit DriveModel(DriveModelOptions options = {}) : options_(options) {}

  DriveState state() const { return state_; }
  /// The statusword of the current state (voltage-enabled bit 4 set in the powered states).
  std::uint16_t statusword() const;

  /// Applies a controlword received in an RPDO or SDO: follows the transition it selects
  /// from the current state, or refuses it with a reason (state unchanged). Repeating the
  /// command of the current state (e.g. enable operation in Operation enabled) is accepted
  /// with transition 0. Fault reset acts only in Fault and only on the 0 -> 1 edge of bit 7
  /// relative to the previous controlword applied.
  TransitionResult ApplyControlword(std::uint16_t controlword);

  /// Transition 1: initialisation done (Not ready to switch on -> Switch on disabled).
  TransitionResult CompleteInitialization();
  /// Transition 13: a fault was detected (from any state but the fault states).
  TransitionResult OnFault();
  /// Transition 14: the fault reaction is done (Fault reaction active -> Fault).
  TransitionResult CompleteFaultReaction();
  /// Transition 12 (option codes 1..4): the quick stop ramp is done (-> Switch on disabled).
  TransitionResult CompleteQuickStop();

 private:
  TransitionResult Move(DriveState next, int transition);
  TransitionResult Stay() const;
  TransitionResult Refuse(std::string reason) const;
  TransitionResult ApplyCommand(Command command, std::uint16_t controlword);

  DriveModelOptions options_;
  DriveState state_ = DriveState::kNotReadyToSwitchOn;
  std::uint16_t previous_controlword_ = 0;
};

}  // namespace topay::cia402
