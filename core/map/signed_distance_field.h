#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/map/distance_transform.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid.h"
#include "core/map/signed_distance_values.h"

namespace topay {

/// A signed Euclidean distance field (m) of dimension Dim over an occupancy grid: positive
/// in free space, negative deep inside obstacles. Dim = 3 (SignedDistanceField3): the world,
/// for the arm; Dim = 2 (SignedDistanceField2): the world xy plane, for the mobile base. One
/// implementation for both; the 2D and 3D names are aliases.
///
/// Cell values (float) come from two exact Euclidean distance transforms: D_out, the squared
/// distance in cells from a free cell's centre to the nearest occupied cell's centre, and D_in,
/// from an occupied cell's centre to the nearest free cell's centre, where the world beyond the
/// grid counts as free (a wall on the grid's edge is shallow near its outer face too). They are
/// combined as SignedDistanceFieldOptions documents: by default the zero level lies on the
/// centres of the boundary occupied cells, the unbiased estimate of a surface rasterised
/// conservatively (OccupancyGrid3::AddBox) or seen as point hits: measured within one cell of
/// the exact signed distance to the boxes (tests/core/map/signed_distance_field3_test.cc).
/// Or given cell values (FromCellValues, e.g. exact distances: footprint_distance_field.h).
///
/// Queries interpolate the 2^Dim surrounding cell-centre values (bilinearly, trilinearly);
/// the gradient is the exact derivative of that interpolant (consistent with Distance for
/// optimizers; at a cell boundary, where the interpolant has a kink, it is the one-sided
/// derivative from the upper cell). Outside the box spanned by the first and last cell
/// centres (including the outer half cell of the grid), a query point p is clamped to its
/// nearest point c in that box and
///   Distance(p) = Distance(c) + |p - c|,
/// continuous, with gradient (clamped axes' derivative zero) + (p - c) / |p - c|: the world
/// beyond the map is assumed free and the field keeps rising away from it. A NaN coordinate
/// gives NaN. If the grid has no occupied cell, every value is +max_distance_m() (the length
/// of the grid's diagonal, farther than any obstacle inside the grid could be): large, finite,
/// with zero gradient.
template <int Dim>
class SignedDistanceField {
  static_assert(Dim == 2 || Dim == 3, "SignedDistanceField: 2 or 3 dimensions");

 public:
  using Geometry = GridGeometry<Dim>;
  using Point = Eigen::Matrix<double, Dim, 1>;

  /// A band of obstacles lowered into this field with an offset (LowerTo): wherever
  /// Distance(p) >= d + exactness_margin_m(), every obstacle in `band` is at least
  /// d - offset_m from p in xy. Lets the base field stand for the robot's rigid parts above the
  /// chassis (core/planning/base_band.h).
  struct OffsetBand {
    HeightBand band;
    double offset_m = 0.0;
  };

  /// Builds the field with two exact squared EDTs (outside: sites = occupied cells; inside:
  /// sites = free cells). The workspace, if given, is reused across builds (no allocation once
  /// warmed up apart from the field's own storage); otherwise a local one is used.
  static SignedDistanceField Build(const OccupancyGrid<Dim>& occupancy,
                                   const SignedDistanceFieldOptions& options = {},
                                   EdtWorkspace* workspace = nullptr);

  /// Rebuilds in place from `occupancy` (same or different geometry), reusing this field's
  /// storage and the workspace. Validates first, so a bad option leaves the field as it was.
  void Rebuild(const OccupancyGrid<Dim>& occupancy, const SignedDistanceFieldOptions& options = {},
               EdtWorkspace* workspace = nullptr);

  /// A field from given cell values (x fastest, geometry.NumCells() of them), e.g. exact
  /// distances (core/map/footprint_distance_field.h). exactness_margin_m: see below. Throws
  /// std::invalid_argument for a wrong count, an invalid geometry or a negative margin.
  static SignedDistanceField FromCellValues(const Geometry& geometry, std::vector<float> values,
                                            double max_distance_m, double exactness_margin_m);

  /// Cell by cell: value <- min(value, other's value + offset_m). Both fields must share one
  /// geometry (std::invalid_argument otherwise, also for a non-finite offset). The result is
  /// still 1-Lipschitz between neighbouring cells, and its interpolant is at most the minimum
  /// of the two interpolants (interpolation is a convex combination), so a point that clears a
  /// requirement on the result clears it on both fields. The first LowerTo keeps the field as
  /// it was before as primary_band().
  void LowerTo(const SignedDistanceField& other, double offset_m);

  /// The field of this field's own obstacles alone, as it was before the first LowerTo (for
  /// the base field: the obstacles the base cylinder itself can touch, without the band
  /// lowered in for the parts above it); null if nothing was lowered in. The lowered field is
  /// never above it, so it matters only where a requirement on the lowered field is relaxed
  /// (near a start or goal under a table top: EndpointRelief).
  const SignedDistanceField* primary_band() const { return primary_band_.get(); }

