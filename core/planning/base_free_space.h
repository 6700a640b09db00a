#pragma once

#include <Eigen/Core>

#include "core/map/signed_distance_field2.h"

namespace topay {

/// Where the mobile base may stand and which straight moves it may make, read
/// from the base's 2D signed distance field: a position p is free when field(p)
/// >= required_distance_m (base radius + clearance, 0.40 + 0.1 m by default)
/// and lies inside the field's grid (the world beyond the map is unknown, never
/// free).
///
/// Segment checks are exact with respect to the field: far from obstacles they
/// sphere-trace (the bilinear field changes along a unit direction u by at most
/// L = |u_x| + |u_y| per metre, as neighbouring EDT values differ by at most
/// one cell, so from a point with margin d = field - required the next d / L
/// metres are free); within one cell of the requirement they walk the bilinear
/// patches the segment crosses and take each patch's exact minimum along the
/// segment (a quadratic in arc length). Only in the outer half cell of the
/// grid, where the field is extrapolated, do they fall back to fixed steps of
/// min_step_m, declaring a point blocked below L * min_step_m of margin
/// (conservative by at most that).
class BaseFreeSpace {
 public:
  /// `field` must outlive this object. min_step_m <= 0 selects 1 % of the cell
  /// size.
  BaseFreeSpace(const SignedDistanceField2& field, double required_distance_m,
                double min_step_m = 0.0);

  const SignedDistanceField2& field() const { return *field_; }
  double required_distance_m() const { return required_distance_m_; }

  /// True if p_W is finite, inside the grid and field(p_W) >=
  /// required_distance_m().
  bool IsFree(const Eigen::Vector2d& p_W) const;

  /// True if every point of the segment a_W -> b_W is free (see class comment).
  bool IsSegmentFree(const Eigen::Vector2d& a_W, const Eigen::Vector2d& b_W) const;

 private:
  bool InsideGrid(const Eigen::Vector2d& p_W) const;
  // Minimum of the field over the segment p_W + s u, s in [0, min(max_step_m,
  // patch exit)], inside the bilinear patch holding p_W, compared with the
  // requirement; *step_m gets the length covered.
  bool PatchClear(const Eigen::Vector2d& p_W, const Eigen::Vector2d& u, double max_step_m,
                  double* step_m) const;

  const SignedDistanceField2* field_;
  double required_distance_m_;
  double min_step_m_;
};

}  // namespace topay
