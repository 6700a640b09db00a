#pragma once

#include <vector>

#include "core/geometry/scene.h"
#include "tools/viz/color_map.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

struct BoxDrawingOptions {
  /// Top heights (m) mapped onto the grey ramp: taller is darker. The renderer uses the scene's
  /// map height (Scene::bounds_W_m z range).
  ScalarRange top_height_m{0.0, 1.6};
  /// A box whose bottom is higher than this above the floor is "raised" (floating cubes,
  /// table tops): drawn translucent and hatched so what lies under it stays visible.
  double raised_above_m = 0.01;
  double outline_px = 1.0;
  double raised_fill_alpha = 0.35;
  double hatch_spacing_px = 5.0;
};

/// True if the box's bottom face is above options.raised_above_m.
bool IsRaised(const OrientedBox& box, const BoxDrawingOptions& options);

/// Draws every box's footprint (its rotated rectangle) seen from above, in order of increasing
/// top height so taller boxes cover lower ones: grounded boxes filled opaque with the grey of
/// their top height and outlined in ink; raised boxes filled translucent in that grey, hatched
/// with diagonal stripes and outlined in the grey.
void DrawBoxes(WorldCanvas* canvas, const std::vector<OrientedBox>& boxes,
               const BoxDrawingOptions& options = {});

}  // namespace topay::viz
