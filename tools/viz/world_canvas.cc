#include "tools/viz/world_canvas.h"

#include <algorithm>
#include <vector>

#include "tools/viz/shapes.h"

namespace topay::viz {
namespace {

std::vector<Eigen::Vector2d> ToPixels(const ViewTransform& view,
                                      std::span<const Eigen::Vector2d> points_W_m) {
  std::vector<Eigen::Vector2d> points_px;
  points_px.reserve(points_W_m.size());
  for (const Eigen::Vector2d& p_W : points_W_m) points_px.push_back(view.ToPixel(p_W));
  return points_px;
}

}  // namespace

WorldCanvas::WorldCanvas(Image image, const ViewTransform& view, bool clip_to_view)
    : image_(std::move(image)), view_(view), painter_(&image_) {
  if (clip_to_view) {
    const Eigen::Vector2d& o = view_.offset_px();
    painter_.PushClip(o.x(), o.y(), o.x() + view_.width_px(), o.y() + view_.height_px());
  }
}

void WorldCanvas::FillPolygon(std::span<const Eigen::Vector2d> vertices_W_m, const Rgb& colour,
                              double alpha) {
  painter_.FillPolygon(ToPixels(view_, vertices_W_m), colour, alpha);
}

void WorldCanvas::HatchPolygon(std::span<const Eigen::Vector2d> vertices_W_m, const Rgb& colour,
                               double spacing_px, double stripe_px, double alpha) {
  painter_.HatchPolygon(ToPixels(view_, vertices_W_m), colour, spacing_px, stripe_px, alpha);
}

void WorldCanvas::DrawPolyline(std::span<const Eigen::Vector2d> points_W_m, bool closed,
                               const Rgb& colour, double width_px, double alpha) {
  painter_.DrawPolyline(ToPixels(view_, points_W_m), closed, colour, width_px, alpha);
}

void WorldCanvas::DrawLine(const Eigen::Vector2d& a_W_m, const Eigen::Vector2d& b_W_m,
                           const Rgb& colour, double width_px, double alpha) {
  painter_.DrawLine(view_.ToPixel(a_W_m), view_.ToPixel(b_W_m), colour, width_px, alpha);
}

void WorldCanvas::FillCircle(const Eigen::Vector2d& centre_W_m, double radius_m,
                             const Rgb& colour, double alpha) {
  painter_.FillCircle(view_.ToPixel(centre_W_m), view_.ToPixels(radius_m), colour, alpha);
}

void WorldCanvas::StrokeCircle(const Eigen::Vector2d& centre_W_m, double radius_m,
                               const Rgb& colour, double width_px, double alpha) {
  painter_.StrokeCircle(view_.ToPixel(centre_W_m), view_.ToPixels(radius_m), colour, width_px,
                        alpha);
}

void WorldCanvas::DrawArrow(const Eigen::Vector2d& from_W_m, const Eigen::Vector2d& to_W_m,
                            const Rgb& colour, double width_px, double head_px, double alpha) {
  const Eigen::Vector2d from_px = view_.ToPixel(from_W_m);
  const Eigen::Vector2d to_px = view_.ToPixel(to_W_m);
  const Eigen::Vector2d along = to_px - from_px;
  if (!(along.norm() > 0.0)) return;
  const Eigen::Vector2d direction = along.normalized();
  // The shaft stops where the head begins, so a translucent arrow is not painted twice.
  const Eigen::Vector2d shaft_end = to_px - std::min(head_px, along.norm()) * direction;
  painter_.DrawLine(from_px, shaft_end, colour, width_px, alpha);
  const auto head = ArrowHead(to_px, direction, head_px, 0.8 * head_px);
  painter_.FillPolygon(head, colour, alpha);
}

}  // namespace topay::viz
