#include "tools/viz/view_transform.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay::viz {

ViewTransform::ViewTransform(const Eigen::AlignedBox2d& region_W_m, double px_per_m,
                             const Eigen::Vector2d& offset_px)
    : region_W_m_(region_W_m), px_per_m_(px_per_m), offset_px_(offset_px) {
  if (region_W_m.isEmpty() || !region_W_m.min().allFinite() || !region_W_m.max().allFinite() ||
      region_W_m.sizes().minCoeff() <= 0.0) {
    throw std::invalid_argument("ViewTransform: the world region is empty or not finite");
  }
  if (!(px_per_m > 0.0 && px_per_m <= 1000.0)) {
    throw std::invalid_argument("ViewTransform: px_per_m = " + std::to_string(px_per_m) +
                                " is outside (0, 1000]");
  }
  if (!offset_px.allFinite()) throw std::invalid_argument("ViewTransform: offset is not finite");
}

int ViewTransform::width_px() const {
  return static_cast<int>(std::ceil(px_per_m_ * region_W_m_.sizes().x() - 1e-9));
}

int ViewTransform::height_px() const {
  return static_cast<int>(std::ceil(px_per_m_ * region_W_m_.sizes().y() - 1e-9));
}

Eigen::Vector2d ViewTransform::ToPixel(const Eigen::Vector2d& p_W_m) const {
  return {offset_px_.x() + px_per_m_ * (p_W_m.x() - region_W_m_.min().x()),
          offset_px_.y() + px_per_m_ * (region_W_m_.max().y() - p_W_m.y())};
}

Eigen::Vector2d ViewTransform::ToWorld(const Eigen::Vector2d& p_px) const {
  return {region_W_m_.min().x() + (p_px.x() - offset_px_.x()) / px_per_m_,
          region_W_m_.max().y() - (p_px.y() - offset_px_.y()) / px_per_m_};
}

Eigen::Vector2d ViewTransform::DirectionToPixel(double angle_rad) const {
  return {std::cos(angle_rad), -std::sin(angle_rad)};
}

}  // namespace topay::viz
