#include "sim/lidar/scan_pattern.h"

#include <algorithm>
#include <cmath>

namespace topay::sim {
namespace {

// round(2^64 / g) and round(2^64 / g^2), g the plastic number (R2 sequence constants).
constexpr std::uint64_t kAlpha1 = 0xc13fa9a902a6328fULL;
constexpr std::uint64_t kAlpha2 = 0x91e10da5c79e7b1cULL;
constexpr std::uint64_t kHalf = 0x8000000000000000ULL;  // the sequence's 1/2 offset
constexpr double kTwoPi = 6.28318530717958647693;

// A 64-bit fixed-point fraction to [0, 1): its top 53 bits.
double ToUnit(std::uint64_t fraction) { return static_cast<double>(fraction >> 11) * 0x1.0p-53; }

}  // namespace

ScanPattern::ScanPattern(double elevation_min_rad, double elevation_max_rad)
    : sin_min_(std::sin(elevation_min_rad)),
      sin_span_(std::sin(elevation_max_rad) - std::sin(elevation_min_rad)) {}

Eigen::Vector2d ScanPattern::Fractions(std::uint64_t n) {
  // frac(1/2 + n alpha) in fixed point: unsigned arithmetic wraps modulo 2^64 = 1.0.
  return {ToUnit(kHalf + n * kAlpha1), ToUnit(kHalf + n * kAlpha2)};
}

Eigen::Vector3d ScanPattern::Direction(std::uint64_t n) const {
  const Eigen::Vector2d uv = Fractions(n);
  const double azimuth = kTwoPi * uv.x();
  // Uniform in sin(elevation): equal solid angle per unit of v.
  const double sin_elevation = sin_min_ + uv.y() * sin_span_;
  const double cos_elevation = std::sqrt(std::max(0.0, 1.0 - sin_elevation * sin_elevation));
  return {cos_elevation * std::cos(azimuth), cos_elevation * std::sin(azimuth), sin_elevation};
}

}  // namespace topay::sim
