#include "tools/viz/png_io.h"

#include <png.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace topay::viz {
namespace {

std::runtime_error PngError(const std::string& path, const std::string& action,
                            const png_image& png) {
  std::string reason = png.message[0] != '\0' ? png.message : "unknown libpng error";
  return std::runtime_error(path + ": " + action + ": " + reason);
}

}  // namespace

void WritePng(const Image& image, const std::string& path) {
  // libpng's simplified API reports a failed fopen only as "png_image_write_to_file: open
  // failed"; open the file ourselves to name the reason.
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
  }
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width());
  png.height = static_cast<png_uint_32>(image.height());
  png.format = PNG_FORMAT_RGB;
  const bool ok = png_image_write_to_stdio(&png, file, /*convert_to_8bit=*/0,
                                           image.bytes().data(), /*row_stride=*/0,
                                           /*colormap=*/nullptr) != 0;
  const bool closed = std::fclose(file) == 0;
  if (!ok) throw PngError(path, "cannot write PNG", png);
  if (!closed) throw std::runtime_error(path + ": cannot write PNG: " + std::strerror(errno));
}

Image ReadPng(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw std::runtime_error(path + ": cannot open for reading: " + std::strerror(errno));
  }
  if (png_image_begin_read_from_stdio(&png, file) == 0) {
    std::fclose(file);
    throw PngError(path, "not a valid PNG", png);
  }
  png.format = PNG_FORMAT_RGB;
  if (png.width == 0 || png.height == 0 || png.width > Image::kMaxSidePx ||
      png.height > Image::kMaxSidePx) {
    png_image_free(&png);
    std::fclose(file);
    throw std::runtime_error(path + ": PNG size " + std::to_string(png.width) + " x " +
                             std::to_string(png.height) + " is not supported");
  }
  std::vector<std::uint8_t> buffer(PNG_IMAGE_SIZE(png));
  const bool ok = png_image_finish_read(&png, /*background=*/nullptr, buffer.data(),
                                        /*row_stride=*/0, /*colormap=*/nullptr) != 0;
  std::fclose(file);
  if (!ok) throw PngError(path, "not a valid PNG", png);
  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width() + x);
      image.Set(x, y, {buffer[i], buffer[i + 1], buffer[i + 2]});
    }
  }
  return image;
}

}  // namespace topay::viz
