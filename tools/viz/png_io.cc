#include "tools/viz/png_io.h"

#include <filesystem>
#include <stdexcept>

namespace topay::viz {

void WritePng(const Image& image, const std::string& path) {
  cairo_surface_flush(image.surface());
  const cairo_status_t status = cairo_surface_write_to_png(image.surface(), path.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(path + ": cannot write the PNG: " + cairo_status_to_string(status));
  }
}

Image ReadPng(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error(path + ": not a readable file");
  }
  return Image::Adopt(cairo_image_surface_create_from_png(path.c_str()),
                     path + ": not a valid PNG");
}

}  // namespace topay::viz
