#pragma once

#include <cairo.h>

#include <functional>
#include <optional>
#include <string>

#include "tools/viz/color.h"

namespace topay::viz {

/// An RGB raster image held by a cairo image surface (CAIRO_FORMAT_RGB24), top row first (the
/// PNG order). Pixel (x, y) covers the square [x, x + 1) x [y, y + 1) in pixel coordinates,
/// x to the right, y down. Drawing goes through a Painter (tools/viz/painter.h) on the surface;
/// the image itself only creates, copies and reads pixels.
class Image {
 public:
  /// Throws std::invalid_argument unless 0 < width, height <= kMaxSidePx.
  Image(int width_px, int height_px, Rgb fill = colors::kWhite);
  /// Takes over `surface` (one reference), converted to RGB24 over white if it has another
  /// format. Throws std::runtime_error "<what>: <cairo's reason>" if the surface is in error.
  static Image Adopt(cairo_surface_t* surface, const std::string& what);

  Image(const Image& other);
  Image& operator=(const Image& other);
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  ~Image();

  static constexpr int kMaxSidePx = 16384;

  int width() const { return width_; }
  int height() const { return height_; }
  bool Contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  /// Colour at (x, y); throws std::out_of_range outside the image.
  Rgb At(int x, int y) const;
  /// Sets every pixel for which colour_of(x, y) gives a colour (one pass, for per-pixel maps
  /// such as a distance field).
  void SetPixels(const std::function<std::optional<Rgb>(int x, int y)>& colour_of);

  /// The cairo surface, owned by the image (a cairo_t made on it holds its own reference).
  cairo_surface_t* surface() const { return surface_; }

 private:
  explicit Image(cairo_surface_t* surface);

  cairo_surface_t* surface_ = nullptr;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace topay::viz
