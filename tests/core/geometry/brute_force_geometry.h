#pragma once

// Brute-force references for the exact distance functions: everything here works only from
// sampled surface points, never from the formulas under test.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "core/common/random.h"
#include "core/geometry/oriented_box.h"
#include "core/geometry/vertical_cylinder.h"

namespace topay::testing {

using Points = std::vector<Eigen::Vector3d>;

/// Corners of the box (its support points) and a grid of n x n points on each face.
inline Points SampleBoxSurface(const OrientedBox& box, int n) {
  const double c = std::cos(box.yaw_rad);
  const double s = std::sin(box.yaw_rad);
  const Eigen::Vector3d h = box.HalfSize();
  Points points;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3;
    const int b = (axis + 2) % 3;
    for (const double side : {-1.0, 1.0}) {
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          Eigen::Vector3d p_B;
          p_B(axis) = side * h(axis);
          p_B(a) = h(a) * (2.0 * i / n - 1.0);
          p_B(b) = h(b) * (2.0 * j / n - 1.0);
          points.push_back(box.center_W_m +
                           Eigen::Vector3d(c * p_B.x() - s * p_B.y(), s * p_B.x() + c * p_B.y(),
                                           p_B.z()));
        }
      }
    }
  }
  return points;
}

/// The rims (top and bottom circles, `n` points each), the side wall and both caps.
inline Points SampleCylinderSurface(const VerticalCylinder& cylinder, int n, int n_rings) {
  Points points;
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / n;
    const Eigen::Vector2d rim =
        cylinder.axis_W_m + cylinder.radius_m * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    for (int ring = 0; ring <= n_rings; ++ring) {
      const double z = cylinder.bottom_z_m + cylinder.height_m * ring / n_rings;
      points.emplace_back(rim.x(), rim.y(), z);  // side wall, rims at ring 0 and n_rings
      const double f = static_cast<double>(ring) / n_rings;  // caps: concentric circles
      const Eigen::Vector2d cap = cylinder.axis_W_m + f * (rim - cylinder.axis_W_m);
      points.emplace_back(cap.x(), cap.y(), cylinder.bottom_z_m);
      points.emplace_back(cap.x(), cap.y(), cylinder.top_z_m());
    }
  }
  return points;
}

/// n points spread over the unit sphere (Fibonacci lattice).
inline Points FibonacciDirections(int n) {
  Points directions;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    directions.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return directions;
}

inline Points SampleSphereSurface(const Eigen::Vector3d& center, double radius, int n) {
  Points points = FibonacciDirections(n);
  for (Eigen::Vector3d& p : points) p = center + radius * p;
  return points;
}

/// Gap of two point sets along unit direction u: min_b u.b - max_a u.a (support functions).
inline double GapAlong(const Points& a, const Points& b, const Eigen::Vector3d& u) {
  double max_a = -std::numeric_limits<double>::infinity();
  double min_b = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : a) max_a = std::max(max_a, u.dot(p));
  for (const Eigen::Vector3d& p : b) min_b = std::min(min_b, u.dot(p));
  return min_b - max_a;
}

/// Signed distance of the convex hulls of two surface samples: max over unit directions of
/// the gap (positive: distance when apart; negative: minus the penetration depth, the
/// shortest separating translation). Coarse direction grid, then a random local search with
/// shrinking steps from the best few directions.
inline double BruteForceConvexSignedDistance(const Points& a, const Points& b) {
  const Points grid = FibonacciDirections(2000);
  std::vector<std::pair<double, Eigen::Vector3d>> scored;
  for (const Eigen::Vector3d& u : grid) scored.emplace_back(GapAlong(a, b, u), u);
  std::partial_sort(scored.begin(), scored.begin() + 6, scored.end(),
                    [](const auto& x, const auto& y) { return x.first > y.first; });
  Rng rng(12345);
  double best_overall = -std::numeric_limits<double>::infinity();
  for (int start = 0; start < 6; ++start) {
    auto [best, u] = scored[start];
    for (double step = 0.05; step > 1e-7; step *= 0.7) {
      for (int trial = 0; trial < 12; ++trial) {
        const Eigen::Vector3d candidate =
            (u + step * Eigen::Vector3d(rng.Normal(), rng.Normal(), rng.Normal())).normalized();
        const double gap = GapAlong(a, b, candidate);
        if (gap > best) {
          best = gap;
          u = candidate;
        }
      }
    }
    best_overall = std::max(best_overall, best);
  }
  return best_overall;
}

}  // namespace topay::testing
