#pragma once

#include <optional>

#include "core/map/signed_distance_field2.h"
#include "tools/viz/color_map.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {

struct FieldDrawingOptions {
  /// Distances (m) spread over the whole viridis map (dark purple at min, yellow at max).
  /// Unset (the default): the values the field holds, FieldValueRange.
  std::optional<ScalarRange> range_m;
};

/// The smallest and largest cell value of the field (m): negative inside obstacles, up to the
/// cap of the values far from them. A field of equal values gets a range 1 mm wide around it.
ScalarRange FieldValueRange(const SignedDistanceField2& field);

/// The colour scale DrawDistanceField uses: options.range_m if set, else FieldValueRange.
ScalarRange DistanceColourRange(const SignedDistanceField2& field,
                                const FieldDrawingOptions& options = {});

/// The colour of a distance on a range (for the legend and tests): Viridis(range.Normalize(d)).
Rgb DistanceColour(double distance_m, const ScalarRange& range_m);

/// Paints the base's 2D signed distance field under everything else: each pixel whose centre
/// lies inside the field's grid (and inside the view's block) gets the colour of the
/// interpolated distance there on DistanceColourRange. Other pixels are left as they are.
void DrawDistanceField(WorldCanvas* canvas, const SignedDistanceField2& field,
                       const FieldDrawingOptions& options = {});

}  // namespace topay::viz
