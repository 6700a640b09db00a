#include "tools/viz/field_drawing.h"

#include <algorithm>

namespace topay::viz {

ScalarRange FieldValueRange(const SignedDistanceField2& field) {
  const std::vector<float>& values = field.values();
  if (values.empty()) return {0.0, 1.0};
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  ScalarRange range{*lo, *hi};
  if (!(range.max > range.min)) range = {range.min - 5e-4, range.min + 5e-4};
  return range;
}

ScalarRange DistanceColourRange(const SignedDistanceField2& field,
                                const FieldDrawingOptions& options) {
  return options.range_m ? *options.range_m : FieldValueRange(field);
}

Rgb DistanceColour(double distance_m, const ScalarRange& range_m) {
  return Viridis(range_m.Normalize(distance_m));
}

void DrawDistanceField(WorldCanvas* canvas, const SignedDistanceField2& field,
                       const FieldDrawingOptions& options) {
  const ViewTransform& view = canvas->view();
  const GridGeometry2& grid = field.geometry();
  const ScalarRange range = DistanceColourRange(field, options);
  const Eigen::Vector2d& offset = view.offset_px();
  const double u1 = offset.x() + view.width_px(), v1 = offset.y() + view.height_px();
  canvas->image().SetPixels([&](int x, int y) -> std::optional<Rgb> {
    const Eigen::Vector2d p_px(x + 0.5, y + 0.5);
    if (p_px.x() < offset.x() || p_px.y() < offset.y() || p_px.x() > u1 || p_px.y() > v1) {
      return std::nullopt;
    }
    const Eigen::Vector2d p_W = view.ToWorld(p_px);
    if (!grid.Contains(p_W)) return std::nullopt;
    return DistanceColour(field.Distance(p_W), range);
  });
}

}  // namespace topay::viz
