#pragma once

#include "core/map/signed_distance_field2.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

struct FieldDrawingOptions {
  /// Distances (m) from 0 up to this clip value are spread over the whole viridis map (dark
  /// purple at contact, yellow at clip_m and beyond). Inside obstacles (distance <= 0) is
  /// painted colors::kObstacleCore, darker than any map colour.
  double clip_m = 2.0;
};

/// Paints the base's 2D signed distance field under everything else: each pixel whose centre
/// lies inside the field's grid gets the colour of the interpolated distance there. Pixels
/// outside the grid are left as they are.
void DrawDistanceField(WorldCanvas* canvas, const SignedDistanceField2& field,
                       const FieldDrawingOptions& options = {});

/// The colour DrawDistanceField gives to a distance (for legends and tests).
Rgb DistanceColour(double distance_m, const FieldDrawingOptions& options = {});

}  // namespace topay::viz
