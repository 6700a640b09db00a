#pragma once

#include <string_view>

#include "tools/viz/color.h"
#include "tools/viz/image.h"

namespace topay::viz {

/// A fixed-width 5 x 7 pixel font (hand-drawn glyphs for digits, upper- and lower-case letters,
/// space and . , : ; - + = / ( ) [ ] % _ # < > ' ! ?; any other character draws as a hollow box).
/// Each glyph cell is 6 x 9 pixels (one pixel of spacing, two below for descenders), times
/// `scale`.
struct BitmapFont {
  static constexpr int kGlyphWidth = 5;
  static constexpr int kGlyphHeight = 7;
  static constexpr int kAdvance = 6;     ///< Horizontal step per character at scale 1.
  static constexpr int kLineHeight = 10; ///< Vertical step per line at scale 1.

  /// Pixel width and height of `text` on one line at `scale`.
  static int TextWidth(std::string_view text, int scale);
  static int TextHeight(int scale) { return kGlyphHeight * scale; }

  /// True if glyph `c` has its pixel (column, row) set (column 0..4, row 0..6 from the top).
  /// Characters descending below the baseline (g, p, q, y) are shifted down by 2 rows when
  /// drawn.
  static bool GlyphPixel(char c, int column, int row);
};

/// Draws `text` (one line; '\n' starts a new line) with its top-left corner at (x_px, y_px),
/// each font pixel a scale x scale block.
void DrawText(Image* image, int x_px, int y_px, std::string_view text, const Rgb& colour,
              int scale = 1);

}  // namespace topay::viz
