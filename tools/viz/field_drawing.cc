#include "tools/viz/field_drawing.h"

#include "tools/viz/color_map.h"

namespace topay::viz {

Rgb DistanceColour(double distance_m, const FieldDrawingOptions& options) {
  if (!(distance_m > 0.0)) return colors::kObstacleCore;  // Also NaN: never looks free.
  return Viridis(ScalarRange{0.0, options.clip_m}.Normalize(distance_m));
}

void DrawDistanceField(WorldCanvas* canvas, const SignedDistanceField2& field,
                       const FieldDrawingOptions& options) {
  const ViewTransform& view = canvas->view();
  const GridGeometry2& grid = field.geometry();
  Image& image = canvas->image();
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Eigen::Vector2d p_W = view.ToWorld(Eigen::Vector2d(x + 0.5, y + 0.5));
      if (!grid.Contains(p_W)) continue;
      image.Set(x, y, DistanceColour(field.Distance(p_W), options));
    }
  }
}

}  // namespace topay::viz
