#include "sim/lidar/scan_pattern.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace topay::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMin = -7.0 * kPi / 180.0;
constexpr double kMax = 52.0 * kPi / 180.0;
constexpr int kPerScan = 20000;

TEST(ScanPatternTest, FractionsAreTheR2Sequence) {
  // frac(1/2 + n / g), frac(1/2 + n / g^2), g the plastic number (g^3 = g + 1).
  const long double g = 1.32471795724474602596090885447809734L;
  for (std::uint64_t n : {0ULL, 1ULL, 2ULL, 17ULL, 12345ULL, 999999ULL}) {
    const long double u = 0.5L + static_cast<long double>(n) / g;
    const long double v = 0.5L + static_cast<long double>(n) / (g * g);
    const Eigen::Vector2d f = ScanPattern::Fractions(n);
    EXPECT_NEAR(f.x(), static_cast<double>(u - std::floor(u)), 1e-12) << n;
    EXPECT_NEAR(f.y(), static_cast<double>(v - std::floor(v)), 1e-12) << n;
  }
}

TEST(ScanPatternTest, DirectionsAreUnitAndInsideTheFieldOfView) {
  const ScanPattern pattern(kMin, kMax);
  double lowest = 1.0, highest = -1.0;
  for (std::uint64_t n = 0; n < 3 * kPerScan; ++n) {
    const Eigen::Vector3d d = pattern.Direction(n);
    ASSERT_NEAR(d.norm(), 1.0, 1e-12);
    const double elevation = std::asin(d.z());
    ASSERT_GE(elevation, kMin - 1e-12);
    ASSERT_LE(elevation, kMax + 1e-12);
    lowest = std::min(lowest, elevation);
    highest = std::max(highest, elevation);
  }
  // The edges of the field of view are reached (within 0.1 deg).
  EXPECT_NEAR(lowest, kMin, 0.1 * kPi / 180.0);
  EXPECT_NEAR(highest, kMax, 0.1 * kPi / 180.0);
}

// One scan's rays fall evenly into equal-solid-angle cells: 36 azimuth sectors x 6 bands
// equal in sin(elevation), about 93 rays per cell.
TEST(ScanPatternTest, OneScanCoversTheFieldOfViewEvenly) {
  const ScanPattern pattern(kMin, kMax);
  constexpr int kAz = 36, kEl = 6;
  std::vector<int> counts(kAz * kEl, 0);
  const double s0 = std::sin(kMin), s1 = std::sin(kMax);
  for (int scan = 0; scan < 3; ++scan) {
    std::fill(counts.begin(), counts.end(), 0);
    for (int k = 0; k < kPerScan; ++k) {
      const Eigen::Vector3d d = pattern.Direction(std::uint64_t(scan) * kPerScan + k);
      double azimuth = std::atan2(d.y(), d.x());
      if (azimuth < 0) azimuth += 2 * kPi;
      const int a = std::min(kAz - 1, static_cast<int>(azimuth / (2 * kPi) * kAz));
      const int e = std::min(kEl - 1, static_cast<int>((d.z() - s0) / (s1 - s0) * kEl));
      ++counts[a * kEl + e];
    }
    const double expected = double(kPerScan) / (kAz * kEl);
    for (int c : counts) {
      EXPECT_GT(c, 0.9 * expected) << "scan " << scan;
      EXPECT_LT(c, 1.1 * expected) << "scan " << scan;
    }
  }
}

TEST(ScanPatternTest, ConsecutiveScansShareNoRay) {
  const ScanPattern pattern(kMin, kMax);
  std::set<std::pair<double, double>> first;
  for (int k = 0; k < kPerScan; ++k) {
    const Eigen::Vector3d d = pattern.Direction(k);
    first.insert({d.x(), d.z()});
  }
  int shared = 0;
  for (int k = 0; k < kPerScan; ++k) {
    const Eigen::Vector3d d = pattern.Direction(kPerScan + k);
    shared += first.count({d.x(), d.z()}) > 0 ? 1 : 0;
  }
  EXPECT_EQ(shared, 0);
  // Ray k of scan 1 is not ray k of scan 0.
  const Eigen::Vector3d a = pattern.Direction(5), b = pattern.Direction(kPerScan + 5);
  EXPECT_GT((a - b).norm(), 1e-6);
}

TEST(ScanPatternTest, SameIndexSameDirection) {
  const ScanPattern a(kMin, kMax), b(kMin, kMax);
  for (std::uint64_t n : {0ULL, 7ULL, 123456789ULL, (1ULL << 40) + 3}) {
    EXPECT_EQ(a.Direction(n), b.Direction(n));
  }
}

}  // namespace
}  // namespace topay::sim
