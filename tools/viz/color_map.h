#pragma once

#include "tools/viz/color.h"

namespace topay::viz {

/// A closed interval of scalar values mapped onto a colour map's [0, 1].
struct ScalarRange {
  double min = 0.0;
  double max = 1.0;

  /// (value - min) / (max - min), clamped to [0, 1]; NaN maps to 0.
  double Normalize(double value) const;
};

/// Perceptually ordered sequential map: the 9 anchor colours of matplotlib's "viridis" (van der
/// Walt and Smith, 2015), interpolated linearly in linear light. Dark purple at 0, yellow at 1.
/// The anchors' luminances increase and luminance is linear in linear light, so the
/// unquantised map (ViridisLinear) has strictly increasing luminance and reads correctly in
/// grey too. t is clamped to [0, 1]; NaN maps to 0.
Rgb Viridis(double t);
LinearRgb ViridisLinear(double t);

/// Grey ramp for heights: light grey (0.88) at t = 0 to dark grey (0.30) at 1, so that taller
/// is darker and both ends stay distinct from white paper and black ink.
Rgb GreyRamp(double t);

/// Warm ramp for arm heights: pale yellow at 0 through orange to dark red at 1 (luminance
/// decreasing), distinct from both the viridis field and the grey obstacles.
Rgb WarmRamp(double t);

/// The distinct colour of category k (0-based; the palette of Okabe and Ito, 2008, without its
/// yellow, repeating after 7): joints of a plot, methods of a benchmark.
Rgb CategoryColour(int k);

}  // namespace topay::viz
