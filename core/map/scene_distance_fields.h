#pragma once

#include <cstdint>
#include <optional>
#include <stop_token>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"

namespace topay {

/// How BuildSceneDistanceFields maps a scene.
struct SceneDistanceFieldsOptions {
  /// Cell size (m) of the 3D field (and of the 2D field unless base_resolution_m is set): the
  /// benchmark maps use 0.1 m.
  double resolution_m = 0.1;
  /// Cell size (m) of the 2D base field; 0 (default): resolution_m, the grid then being the 3D
  /// grid's xy footprint. A finer base field lets the base pass closer to obstacles, since its
  /// exactness margin (sqrt(2) x the 2D cell size, WholeBodyValidityOptions) shrinks with it;
  /// the grid then covers the same xy bounds (GridGeometry2::FromBounds). Must be finite and
  /// >= 0.
  double base_resolution_m = 0.0;
  /// Obstacles whose z extent overlaps this band's interior block the base (2D field); the
  /// default is the floor up to the chassis top, so the base may pass under table tops and
  /// floating boxes, which the arm must clear in the 3D field.
  HeightBand base_band{0.0, 0.155};
  /// Optional second band for the 2D field, for a robot whose parts above base_band reach
  /// less far from its axis than the base: obstacles in this band count with
  /// base_upper_band_offset_m added to their distance, the 2D field being
  /// min(d_base_band(p), d_upper_band(p) + offset) cell by cell (SignedDistanceField2::LowerTo).
  /// E.g. a base of radius R whose rigid parts in the upper band lie within R - offset of its
  /// axis. Unset (default): base_band alone. Must be a valid band; offset finite and >= 0.
  std::optional<HeightBand> base_upper_band;
  double base_upper_band_offset_m = 0.0;
  /// 0 (default): the 2D field is the EDT of the band(s) rasterised on its grid (exactness
  /// margin sqrt(2) x the cell size). > 0: exact distances to the boxes' footprints at the
  /// cell centres, capped at this value (m), for each band (BuildFootprintDistanceField;
  /// margin cell size / sqrt(2)). Must be finite and >= 0.
  double base_exact_cap_m = 0.0;
  /// 0 (default): the 3D field is the EDT of the boxes rasterised on its grid (exactness
  /// margin sqrt(3) x the cell size). > 0: exact distances to the boxes at the cell centres,
  /// capped at this value (m) (BuildBoxDistanceField; margin sqrt(3) / 2 x the cell size).
  /// Must be finite and >= 0.
  double arm_exact_cap_m = 0.0;
  /// Placement of the zero level, for both fields.
  SignedDistanceFieldOptions field;
  /// Volume the 3D field covers (and, in xy, the 2D one); unset: the scene's bounds_W_m.
  std::optional<Eigen::AlignedBox3d> bounds_W_m;
};

/// What BuildSceneDistanceFields did: sizes and wall-clock timings (steady clock, s).
struct SceneDistanceFieldsSummary {
  std::int64_t num_cells_3d = 0;
  std::int64_t num_occupied_3d = 0;
  std::int64_t num_cells_2d = 0;
  std::int64_t num_occupied_2d = 0;
  int num_boxes_in_base_band = 0;  ///< Boxes that count for the 2D base field (base_band).
  int num_boxes_in_upper_band = 0;  ///< Boxes in base_upper_band (if set).
  double rasterize_3d_s = 0.0;     ///< OccupancyGrid3::AddBox over all boxes.
  double build_3d_s = 0.0;         ///< SignedDistanceField3::Build.
  double rasterize_2d_s = 0.0;     ///< OccupancyGrid2::AddBoxInBand over all boxes.
  double build_2d_s = 0.0;         ///< SignedDistanceField2::Build.
  double total_s = 0.0;
  /// The caller's stop ended the build early: the fields are incomplete, do not plan on them.
  bool stopped = false;
};

/// The arm's 3D field and the base's 2D field of one scene.
struct SceneDistanceFields {
  SignedDistanceField3 field_3d;
  SignedDistanceField2 base_field_2d;
  SceneDistanceFieldsSummary summary;
};

/// The exactness margin (m) of the 3D field BuildSceneDistanceFields builds with these
/// options: BoxDistanceFieldMargin(resolution_m) = sqrt(3) / 2 x the cell size if
/// arm_exact_cap_m > 0, else the EDT field's sqrt(3) x the cell size.
double ArmFieldMargin(const SceneDistanceFieldsOptions& options);

/// Rasterises every box of the scene exactly (conservative: thin parts are kept) into a 3D grid
/// over the bounds and, if it overlaps the base band, into a 2D grid, then builds both signed
/// distance fields. Throws std::invalid_argument for bad options or a box with NaN/inf values
/// or negative sizes (the message names the box index).
///
/// Cost: linear in the cells the boxes cover (rasterisation visits each box's own cells) plus
/// the grids' sizes (the EDTs); the exact base field (base_exact_cap_m > 0) looks at the
/// boxes near each block of cells (BuildFootprintDistanceField), not at every box within the
/// cap. `stop` is polled every 1024 boxes while rasterising and once per row of 8-cell blocks
/// of the exact base field (an EDT pass runs to its end: linear in the grid); when it ends the
/// build early, summary.stopped is set.
SceneDistanceFields BuildSceneDistanceFields(const Scene& scene,
                                             const SceneDistanceFieldsOptions& options = {},
                                             std::stop_token stop = {});

}  // namespace topay
