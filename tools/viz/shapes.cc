#include "tools/viz/shapes.h"

#include <cmath>

namespace topay::viz {

std::array<Eigen::Vector2d, 4> RectangleCorners(const Eigen::Vector2d& centre_W_m,
                                                const Eigen::Vector2d& size_m, double yaw_rad) {
  const Eigen::Vector2d axis_x = 0.5 * size_m.x() * Eigen::Vector2d(std::cos(yaw_rad),
                                                                    std::sin(yaw_rad));
  const Eigen::Vector2d axis_y = 0.5 * size_m.y() * Eigen::Vector2d(-std::sin(yaw_rad),
                                                                    std::cos(yaw_rad));
  return {centre_W_m - axis_x - axis_y, centre_W_m + axis_x - axis_y,
          centre_W_m + axis_x + axis_y, centre_W_m - axis_x + axis_y};
}

std::array<Eigen::Vector2d, 3> ArrowHead(const Eigen::Vector2d& tip,
                                         const Eigen::Vector2d& direction, double length,
                                         double width) {
  const Eigen::Vector2d normal(-direction.y(), direction.x());
  const Eigen::Vector2d base = tip - length * direction;
  return {tip, base + 0.5 * width * normal, base - 0.5 * width * normal};
}

}  // namespace topay::viz
