#include "tools/viz/strokes.h"

#include <algorithm>
#include <stdexcept>

#include "tools/viz/raster.h"

namespace topay::viz {

void DrawLongPolyline(Image* image, std::span<const Eigen::Vector2d> points_px, const Rgb& colour,
                      double width_px, double alpha, int run_points) {
  if (run_points < 2) {
    throw std::invalid_argument("DrawLongPolyline: run_points must be at least 2, got " +
                                std::to_string(run_points));
  }
  const std::size_t n = points_px.size();
  std::size_t begin = 0;
  while (begin < n) {
    // A run of finite points [begin, end), at most run_points long.
    while (begin < n && !points_px[begin].allFinite()) ++begin;
    std::size_t end = begin;
    while (end < n && end - begin < static_cast<std::size_t>(run_points) &&
           points_px[end].allFinite()) {
      ++end;
    }
    if (end > begin) {
      DrawPolyline(image, points_px.subspan(begin, end - begin), /*closed=*/false, colour, width_px,
                   alpha);
    }
    // The next run starts at this run's last point, unless the run ended at a gap.
    const bool at_gap = end >= n || !points_px[end].allFinite();
    begin = (at_gap || end - begin < 2) ? end : end - 1;
  }
}

void DrawDashedLine(Image* image, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                    const Rgb& colour, double width_px, const DashPattern& pattern, double alpha) {
  if (!a_px.allFinite() || !b_px.allFinite() || !(pattern.dash_px > 0.0) ||
      !(pattern.gap_px >= 0.0)) {
    return;
  }
  const double length = (b_px - a_px).norm();
  if (length == 0.0) return;
  const Eigen::Vector2d direction = (b_px - a_px) / length;
  const double period = pattern.dash_px + pattern.gap_px;
  for (double start = 0.0; start < length; start += period) {
    const double stop = std::min(start + pattern.dash_px, length);
    DrawLine(image, a_px + start * direction, a_px + stop * direction, colour, width_px, alpha);
  }
}

}  // namespace topay::viz
