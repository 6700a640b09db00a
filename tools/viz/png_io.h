#pragma once

#include <string>

#include "tools/viz/image.h"

namespace topay::viz {

/// Writes the image as a PNG (cairo_surface_write_to_png). Throws std::runtime_error
/// "<path>: <reason>" if the file cannot be written (missing folder, no permission, ...).
void WritePng(const Image& image, const std::string& path);

/// Reads a PNG (cairo_image_surface_create_from_png), converted to RGB over white if it has an
/// alpha channel. Throws std::runtime_error "<path>: <reason>" if the file is missing or not a
/// valid PNG.
Image ReadPng(const std::string& path);

}  // namespace topay::viz
