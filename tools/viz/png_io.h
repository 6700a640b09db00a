#pragma once

#include <string>

#include "tools/viz/image.h"

namespace topay::viz {

/// Writes an 8-bit RGB PNG (libpng). Throws std::runtime_error "<path>: <reason>" if the file
/// cannot be written (missing folder, no permission, ...).
void WritePng(const Image& image, const std::string& path);

/// Reads any PNG libpng understands, converted to 8-bit RGB by libpng's simplified API (which
/// also removes an alpha channel). Throws std::runtime_error "<path>: <reason>" if the file is
/// missing or not a valid PNG.
Image ReadPng(const std::string& path);

}  // namespace topay::viz
