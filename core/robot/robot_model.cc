#include "core/robot/robot_model.h"

namespace topay {

int RobotModel::FindLink(const std::string& link_name) const {
  for (int i = 0; i < static_cast<int>(links.size()); ++i) {
    if (links[i].name == link_name) return i;
  }
  return -1;
}

}  // namespace topay
