#include "tools/viz/image.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace topay::viz {
namespace {

std::uint32_t Pack(const Rgb& c) {
  return (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | std::uint32_t{c.b};
}

cairo_surface_t* MakeSurface(int width_px, int height_px) {
  if (width_px <= 0 || height_px <= 0 || width_px > Image::kMaxSidePx ||
      height_px > Image::kMaxSidePx) {
    throw std::invalid_argument("Image: size " + std::to_string(width_px) + " x " +
                                std::to_string(height_px) + " px is outside 1.." +
                                std::to_string(Image::kMaxSidePx));
  }
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_px, height_px);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    const std::string reason = cairo_status_to_string(cairo_surface_status(surface));
    cairo_surface_destroy(surface);
    throw std::runtime_error("Image: cannot create a " + std::to_string(width_px) + " x " +
                             std::to_string(height_px) + " px surface: " + reason);
  }
  return surface;
}

// A new RGB24 surface with `from` painted over white.
cairo_surface_t* CopyOverWhite(cairo_surface_t* from) {
  cairo_surface_t* to = MakeSurface(cairo_image_surface_get_width(from),
                                    cairo_image_surface_get_height(from));
  cairo_t* cr = cairo_create(to);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  cairo_set_source_surface(cr, from, 0.0, 0.0);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(to);
  return to;
}

}  // namespace

Image::Image(cairo_surface_t* surface)
    : surface_(surface),
      width_(cairo_image_surface_get_width(surface)),
      height_(cairo_image_surface_get_height(surface)) {}

Image::Image(int width_px, int height_px, Rgb fill) : Image(MakeSurface(width_px, height_px)) {
  SetPixels([&](int, int) { return std::optional<Rgb>(fill); });
}

Image Image::Adopt(cairo_surface_t* surface, const std::string& what) {
  const cairo_status_t status = cairo_surface_status(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw std::runtime_error(what + ": " + cairo_status_to_string(status));
  }
  if (cairo_surface_get_type(surface) == CAIRO_SURFACE_TYPE_IMAGE &&
      cairo_image_surface_get_format(surface) == CAIRO_FORMAT_RGB24) {
    return Image(surface);
  }
  cairo_surface_t* copy = nullptr;
  try {
    copy = CopyOverWhite(surface);
  } catch (...) {
    cairo_surface_destroy(surface);
    throw;
  }
  cairo_surface_destroy(surface);
  return Image(copy);
}

Image::Image(const Image& other) : Image(CopyOverWhite(other.surface_)) {}

Image& Image::operator=(const Image& other) {
  if (this != &other) *this = Image(other);
  return *this;
}

Image::Image(Image&& other) noexcept
    : surface_(std::exchange(other.surface_, nullptr)),
      width_(other.width_),
      height_(other.height_) {}

Image& Image::operator=(Image&& other) noexcept {
  std::swap(surface_, other.surface_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  return *this;
}

Image::~Image() {
  if (surface_ != nullptr) cairo_surface_destroy(surface_);
}

Rgb Image::At(int x, int y) const {
  if (!Contains(x, y)) {
    throw std::out_of_range("Image::At: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is outside the image");
  }
  cairo_surface_flush(surface_);
  const unsigned char* row =
      cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
  std::uint32_t pixel;
  std::memcpy(&pixel, row + 4 * x, sizeof pixel);
  return {static_cast<std::uint8_t>(pixel >> 16), static_cast<std::uint8_t>(pixel >> 8),
          static_cast<std::uint8_t>(pixel)};
}

void Image::SetPixels(const std::function<std::optional<Rgb>(int x, int y)>& colour_of) {
  cairo_surface_flush(surface_);
  unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::optional<Rgb> colour = colour_of(x, y);
      if (!colour) continue;
      const std::uint32_t pixel = Pack(*colour);
      std::memcpy(data + y * stride + 4 * x, &pixel, sizeof pixel);
    }
  }
  cairo_surface_mark_dirty(surface_);
}

}  // namespace topay::viz