  const Geometry& geometry() const { return geometry_; }
  double max_distance_m() const { return max_distance_m_; }
  /// How far the interpolated Distance(p) may exceed the exact signed distance at p: a point
  /// with Distance(p) >= d + exactness_margin_m() is at least d from every obstacle (for d
  /// below any cap of the values). Built from an occupancy grid (EDT between cell centres,
  /// plus the rasterisation): sqrt(Dim) x the cell size. Exact values at the cell centres (a
  /// 1-Lipschitz function sampled): the interpolant's bound, e.g. cell size / sqrt(2) in 2D.
  /// LowerTo keeps the larger of the two fields' margins.
  double exactness_margin_m() const { return exactness_margin_m_; }

  /// The offset band this field holds, if its builder declared one (BuildSceneDistanceFields
  /// does for SceneDistanceFieldsOptions::base_upper_band). Only declare what LowerTo put in.
  const std::optional<OffsetBand>& offset_band() const { return offset_band_; }
  void set_offset_band(const OffsetBand& band) { offset_band_ = band; }

  /// Signed distance (m) stored for a cell's centre.
  template <typename... Ints>
    requires(sizeof...(Ints) == Dim)
  float CellValue(Ints... index) const {
    return values_[geometry_.Index(index...)];
  }
  const std::vector<float>& values() const { return values_; }

  /// For incremental builders (core/map/voxel_map_fields.h), which overwrite the values of the
  /// cells a map change affects: this field's cell values, and those of its primary_band()
  /// (null if it has none; copied first if a copy of this field shares it, so copies never
  /// change). The caller keeps what the class documents true of the values (exactness margin,
  /// max_distance_m(), the lowered field never above the primary band).
  std::vector<float>* mutable_values() { return &values_; }
  std::vector<float>* mutable_primary_band_values();

  /// Interpolated signed distance (m) at p_W, see the class comment.
  double Distance(const Point& p_W) const { return Interpolate(p_W, nullptr); }

  /// Distance(p_W) and its gradient with respect to p_W (dimensionless, in W).
  double DistanceAndGradient(const Point& p_W, Point* gradient_W) const {
    return Interpolate(p_W, gradient_W);
  }

 private:
  SignedDistanceField() = default;
  inline double Interpolate(const Point& p_W, Point* gradient_W) const;

  Geometry geometry_;
  double inv_resolution_ = 10.0;
  double max_distance_m_ = 0.0;
  double exactness_margin_m_ = 0.0;
  std::optional<OffsetBand> offset_band_;
  std::vector<float> values_;
  std::shared_ptr<const SignedDistanceField> primary_band_;  // immutable: shared by copies
};

extern template class SignedDistanceField<2>;
extern template class SignedDistanceField<3>;

template <int Dim>
inline double SignedDistanceField<Dim>::Interpolate(const Point& p_W, Point* gradient_W) const {
  const Geometry& g = geometry_;
  double t[Dim];
  double outside_m[Dim];
  bool clamped[Dim];
  int base[Dim];
  for (int a = 0; a < Dim; ++a) {
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
  double distance;
  if constexpr (Dim == 2) {
    const float* c = values_.data() + g.Index(base[0], base[1]);
    const double c00 = c[0], c10 = c[1], c01 = c[sy], c11 = c[sy + 1];
    // Bilinear interpolation: linear in x on both rows, then in y (Numerical Recipes 3rd ed.,
    // eq. 3.6.5).
    const double c0 = c00 + t[0] * (c10 - c00);
    const double c1 = c01 + t[0] * (c11 - c01);
    distance = c0 + t[1] * (c1 - c0);
    if (gradient_W) {
      // Exact partial derivatives of the interpolant, times dt/dp = 1 / res (0 where clamped).
      const double d_dty = c1 - c0;
      const double d_dtx = (1.0 - t[1]) * (c10 - c00) + t[1] * (c11 - c01);
      *gradient_W = Point(clamped[0] ? 0.0 : d_dtx * inv_resolution_,
                          clamped[1] ? 0.0 : d_dty * inv_resolution_);
    }
  } else {
    const std::int64_t sx = 1;
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
    distance = c0 + t[2] * (c1 - c0);
    if (gradient_W) {
      // Exact partial derivatives of the interpolant in t, times dt/dp = 1 / res (zero on an
      // axis where p was clamped).
      const double d_dtz = c1 - c0;
      const double d_dty = (1.0 - t[2]) * (c10 - c00) + t[2] * (c11 - c01);
      const double d_dtx =
          (1.0 - t[2]) * ((1.0 - t[1]) * (c100 - c000) + t[1] * (c110 - c010)) +
          t[2] * ((1.0 - t[1]) * (c101 - c001) + t[1] * (c111 - c011));
      *gradient_W = Point(clamped[0] ? 0.0 : d_dtx * inv_resolution_,
                          clamped[1] ? 0.0 : d_dty * inv_resolution_,
                          clamped[2] ? 0.0 : d_dtz * inv_resolution_);
    }
  }
  double outside_sq = 0.0;
  for (int a = 0; a < Dim; ++a) outside_sq += outside_m[a] * outside_m[a];
  if (outside_sq != 0.0) {  // also taken for NaN, which then propagates
    const double outside_norm = std::sqrt(outside_sq);
    distance += outside_norm;
    if (gradient_W) *gradient_W += Eigen::Map<const Point>(outside_m) / outside_norm;
  }
  return distance;
}

}  // namespace topay
