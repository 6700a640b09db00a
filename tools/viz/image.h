#pragma once

#include <cstdint>
#include <vector>

#include "tools/viz/color.h"

namespace topay::viz {

/// An RGB raster image, row-major, top row first (the PNG order). Pixel (x, y) covers the square
/// [x, x + 1) x [y, y + 1) in pixel coordinates, x to the right, y down. Writes outside the image
/// are ignored, so drawing code never needs to clip.
class Image {
 public:
  /// Throws std::invalid_argument unless 0 < width, height <= kMaxSidePx.
  Image(int width_px, int height_px, Rgb fill = colors::kWhite);

  static constexpr int kMaxSidePx = 16384;

  int width() const { return width_; }
  int height() const { return height_; }
  bool Contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  /// Colour at (x, y); throws std::out_of_range outside the image.
  Rgb At(int x, int y) const;
  /// Sets (x, y) if it is inside the image.
  void Set(int x, int y, const Rgb& colour);
  /// Composites colour with opacity alpha onto (x, y) if it is inside (see Blend).
  void Paint(int x, int y, const Rgb& colour, double alpha);
  void Fill(const Rgb& colour);

  /// Interleaved RGB bytes, 3 * width * height, row-major from the top row.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::size_t Offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x));
  }

  int width_;
  int height_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace topay::viz
