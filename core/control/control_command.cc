#include "core/control/control_command.h"

namespace topay {

ControlCommand ControlCommand::Zero(int num_joints) {
  ControlCommand command;
  command.qd_radps.setZero(num_joints);
  return command;
}

InputSequence InputSequence::Zero(int steps, int num_joints) {
  InputSequence inputs;
  inputs.u_base.setZero(2, steps);
  inputs.qd_radps.setZero(num_joints, steps);
  return inputs;
}

void InputSequence::CommandAt(int k, ControlCommand* command) const {
  command->v_mps = u_base(0, k);
  command->omega_radps = u_base(1, k);
  command->qd_radps = qd_radps.col(k);
}

void InputSequence::Fill(const ControlCommand& command) {
  u_base.row(0).setConstant(command.v_mps);
  u_base.row(1).setConstant(command.omega_radps);
  for (int k = 0; k < steps(); ++k) qd_radps.col(k) = command.qd_radps;
}

}  // namespace topay
