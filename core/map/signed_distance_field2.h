#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/map/distance_transform.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_values.h"

namespace topay {

/// The 2D counterpart of SignedDistanceField3, in the world xy plane, for the mobile base:
/// built from an OccupancyGrid2 (e.g. OccupancyGrid2::AddBoxInBand over the chassis band).
/// Same cell values (exact EDTs, beyond the grid counts as free, zero level placed by
/// SignedDistanceFieldOptions, +max_distance_m() everywhere for a grid without occupied cells),
/// bilinear interpolation with its exact gradient, and the same
/// behaviour outside the box of cell centres: clamp to its nearest point c and add |p - c|.
class SignedDistanceField2 {
 public:
  /// A band of obstacles lowered into this field with an offset (LowerTo): wherever
  /// Distance(p) >= d + exactness_margin_m(), every obstacle in `band` is at least
  /// d - offset_m from p in xy. Lets the base field stand for the robot's rigid parts above the
  /// chassis (core/planning/base_band.h).
  struct OffsetBand {
    HeightBand band;
    double offset_m = 0.0;
  };

  /// Builds the field (two exact squared EDTs); the workspace, if given, is reused.
  static SignedDistanceField2 Build(const OccupancyGrid2& occupancy,
                                    const SignedDistanceFieldOptions& options = {},
                                    EdtWorkspace* workspace = nullptr);
  void Rebuild(const OccupancyGrid2& occupancy, const SignedDistanceFieldOptions& options = {},
               EdtWorkspace* workspace = nullptr);

  /// Cell by cell: value <- min(value, other's value + offset_m). Both fields must share one
  /// geometry (std::invalid_argument otherwise, also for a non-finite offset). The result is
  /// still 1-Lipschitz between neighbouring cells, and its interpolant is at most the minimum
  /// of the two interpolants (interpolation is a convex combination), so a point that clears a
  /// requirement on the result clears it on both fields.
  void LowerTo(const SignedDistanceField2& other, double offset_m);

  /// A field from given cell values (x fastest, geometry.NumCells() of them), e.g. exact
  /// distances (core/map/footprint_distance_field.h). exactness_margin_m: see below. Throws
  /// std::invalid_argument for a wrong count, an invalid geometry or a negative margin.
  static SignedDistanceField2 FromCellValues(const GridGeometry2& geometry,
                                             std::vector<float> values, double max_distance_m,
                                             double exactness_margin_m);

  const GridGeometry2& geometry() const { return geometry_; }
  double max_distance_m() const { return max_distance_m_; }
  /// How far the interpolated Distance(p) may exceed the exact signed distance at p: a point
  /// with Distance(p) >= d + exactness_margin_m() is at least d from every obstacle (for d
  /// below any cap of the values). Built from an occupancy grid (EDT between cell centres,
  /// plus the rasterisation): sqrt(2) x the cell size. Exact values at the cell centres (a
  /// 1-Lipschitz function sampled): the bilinear interpolant's bound, cell size / sqrt(2).
  /// LowerTo keeps the larger of the two fields' margins.
  double exactness_margin_m() const { return exactness_margin_m_; }

  /// The offset band this field holds, if its builder declared one (BuildSceneDistanceFields
  /// does for SceneDistanceFieldsOptions::base_upper_band). Only declare what LowerTo put in.
  const std::optional<OffsetBand>& offset_band() const { return offset_band_; }
  void set_offset_band(const OffsetBand& band) { offset_band_ = band; }
  float CellValue(int ix, int iy) const { return values_[geometry_.Index(ix, iy)]; }
  const std::vector<float>& values() const { return values_; }

  /// Interpolated signed distance (m) at p_W (xy).
  double Distance(const Eigen::Vector2d& p_W) const { return Interpolate(p_W, nullptr); }

  /// Distance(p_W) and its gradient with respect to p_W.
  double DistanceAndGradient(const Eigen::Vector2d& p_W, Eigen::Vector2d* gradient_W) const {
    return Interpolate(p_W, gradient_W);
  }

 private:
  SignedDistanceField2() = default;
  inline double Interpolate(const Eigen::Vector2d& p_W, Eigen::Vector2d* gradient_W) const;

  GridGeometry2 geometry_;
  double inv_resolution_ = 10.0;
  double max_distance_m_ = 0.0;
  double exactness_margin_m_ = 0.0;
  std::optional<OffsetBand> offset_band_;
  std::vector<float> values_;
};

inline double SignedDistanceField2::Interpolate(const Eigen::Vector2d& p_W,
                                                Eigen::Vector2d* gradient_W) const {
  const GridGeometry2& g = geometry_;
  double t[2];
  double outside_m[2];
  bool clamped[2];
  int base[2];
  for (int a = 0; a < 2; ++a) {
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
  const std::int64_t sy = g.dims.x();
  const float* c = values_.data() + g.Index(base[0], base[1]);
  const double c00 = c[0], c10 = c[1], c01 = c[sy], c11 = c[sy + 1];
  // Bilinear interpolation: linear in x on both rows, then in y (Numerical Recipes 3rd ed.,
  // eq. 3.6.5).
  const double c0 = c00 + t[0] * (c10 - c00);
  const double c1 = c01 + t[0] * (c11 - c01);
  double distance = c0 + t[1] * (c1 - c0);
  if (gradient_W) {
    // Exact partial derivatives of the interpolant, times dt/dp = 1 / res (0 where clamped).
    const double d_dty = c1 - c0;
    const double d_dtx = (1.0 - t[1]) * (c10 - c00) + t[1] * (c11 - c01);
    *gradient_W = Eigen::Vector2d(clamped[0] ? 0.0 : d_dtx * inv_resolution_,
                                  clamped[1] ? 0.0 : d_dty * inv_resolution_);
  }
  const double outside_sq = outside_m[0] * outside_m[0] + outside_m[1] * outside_m[1];
  if (outside_sq != 0.0) {  // also taken for NaN, which then propagates
    const double outside_norm = std::sqrt(outside_sq);
    distance += outside_norm;
    if (gradient_W) *gradient_W += Eigen::Vector2d(outside_m[0], outside_m[1]) / outside_norm;
  }
  return distance;
}

}  // namespace topay
