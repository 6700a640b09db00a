#include "tools/viz/image.h"

#include <stdexcept>
#include <string>

namespace topay::viz {

Image::Image(int width_px, int height_px, Rgb fill) : width_(width_px), height_(height_px) {
  if (width_px <= 0 || height_px <= 0 || width_px > kMaxSidePx || height_px > kMaxSidePx) {
    throw std::invalid_argument("Image: size " + std::to_string(width_px) + " x " +
                                std::to_string(height_px) + " px is outside 1.." +
                                std::to_string(kMaxSidePx));
  }
  bytes_.resize(3 * static_cast<std::size_t>(width_) * height_);
  Fill(fill);
}

Rgb Image::At(int x, int y) const {
  if (!Contains(x, y)) {
    throw std::out_of_range("Image::At: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is outside the image");
  }
  const std::size_t i = Offset(x, y);
  return {bytes_[i], bytes_[i + 1], bytes_[i + 2]};
}

void Image::Set(int x, int y, const Rgb& colour) {
  if (!Contains(x, y)) return;
  const std::size_t i = Offset(x, y);
  bytes_[i] = colour.r;
  bytes_[i + 1] = colour.g;
  bytes_[i + 2] = colour.b;
}

void Image::Paint(int x, int y, const Rgb& colour, double alpha) {
  if (!Contains(x, y) || !(alpha > 0.0)) return;
  Set(x, y, alpha >= 1.0 ? colour : Blend(At(x, y), colour, alpha));
}

void Image::Fill(const Rgb& colour) {
  for (std::size_t i = 0; i < bytes_.size(); i += 3) {
    bytes_[i] = colour.r;
    bytes_[i + 1] = colour.g;
    bytes_[i + 2] = colour.b;
  }
}

}  // namespace topay::viz
