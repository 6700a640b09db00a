#include "tools/viz/box_drawing.h"

#include <algorithm>
#include <numeric>

#include "tools/viz/shapes.h"

namespace topay::viz {
namespace {

double TopHeight(const OrientedBox& box) { return box.center_W_m.z() + 0.5 * box.size_m.z(); }

void DrawOneBox(WorldCanvas* canvas, const OrientedBox& box, const BoxDrawingOptions& options) {
  const auto corners =
      RectangleCorners(box.center_W_m.head<2>(), box.size_m.head<2>(), box.yaw_rad);
  const Rgb shade = GreyRamp(options.top_height_m.Normalize(TopHeight(box)));
  if (IsRaised(box, options)) {
    canvas->FillPolygon(corners, shade, options.raised_fill_alpha);
    canvas->HatchPolygon(corners, Lerp(shade, colors::kInk, 0.4), options.hatch_spacing_px, 1.0);
    canvas->DrawPolyline(corners, /*closed=*/true, Lerp(shade, colors::kInk, 0.4),
                         1.5 * options.outline_px);
    return;
  }
  canvas->FillPolygon(corners, shade);
  canvas->DrawPolyline(corners, /*closed=*/true, colors::kInk, options.outline_px);
}

}  // namespace

bool IsRaised(const OrientedBox& box, const BoxDrawingOptions& options) {
  return box.center_W_m.z() - 0.5 * box.size_m.z() > options.raised_above_m;
}

void DrawBoxes(WorldCanvas* canvas, const std::vector<OrientedBox>& boxes,
               const BoxDrawingOptions& options) {
  std::vector<std::size_t> order(boxes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return TopHeight(boxes[a]) < TopHeight(boxes[b]);
  });
  for (std::size_t i : order) DrawOneBox(canvas, boxes[i], options);
}

}  // namespace topay::viz
