#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace topay::sim {

/// The simulated LiDAR's non-repetitive scan pattern (Livox Mid-360-like: the field of view
/// fills in more densely the longer one integrates, and no two scans share their rays).
///
/// Ray n (a global index: ray k of scan s is n = s * points_per_scan + k) takes the n-th point
/// of Roberts' R2 sequence, the 2D golden-ratio (Weyl) sequence built on the plastic number
/// g = 1.3247... (the real root of g^3 = g + 1):
///   (u_n, v_n) = frac(1/2 + n / g, 1/2 + n / g^2),
/// a low-discrepancy sequence: any window of consecutive indices covers the unit square
/// evenly, and since 1/g and 1/g^2 are irrational it never repeats. u maps to the azimuth and
/// v to the sine of the elevation, so that the rays are uniform per solid angle over the
/// field of view (a band of the sphere):
///   azimuth   = 2 pi u,
///   sin(elev) = sin(elev_min) + v (sin(elev_max) - sin(elev_min)),
///   d_S = (cos(elev) cos(azimuth), cos(elev) sin(azimuth), sin(elev)).
/// The fractions are computed exactly in 64-bit fixed point (n * round(2^64 / g) modulo 2^64),
/// so ray n is the same on every platform, for any n < 2^64.
class ScanPattern {
 public:
  ScanPattern(double elevation_min_rad, double elevation_max_rad);

  /// Unit direction of ray n in the sensor frame S.
  Eigen::Vector3d Direction(std::uint64_t n) const;

  /// (u_n, v_n) in [0, 1)^2 (exposed for tests).
  static Eigen::Vector2d Fractions(std::uint64_t n);

 private:
  double sin_min_;
  double sin_span_;
};

}  // namespace topay::sim
