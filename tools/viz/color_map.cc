#include "tools/viz/color_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace topay::viz {
namespace {

// Piecewise-linear interpolation through equally spaced anchors, t in [0, 1].
template <std::size_t N>
Rgb Interpolate(const std::array<Rgb, N>& anchors, double t) {
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  const double position = t * (N - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), N - 2);
  return Lerp(anchors[i], anchors[i + 1], position - static_cast<double>(i));
}

// viridis sampled at t = 0, 1/8, ..., 1 (the published colour values, as hex #440154 ...).
constexpr std::array<Rgb, 9> kViridisAnchors = {{{0x44, 0x01, 0x54},
                                                 {0x47, 0x2c, 0x7a},
                                                 {0x3b, 0x51, 0x8b},
                                                 {0x2c, 0x71, 0x8e},
                                                 {0x21, 0x90, 0x8d},
                                                 {0x27, 0xad, 0x81},
                                                 {0x5c, 0xc8, 0x63},
                                                 {0xaa, 0xdc, 0x32},
                                                 {0xfd, 0xe7, 0x25}}};

constexpr std::array<Rgb, 4> kWarmAnchors = {
    {{255, 237, 160}, {254, 178, 76}, {227, 74, 51}, {128, 0, 38}}};

}  // namespace

LinearRgb ViridisLinear(double t) {
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  constexpr std::size_t kN = kViridisAnchors.size();
  const double position = t * (kN - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), kN - 2);
  const double f = position - static_cast<double>(i);
  const LinearRgb a = ToLinear(kViridisAnchors[i]);
  const LinearRgb b = ToLinear(kViridisAnchors[i + 1]);
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

double ScalarRange::Normalize(double value) const {
  if (std::isnan(value) || !(max > min)) return 0.0;
  return std::clamp((value - min) / (max - min), 0.0, 1.0);
}

Rgb Viridis(double t) { return FromLinear(ViridisLinear(t)); }

Rgb GreyRamp(double t) {
  const Rgb light{224, 224, 224};
  const Rgb dark{77, 77, 77};
  return Lerp(light, dark, t);
}

Rgb WarmRamp(double t) { return Interpolate(kWarmAnchors, t); }

Rgb CategoryColour(int k) {
  static constexpr Rgb kPalette[] = {{0, 114, 178}, {213, 94, 0},   {0, 158, 115}, {204, 121, 167},
                                     {230, 159, 0}, {86, 180, 233}, {0, 0, 0}};
  const int n = static_cast<int>(std::size(kPalette));
  return kPalette[((k % n) + n) % n];
}

}  // namespace topay::viz
