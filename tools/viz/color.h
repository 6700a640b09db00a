#pragma once

#include <cstdint>

namespace topay::viz {

/// An 8-bit sRGB colour.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// A colour in linear light (sRGB primaries, channels in [0, 1]): the space where light adds
/// and luminance is a weighted sum.
struct LinearRgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
};

/// sRGB decoding and encoding (IEC 61966-2-1 transfer function); FromLinear clamps and rounds.
LinearRgb ToLinear(const Rgb& colour);
Rgb FromLinear(const LinearRgb& colour);

/// Relative luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of linear RGB (ITU-R BT.709).
double Luminance(const LinearRgb& colour);

/// Linear interpolation a + t (b - a) per channel in sRGB values, t clamped to [0, 1].
Rgb Lerp(const Rgb& a, const Rgb& b, double t);

/// "Over" compositing: `over` painted with opacity alpha (clamped to [0, 1]) onto `under`:
/// out = alpha * over + (1 - alpha) * under (Porter and Duff, 1984, opaque background).
Rgb Blend(const Rgb& under, const Rgb& over, double alpha);

/// Relative luminance in [0, 1] of an sRGB colour: Luminance(ToLinear(colour)).
double RelativeLuminance(const Rgb& colour);

/// Named colours used by the drawings (constants, not state).
namespace colors {
inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kBlack{0, 0, 0};
inline constexpr Rgb kPaper{250, 250, 247};       ///< Background outside the map.
inline constexpr Rgb kInk{30, 30, 30};            ///< Text and outlines.
inline constexpr Rgb kStart{0, 90, 181};          ///< Start pose (blue).
inline constexpr Rgb kGoal{213, 94, 0};           ///< Goal pose (vermilion).
inline constexpr Rgb kTarget{204, 0, 102};        ///< End-effector target (magenta).
}  // namespace colors

}  // namespace topay::viz
