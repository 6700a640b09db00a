#pragma once

#include <functional>
#include <string>

#include "tools/viz/color.h"
#include "tools/viz/painter.h"
#include "tools/viz/view_transform.h"

namespace topay::viz {

/// Where a legend item was put (pixels, x0 <= x < x1, y0 <= y < y1).
struct LegendBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

/// Lays legend items out left to right in a strip, wrapping to a new row when an item would
/// pass the right edge. With a null painter it only measures (run the same calls twice: once
/// to learn height(), once to draw).
class LegendLayout {
 public:
  /// The strip starts at (x0, y0) and is `width_px` wide; text is font_px high.
  LegendLayout(Painter* painter, double x0, double y0, double width_px, double font_px);

  /// Text in ink.
  void Text(const std::string& text, const Rgb& colour = colors::kInk);
  /// A small square filled with `fill` (outlined in `outline`), then a label.
  void Swatch(const Rgb& fill, const Rgb& outline, const std::string& label,
              bool hatched = false);
  /// A short line in `colour`, then a label (a series of a chart).
  void LineKey(const Rgb& colour, double width_px, const std::string& label);
  /// "caption low [colour bar] high": the bar samples colour_of(t) for t in [0, 1], t = 0 at
  /// its left end; 10 font heights long, shorter (to 3) in a narrow strip. Returns its box.
  LegendBox ColourBar(const std::string& caption, const std::function<Rgb(double)>& colour_of,
                      const std::string& low, const std::string& high);
  /// A bar of a round length in metres (1, 2 or 5 x 10^k) close to `target_px` at the view's
  /// scale, with end ticks and its length as label, e.g. "2 m". Returns the bar's box.
  LegendBox ScaleBar(const ViewTransform& view, double target_px = 100.0);
  /// Ends the current row.
  void NewRow();

  /// Height in pixels used so far, counting the current row.
  double height() const;

  /// The round scale-bar length (m) for a view: the largest of 1, 2, 5 x 10^k whose pixel
  /// length does not exceed target_px (at least 0.01 m).
  static double ScaleBarLength(const ViewTransform& view, double target_px);

 private:
  double RowHeight() const;
  double Gap() const;
  double Top() const;
  // Reserves an item `width` wide and returns its left x (wrapping if needed).
  double Place(double width);

  Painter* painter_;
  double x0_;
  double y0_;
  double width_;
  double font_;
  double pen_x_;
  int row_ = 0;
  bool row_empty_ = true;
};

}  // namespace topay::viz
