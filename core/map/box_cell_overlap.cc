#include "core/map/box_cell_overlap.h"

#include <stdexcept>
#include <string>

namespace topay {

void ValidateBox(const OrientedBox& box, const char* where) {
  if (!box.center_W_m.allFinite() || !box.size_m.allFinite() || !std::isfinite(box.yaw_rad)) {
    throw std::invalid_argument(std::string(where) +
                                ": box centre, size and yaw must be finite (got NaN or inf)");
  }
  if ((box.size_m.array() < 0.0).any()) {
    throw std::invalid_argument(std::string(where) + ": box size must be non-negative");
  }
}

}  // namespace topay
