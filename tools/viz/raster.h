#pragma once

#include <span>

#include <Eigen/Core>

#include "tools/viz/color.h"
#include "tools/viz/image.h"

namespace topay::viz {

/// Drawing primitives in continuous pixel coordinates (x right, y down; the centre of pixel
/// (i, j) is (i + 0.5, j + 0.5)). Every primitive composites `colour` with opacity `alpha`
/// (0..1) and ignores whatever falls outside the image.
///
/// Fills of polygons are crisp (a pixel is painted when its centre is inside, even-odd rule);
/// lines and circles are anti-aliased by coverage (opacity fades over the last pixel).

/// Fills a simple or self-intersecting polygon (even-odd rule). Fewer than 3 vertices: nothing.
void FillPolygon(Image* image, std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                 double alpha = 1.0);

/// Fills the inside of a polygon with diagonal stripes (lines of slope -1 in pixel space,
/// `spacing_px` apart, `stripe_px` wide), e.g. to mark floating obstacles.
void HatchPolygon(Image* image, std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                  int spacing_px, int stripe_px, double alpha = 1.0);

/// Draws the segments between consecutive points (and last->first if `closed`), width_px wide
/// with round joins and caps. Overlapping segments are painted once (no double blending).
void DrawPolyline(Image* image, std::span<const Eigen::Vector2d> points_px, bool closed,
                  const Rgb& colour, double width_px, double alpha = 1.0);

/// One thick segment (see DrawPolyline).
void DrawLine(Image* image, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
              const Rgb& colour, double width_px, double alpha = 1.0);

void FillCircle(Image* image, const Eigen::Vector2d& centre_px, double radius_px,
                const Rgb& colour, double alpha = 1.0);

/// The ring of points at distance radius_px from the centre, width_px wide.
void StrokeCircle(Image* image, const Eigen::Vector2d& centre_px, double radius_px,
                  const Rgb& colour, double width_px, double alpha = 1.0);

/// Pixel-aligned rectangle of the pixels x0 <= x < x1, y0 <= y < y1 (for legends and text).
void FillRect(Image* image, int x0, int y0, int x1, int y1, const Rgb& colour,
              double alpha = 1.0);

}  // namespace topay::viz
