#include "tools/viz/color.h"

#include <algorithm>
#include <cmath>

namespace topay::viz {
namespace {

std::uint8_t RoundToByte(double value) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
}

// sRGB electro-optical transfer function (IEC 61966-2-1): 8-bit code value -> linear light.
double SrgbToLinear(std::uint8_t code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Its inverse (IEC 61966-2-1): linear light in [0, 1] -> 8-bit code value.
std::uint8_t LinearToSrgb(double linear) {
  linear = std::isnan(linear) ? 0.0 : std::clamp(linear, 0.0, 1.0);
  const double c =
      linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return RoundToByte(255.0 * c);
}

}  // namespace

LinearRgb ToLinear(const Rgb& colour) {
  return {SrgbToLinear(colour.r), SrgbToLinear(colour.g), SrgbToLinear(colour.b)};
}

Rgb FromLinear(const LinearRgb& colour) {
  return {LinearToSrgb(colour.r), LinearToSrgb(colour.g), LinearToSrgb(colour.b)};
}

double Luminance(const LinearRgb& colour) {
  return 0.2126 * colour.r + 0.7152 * colour.g + 0.0722 * colour.b;
}

Rgb Lerp(const Rgb& a, const Rgb& b, double t) {
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  return {RoundToByte(a.r + t * (b.r - a.r)), RoundToByte(a.g + t * (b.g - a.g)),
          RoundToByte(a.b + t * (b.b - a.b))};
}

Rgb Blend(const Rgb& under, const Rgb& over, double alpha) { return Lerp(under, over, alpha); }

double RelativeLuminance(const Rgb& colour) { return Luminance(ToLinear(colour)); }

}  // namespace topay::viz
