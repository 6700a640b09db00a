#include "core/trajectory/trajectory_sample.h"

#include <stdexcept>
#include <string>

namespace topay {

TrajectorySample MakeTrajectorySample(int num_joints) {
  if (num_joints < 0) {
    throw std::invalid_argument("MakeTrajectorySample: negative joint count " +
                                std::to_string(num_joints));
  }
  TrajectorySample sample;
  sample.state.q_rad.setZero(num_joints);
  sample.qd_radps.setZero(num_joints);
  sample.qdd_radps2.setZero(num_joints);
  return sample;
}

}  // namespace topay
