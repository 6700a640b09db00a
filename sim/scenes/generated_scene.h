#pragma once

#include <vector>

#include "core/geometry/scene.h"
#include "sim/scenes/box_role.h"

namespace topay {

/// A scene as the generators make it: the exact geometry plus, per box, what it is
/// (roles[i] describes scene.boxes[i]).
struct GeneratedScene {
  Scene scene;
  std::vector<BoxRole> roles;
  int num_tables = 0;  ///< Tables scenes: number of tables over all groups (each 5 boxes).
};

}  // namespace topay
