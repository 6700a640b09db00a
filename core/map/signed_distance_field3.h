#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/map/distance_transform.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid3.h"
#include "core/map/signed_distance_values.h"

namespace topay {

/// A signed Euclidean distance field (m) over a 3D occupancy grid: positive in free space,
/// negative deep inside obstacles.
///
/// Cell values (float) come from two exact Euclidean distance transforms: D_out, the squared
/// distance in cells from a free cell's centre to the nearest occupied cell's centre, and D_in,
/// from an occupied cell's centre to the nearest free cell's centre, where the world beyond the
/// grid counts as free (a wall on the grid's edge is shallow near its outer face too). They are
/// combined as SignedDistanceFieldOptions documents: by default the zero level lies on the
/// centres of the boundary occupied cells, the unbiased estimate of a surface rasterised
/// conservatively (OccupancyGrid3::AddBox) or seen as point hits: measured within one cell of
/// the exact signed distance to the boxes (tests/core/map/signed_distance_field3_test.cc).
///
/// Queries interpolate the 8 surrounding cell-centre values trilinearly; the gradient is the
/// exact derivative of that interpolant (consistent with Distance for optimizers; at a cell
/// boundary, where the interpolant has a kink, it is the one-sided derivative from the upper
/// cell). Outside the box spanned by the first and last cell centres (including the outer half
/// cell of the grid), a query point p is clamped to its nearest point c in that box and
///   Distance(p) = Distance(c) + |p - c|,
/// continuous, with gradient (clamped axes' derivative zero) + (p - c) / |p - c|: the world
/// beyond the map is assumed free and the field keeps rising away from it. A NaN coordinate
/// gives NaN. If the grid has no occupied cell, every value is +max_distance_m() (the length
/// of the grid's diagonal, farther than any obstacle inside the grid could be): large, finite,
/// with zero gradient.
class SignedDistanceField3 {
 public:
  /// Builds the field with two exact squared EDTs (outside: sites = occupied cells; inside:
  /// sites = free cells). The workspace, if given, is reused across builds (no allocation once
  /// warmed up apart from the field's own storage); otherwise a local one is used.
  static SignedDistanceField3 Build(const OccupancyGrid3& occupancy,
                                    const SignedDistanceFieldOptions& options = {},
                                    EdtWorkspace* workspace = nullptr);

  /// Rebuilds in place from `occupancy` (same or different geometry), reusing this field's
  /// storage and the workspace.
  void Rebuild(const OccupancyGrid3& occupancy, const SignedDistanceFieldOptions& options = {},
               EdtWorkspace* workspace = nullptr);

  const GridGeometry3& geometry() const { return geometry_; }
  double max_distance_m() const { return max_distance_m_; }
  /// Signed distance (m) stored for a cell's centre.
  float CellValue(int ix, int iy, int iz) const { return values_[geometry_.Index(ix, iy, iz)]; }
  const std::vector<float>& values() const { return values_; }

  /// Interpolated signed distance (m) at p_W, see the class comment.
  double Distance(const Eigen::Vector3d& p_W) const { return Interpolate(p_W, nullptr); }

  /// Distance(p_W) and its gradient with respect to p_W (dimensionless, in W).
  double DistanceAndGradient(const Eigen::Vector3d& p_W, Eigen::Vector3d* gradient_W) const {
    return Interpolate(p_W, gradient_W);
  }

 private:
  SignedDistanceField3() = default;
  inline double Interpolate(const Eigen::Vector3d& p_W, Eigen::Vector3d* gradient_W) const;

  GridGeometry3 geometry_;
  double inv_resolution_ = 10.0;
  double max_distance_m_ = 0.0;
  std::vector<float> values_;
};

inline double SignedDistanceField3::Interpolate(const Eigen::Vector3d& p_W,
                                                Eigen::Vector3d* gradient_W) const {
  const GridGeometry3& g = geometry_;
  double t[3];
  double outside_m[3];
  bool clamped[3];
  int base[3];
  for (int a = 0; a < 3; ++a) {
    // Continuous index in which cell centre i sits at u = i.
    const double u = (p_W(a) - g.origin_W_m(a)) * inv_resolution_ - 0.5;
    const double last = g.dims(a) - 1;
    double u_clamped = u > 0.0 ? u : 0.0;  // NaN goes to 0 here and propagates via outside_m.
    u_clamped = u_clamped < last ? u_clamped : last;
    outside_m[a] = (u - u_clamped) * g.resolution_m;
    clamped[a] = u != u_clamped;
    base[a] = std::min(static_cast<int>(u_clamped), g.dims(a) - 2);
    t[a] = u_clamped - base[a];
  }
  const std::int64_t sx = 1;
  const std::int64_t sy = g.dims.x();
  const std::int64_t sz = sy * g.dims.y();
  const float* c = values_.data() + g.Index(base[0], base[1], base[2]);
  const double c000 = c[0], c100 = c[sx], c010 = c[sy], c110 = c[sy + sx];
  const double c001 = c[sz], c101 = c[sz + sx], c011 = c[sz + sy], c111 = c[sz + sy + sx];
  // Trilinear interpolation as three rounds of linear interpolation, x then y then z
  // (e.g. Press et al., Numerical Recipes 3rd ed., Sec. 3.6, eq. 3.6.5 applied per axis).
  const double c00 = c000 + t[0] * (c100 - c000);
  const double c10 = c010 + t[0] * (c110 - c010);
  const double c01 = c001 + t[0] * (c101 - c001);
  const double c11 = c011 + t[0] * (c111 - c011);
  const double c0 = c00 + t[1] * (c10 - c00);
  const double c1 = c01 + t[1] * (c11 - c01);
  double distance = c0 + t[2] * (c1 - c0);
  if (gradient_W) {
    // Exact partial derivatives of the interpolant in t, times dt/dp = 1 / res (zero on an axis
    // where p was clamped).
    const double d_dtz = c1 - c0;
    const double d_dty = (1.0 - t[2]) * (c10 - c00) + t[2] * (c11 - c01);
    const double d_dtx =
        (1.0 - t[2]) * ((1.0 - t[1]) * (c100 - c000) + t[1] * (c110 - c010)) +
        t[2] * ((1.0 - t[1]) * (c101 - c001) + t[1] * (c111 - c011));
    *gradient_W = Eigen::Vector3d(clamped[0] ? 0.0 : d_dtx * inv_resolution_,
                                  clamped[1] ? 0.0 : d_dty * inv_resolution_,
                                  clamped[2] ? 0.0 : d_dtz * inv_resolution_);
  }
  const double outside_sq = outside_m[0] * outside_m[0] + outside_m[1] * outside_m[1] +
                            outside_m[2] * outside_m[2];
  if (outside_sq != 0.0) {  // also taken for NaN, which then propagates
    const double outside_norm = std::sqrt(outside_sq);
    distance += outside_norm;
    if (gradient_W) {
      *gradient_W += Eigen::Vector3d(outside_m[0], outside_m[1], outside_m[2]) / outside_norm;
    }
  }
  return distance;
}

}  // namespace topay
