#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay::viz {

/// Maps the world's floor plane (x, y in metres, y up) onto pixel coordinates (x right, y down):
/// the rectangle `region_W_m` fills a width_px() x height_px() block of pixels whose top-left
/// corner is at `offset_px`, at `px_per_m` pixels per metre.
///   u = offset_u + px_per_m (x - x_min),   v = offset_v + px_per_m (y_max - y).
class ViewTransform {
 public:
  /// Throws std::invalid_argument if the region is empty or not finite, or px_per_m is not in
  /// (0, 1000].
  ViewTransform(const Eigen::AlignedBox2d& region_W_m, double px_per_m,
                const Eigen::Vector2d& offset_px = Eigen::Vector2d::Zero());

  const Eigen::AlignedBox2d& region_W_m() const { return region_W_m_; }
  double px_per_m() const { return px_per_m_; }
  const Eigen::Vector2d& offset_px() const { return offset_px_; }
  /// Size in whole pixels of the block covering the region (rounded up).
  int width_px() const;
  int height_px() const;

  Eigen::Vector2d ToPixel(const Eigen::Vector2d& p_W_m) const;
  Eigen::Vector2d ToWorld(const Eigen::Vector2d& p_px) const;
  double ToPixels(double length_m) const { return px_per_m_ * length_m; }
  /// Unit pixel-space vector of the world direction at angle_rad (counter-clockwise from +x):
  /// (cos, -sin), since pixel y points down.
  Eigen::Vector2d DirectionToPixel(double angle_rad) const;

 private:
  Eigen::AlignedBox2d region_W_m_;
  double px_per_m_;
  Eigen::Vector2d offset_px_;
};

}  // namespace topay::viz
