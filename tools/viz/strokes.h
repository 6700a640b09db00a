#pragma once

#include <Eigen/Core>
#include <span>

#include "tools/viz/color.h"
#include "tools/viz/image.h"

namespace topay::viz {

/// Strokes for long curves and reference lines, in pixel coordinates (see raster.h).

/// A polyline of many points (a time series, a sampled path), drawn in overlapping runs of at
/// most `run_points` points with raster.h's DrawPolyline, whose cost grows with the product of
/// a run's bounding box and its segment count: a 2000-point series costs about as much as its
/// 2000 segments drawn alone. Runs share their end points, so where two runs meet the line's
/// anti-aliased rim is painted twice (invisible with alpha = 1). Non-finite points split the
/// line (nothing is drawn to or from them). Throws std::invalid_argument for run_points < 2.
void DrawLongPolyline(Image* image, std::span<const Eigen::Vector2d> points_px, const Rgb& colour,
                      double width_px, double alpha = 1.0, int run_points = 16);

/// Dash pattern of DrawDashedLine, in pixels along the line.
struct DashPattern {
  double dash_px = 8.0;
  double gap_px = 5.0;
};

/// A dashed segment from a to b: dashes of dash_px separated by gaps of gap_px, starting with
/// a dash at a (the last dash is cut at b). Nothing is drawn for a non-finite end point or a
/// pattern with dash_px <= 0 or gap_px < 0.
void DrawDashedLine(Image* image, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                    const Rgb& colour, double width_px, const DashPattern& pattern = {},
                    double alpha = 1.0);

}  // namespace topay::viz
