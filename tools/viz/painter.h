#pragma once

#include <cairo.h>

#include <span>
#include <string>

#include <Eigen/Core>

#include "tools/viz/color.h"
#include "tools/viz/image.h"

namespace topay::viz {

/// Dash pattern of dashed strokes, in pixels along the line.
struct DashPattern {
  double dash_px = 8.0;
  double gap_px = 5.0;
};

enum class TextAlign { kLeft, kCentre, kRight };

/// The one place that draws: cairo primitives on an Image, in continuous pixel coordinates
/// (x right, y down; the centre of pixel (i, j) is (i + 0.5, j + 0.5)), anti-aliased. Every
/// primitive composites `colour` with opacity `alpha` (0..1); whatever falls outside the image
/// (or the current clip) is dropped. Text is cairo's toy API in the "sans-serif" face
/// (fontconfig picks it, DejaVu Sans on Debian).
class Painter {
 public:
  explicit Painter(Image* image);
  Painter(Painter&& other) noexcept;
  Painter& operator=(Painter&& other) noexcept;
  Painter(const Painter&) = delete;
  Painter& operator=(const Painter&) = delete;
  ~Painter();

  /// Fills a polygon (even-odd rule). Fewer than 3 vertices: nothing.
  void FillPolygon(std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                   double alpha = 1.0);
  /// Diagonal stripes (slope -1 in pixel space, spacing_px apart, stripe_px wide) inside the
  /// polygon, e.g. to mark floating obstacles.
  void HatchPolygon(std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                    double spacing_px, double stripe_px, double alpha = 1.0);
  /// The segments between consecutive points (and last -> first if `closed`), round joins and
  /// caps. A non-finite point splits the line. A dash pattern with dash_px > 0 dashes it.
  void DrawPolyline(std::span<const Eigen::Vector2d> points_px, bool closed, const Rgb& colour,
                    double width_px, double alpha = 1.0, const DashPattern* dash = nullptr);
  void DrawLine(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, const Rgb& colour,
                double width_px, double alpha = 1.0);
  /// Dashes from a, starting with a dash (butt caps). Nothing for a non-finite end or a pattern
  /// with dash_px <= 0 or gap_px < 0.
  void DrawDashedLine(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                      const Rgb& colour, double width_px, const DashPattern& pattern = {},
                      double alpha = 1.0);
  void FillCircle(const Eigen::Vector2d& centre_px, double radius_px, const Rgb& colour,
                  double alpha = 1.0);
  void StrokeCircle(const Eigen::Vector2d& centre_px, double radius_px, const Rgb& colour,
                    double width_px, double alpha = 1.0);
  /// The rectangle x0 <= x < x1, y0 <= y < y1 (pixel-aligned when the bounds are integers).
  void FillRect(double x0, double y0, double x1, double y1, const Rgb& colour,
                double alpha = 1.0);
  /// Its outline, width_px wide, inside the rectangle.
  void StrokeRect(double x0, double y0, double x1, double y1, const Rgb& colour,
                  double width_px = 1.0);

  /// One line of text, `size_px` high (the font's em size), the top of its line box at y_px:
  /// the baseline lies TextAscent(size_px) below. x_px is its left end, centre or right end.
  void Text(double x_px, double y_px, const std::string& text, const Rgb& colour,
            double size_px, TextAlign align = TextAlign::kLeft);
  /// The same, turned 90 degrees counter-clockwise (reading upwards), centred on (x, y).
  void VerticalText(double x_px, double y_px, const std::string& text, const Rgb& colour,
                    double size_px);

  /// Only draw inside x0 <= x < x1, y0 <= y < y1 until the matching PopClip.
  void PushClip(double x0, double y0, double x1, double y1);
  void PopClip();

  cairo_t* cairo() { return cr_; }

 private:
  void SetSource(const Rgb& colour, double alpha);
  void PathOf(std::span<const Eigen::Vector2d> points, bool closed);

  cairo_t* cr_ = nullptr;
};

/// Advance width in pixels of `text` in the painter's font at size_px.
double TextWidth(const std::string& text, double size_px);
/// Distance from a line box's top to the baseline (size_px), and the line height used for
/// layout: 1.3 size_px (fixed ratios, so layouts do not depend on the font fontconfig finds).
double TextAscent(double size_px);
inline double LineHeight(double size_px) { return 1.3 * size_px; }

}  // namespace topay::viz
