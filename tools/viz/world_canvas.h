#pragma once

#include <span>
#include <utility>

#include <Eigen/Core>

#include "tools/viz/color.h"
#include "tools/viz/image.h"
#include "tools/viz/painter.h"
#include "tools/viz/view_transform.h"

namespace topay::viz {

/// An image with a view of the floor plane: drawing primitives in world coordinates (metres,
/// y up). Sizes of shapes are in metres; stroke widths and arrow heads in pixels, so outlines
/// stay visible at any scale. This is the surface every top-down drawing (scenes, tasks,
/// trajectories) paints on. With `clip_to_view`, nothing is drawn outside the view's block.
class WorldCanvas {
 public:
  WorldCanvas(Image image, const ViewTransform& view, bool clip_to_view = false);

  Image& image() { return image_; }
  const Image& image() const { return image_; }
  const ViewTransform& view() const { return view_; }
  Painter& painter() { return painter_; }

  void FillPolygon(std::span<const Eigen::Vector2d> vertices_W_m, const Rgb& colour,
                   double alpha = 1.0);
  void HatchPolygon(std::span<const Eigen::Vector2d> vertices_W_m, const Rgb& colour,
                    double spacing_px, double stripe_px, double alpha = 1.0);
  void DrawPolyline(std::span<const Eigen::Vector2d> points_W_m, bool closed, const Rgb& colour,
                    double width_px, double alpha = 1.0);
  void DrawLine(const Eigen::Vector2d& a_W_m, const Eigen::Vector2d& b_W_m, const Rgb& colour,
                double width_px, double alpha = 1.0);
  void FillCircle(const Eigen::Vector2d& centre_W_m, double radius_m, const Rgb& colour,
                  double alpha = 1.0);
  void StrokeCircle(const Eigen::Vector2d& centre_W_m, double radius_m, const Rgb& colour,
                    double width_px, double alpha = 1.0);
  /// A shaft from `from` to `to` with a filled head at `to` (head_px long).
  void DrawArrow(const Eigen::Vector2d& from_W_m, const Eigen::Vector2d& to_W_m,
                 const Rgb& colour, double width_px, double head_px, double alpha = 1.0);

 private:
  Image image_;
  ViewTransform view_;
  Painter painter_;
};

}  // namespace topay::viz
