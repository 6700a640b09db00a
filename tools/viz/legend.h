#pragma once

#include <functional>
#include <string>

#include "tools/viz/color.h"
#include "tools/viz/image.h"
#include "tools/viz/view_transform.h"

namespace topay::viz {

/// Lays legend items out left to right in a strip of an image, wrapping to a new row when an
/// item would pass the right edge. With a null image it only measures (Run the same calls
/// twice: once to learn height(), once to draw).
class LegendLayout {
 public:
  /// The strip starts at (x0, y0) and is `width_px` wide; text uses the bitmap font at
  /// text_scale.
  LegendLayout(Image* image, int x0, int y0, int width_px, int text_scale);

  /// Text in ink.
  void Text(const std::string& text, const Rgb& colour = colors::kInk);
  /// A small square filled with `fill` (outlined in `outline`), then a label.
  void Swatch(const Rgb& fill, const Rgb& outline, const std::string& label,
              bool hatched = false);
  /// "caption low [colour bar] high": the bar samples colour_of(t) for t in [0, 1].
  void ColourBar(const std::string& caption, const std::function<Rgb(double)>& colour_of,
                 const std::string& low, const std::string& high);
  /// A bar of a round length in metres (1, 2 or 5 x 10^k) close to `target_px` at the view's
  /// scale, with end ticks and its length as label, e.g. "2 m".
  void ScaleBar(const ViewTransform& view, int target_px = 100);
  /// Ends the current row.
  void NewRow();

  /// Height in pixels used so far, counting the current row.
  int height() const;

  /// The round scale-bar length (m) for a view: the largest of 1, 2, 5 x 10^k whose pixel
  /// length does not exceed target_px (at least 0.01 m).
  static double ScaleBarLength(const ViewTransform& view, int target_px);

 private:
  int RowHeight() const;
  int Gap() const;
  // Reserves an item `width` wide and returns its left x (wrapping if needed).
  int Place(int width);

  Image* image_;
  int x0_;
  int y0_;
  int width_;
  int scale_;
  int pen_x_;
  int row_ = 0;
  bool row_empty_ = true;
};

}  // namespace topay::viz
