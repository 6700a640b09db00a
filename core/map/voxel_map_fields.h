#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/map/box_cell_overlap.h"
#include "core/map/cell_box.h"
#include "core/map/column_distance_field.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/occupancy_grid3.h"
#include "core/map/scene_distance_fields.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/map/signed_distance_window.h"
#include "core/map/voxel_state.h"

namespace topay {

/// How the planner's fields count voxels never observed (VoxelState::kUnknown).
enum class UnknownVoxelPolicy {
  /// As free, in both fields (default): the planner plans through unseen space and the next
  /// scans correct it; right for a robot that replans on every scan and for a map seeded with
  /// a prior.
  kFree,
  /// As occupied, in both fields: nothing unseen is entered (a fresh, all-unknown map blocks
  /// everything until scanned).
  kOccupied,
  /// As occupied in the 2D base field's bands only, free for the 3D arm field: the base never
  /// drives into unseen space, the arm may reach through it (it moves slowly over seen floor).
  kOccupiedInBaseBands,
};

/// The map volume, the fields built over it and how unknown voxels count.
struct VoxelMapFieldsOptions {
  /// The planning volume (m): the benchmark room, 20 x 20 x 1.6 m.
  Eigen::AlignedBox3d bounds_W_m{Eigen::Vector3d(-10.0, -10.0, 0.0),
                                 Eigen::Vector3d(10.0, 10.0, 1.6)};
  /// Voxel size (m), also the 3D field's cell size: 0.05 m, the planner's 3D field
  /// (PlannerFieldOptions).
  double resolution_m = 0.05;
  /// The 3D field's values are clamped to [-cap, cap] (m): a voxel change alters the field only
  /// within SignedDistanceReachCells(cap, resolution) voxels (22 at the defaults), which bounds
  /// the incremental update. 1.0 m (default) is above every distance the planner compares
  /// the 3D field with (sphere radius + clearance + the 0.087 m margin); below the cap the
  /// values equal SignedDistanceField3::Build's bitwise. Must be finite and > 0 (the grid's
  /// diagonal gives the uncapped field, and every update then recomputes the whole grid).
  double field_3d_cap_m = 1.0;
  /// Placement of the 3D field's zero level (SignedDistanceFieldOptions).
  SignedDistanceFieldOptions field;
  /// Cell size (m) of the 2D base field, 0.01 m as the planner's (PlannerFieldOptions); it
  /// covers the same xy bounds (GridGeometry2::FromBounds). Must be finite and > 0.
  double base_resolution_m = 0.01;
  /// The 2D field's values are capped at this (m), as the planner's exact base field
  /// (base_exact_cap_m = 1.0). Must be finite and > 0.
  double base_cap_m = 1.0;
  /// Voxel layers overlapping this band's interior make a column an obstacle to the base
  /// (OccupancyGrid2::ProjectBand: a layer counts whole).
  HeightBand base_band{0.0, 0.155};
  /// Optional second band, lowered into the 2D field with the offset as
  /// SceneDistanceFieldsOptions::base_upper_band (SignedDistanceField2::LowerTo: the field keeps
  /// the base band alone as primary_band() and declares the band as offset_band()).
  std::optional<HeightBand> base_upper_band;
  double base_upper_band_offset_m = 0.0;
  UnknownVoxelPolicy unknown = UnknownVoxelPolicy::kFree;
  /// Every voxel's state at construction (a sensed map starts knowing nothing).
  VoxelState initial_state = VoxelState::kUnknown;
  /// Changed voxels are grouped by tiles of this many voxels per axis (xy for the columns)
  /// before their windows are formed and merged (MergeCellBoxes); a tuning knob only, the
  /// values do not depend on it. Must be >= 1.
  int tile_voxels = 8;
};

/// The options matching the planner's box-built fields (e.g. PlannerFieldOptions) over
/// `bounds_W_m`: the same voxel and base cell sizes, bands, offset and zero level; the base cap
/// is scene_options.base_exact_cap_m (1.0 m if 0, the rasterised EDT mode, which this map does
/// not use). This map's 3D field is an EDT field (margin sqrt(3) x the voxel size): if the
/// scene options build an exact one (arm_exact_cap_m > 0, margin half that), the upper band's
/// top, which holds the 3D margin (PlannerFieldOptions), is raised by the difference.
VoxelMapFieldsOptions VoxelMapFieldsOptionsFrom(const SceneDistanceFieldsOptions& scene_options,
                                                const Eigen::AlignedBox3d& bounds_W_m);

/// What one ApplyChanges did: counts and wall-clock timings (steady clock, s).
struct VoxelMapUpdateSummary {
  int num_changes = 0;            ///< Changes given.
  int num_voxels_changed = 0;     ///< Voxels whose state changed.
  int num_voxels_changed_3d = 0;  ///< ... whose occupancy for the 3D field changed.
  int num_columns_changed = 0;    ///< Base (and upper) band columns that changed.
  int num_windows_3d = 0;         ///< Windows of the 3D field recomputed.
  std::int64_t num_cells_3d = 0;  ///< 3D cells recomputed (target windows).
  int num_windows_2d = 0;         ///< Windows of the 2D field(s) recomputed (all bands).
  std::int64_t num_cells_2d = 0;  ///< 2D cells recomputed (all bands).
  double apply_s = 0.0;           ///< Validating and applying the changes to the voxels.
  double field_3d_s = 0.0;
  double field_2d_s = 0.0;
  double total_s = 0.0;
};

/// The planner's fields from a sensed map: owns a 3D occupancy grid of voxel states over the
/// planning volume and keeps, derived from it,
///  - field_3d(): the arm's SignedDistanceField3 of the voxels (exact EDT, as
///    SignedDistanceField3::Build, values clamped at field_3d_cap_m; exactness margin
///    sqrt(3) x the voxel size, as any EDT field of a conservatively rasterised grid);
///  - base_field_2d(): the base's SignedDistanceField2 at base_resolution_m: the exact
///    signed distance to the voxel columns of the base band (BuildColumnDistanceField),
///    lowered by that of the upper band's columns plus the offset (LowerTo: primary_band() is
///    the base band's field, offset_band() declared). Exactness margin: base cell size /
///    sqrt(2) with respect to the occupied columns' squares, so to every obstacle in them (a
///    voxel is a box holding the obstacle parts in it); compared with the exact footprints of
///    the same boxes (BuildSceneDistanceFields), it is never above and at most one column
///    diagonal (sqrt(2) x voxel size) below, where the bands are widened to whole voxel layers
///    (tests/core/map/voxel_map_fields_test.cc).
/// ApplyChanges updates them incrementally: only the windows within the caps of the changed
/// voxels are recomputed, from the voxels within the caps of those windows, and the result is
/// bitwise the full rebuild's (RebuildAll) on the same voxels.
/// Not thread safe; copies of the fields taken before an update keep their values.
class VoxelMapFields {
 public:
  /// Throws std::invalid_argument for invalid options (naming the field).
  explicit VoxelMapFields(const VoxelMapFieldsOptions& options = {});

  const VoxelMapFieldsOptions& options() const { return options_; }
  const GridGeometry3& geometry() const { return occupancy_3d_.geometry(); }
  const GridGeometry2& base_geometry() const { return base_field_2d_.geometry(); }
  VoxelState state(int ix, int iy, int iz) const {
    return static_cast<VoxelState>(states_[geometry().Index(ix, iy, iz)]);
  }
  /// One VoxelState per voxel, linear order (GridGeometry3::Index).
  std::span<const std::uint8_t> states() const { return states_; }
  /// The voxels as the 3D field counts them (after the unknown policy).
  const OccupancyGrid3& occupancy_3d() const { return occupancy_3d_; }
  /// The columns of the base band (and the upper band, if set) as the 2D field counts them.
  const OccupancyGrid2& base_columns() const { return base_columns_; }
  const std::optional<OccupancyGrid2>& upper_columns() const { return upper_columns_; }
  const SignedDistanceField3& field_3d() const { return field_3d_; }
  const SignedDistanceField2& base_field_2d() const { return base_field_2d_; }

  /// Applies the changes in order (a voxel listed twice ends in its last state) and updates
  /// both fields in the windows the changed voxels reach. Validates every change first: a
  /// voxel outside the grid or a state that is not a VoxelState throws std::invalid_argument
  /// naming the change, and leaves the map as it was.
  VoxelMapUpdateSummary ApplyChanges(std::span<const VoxelChange> changes);

  /// Sets every voxel to free or occupied as `occupied` says (its geometry must be this map's,
  /// std::invalid_argument otherwise) and rebuilds both fields (RebuildAll).
  void ResetFrom(const OccupancyGrid3& occupied);

  /// Sets every voxel's state (one VoxelState per voxel, GridGeometry3 order: e.g. a received
  /// snapshot) and rebuilds both fields (RebuildAll): far cheaper than ApplyChanges with every
  /// voxel. Throws std::invalid_argument (map unchanged) for a size other than the grid's or
  /// a byte that is not a VoxelState.
  void ResetStates(std::span<const std::uint8_t> states);

  /// Rebuilds both fields from the voxels over the whole grid: the reference ApplyChanges
  /// equals.
  void RebuildAll();

  /// The change setting the voxel holding p_W to `state`. Throws std::invalid_argument for a
  /// point with a NaN or infinite coordinate or outside the map's volume.
  VoxelChange ChangeAt(const Eigen::Vector3d& p_W, VoxelState state) const;

 private:
  bool Occupied3d(std::uint8_t state) const;
  bool OccupiedInBands(std::uint8_t state) const;
  void ValidateChanges(std::span<const VoxelChange> changes) const;
  // Recomputes a column's flag in `columns` over `layers`; records the column if it changed.
  void UpdateColumn(const CellRange& layers, int ix, int iy, OccupancyGrid2* columns,
                    std::vector<Eigen::Vector3i>* changed) const;
  void RecomputeColumns();
  void Update3d(VoxelMapUpdateSummary* summary);
  void Update2d(VoxelMapUpdateSummary* summary);
  // The field windows the changed columns reach, merged.
  std::vector<CellBox> ColumnWindows(const std::vector<Eigen::Vector3i>& changed) const;
  // Lowered values <- min(primary, upper + offset) in `window`.
  void LowerWindow(const CellBox& window);

  VoxelMapFieldsOptions options_;
  std::vector<std::uint8_t> states_;
  OccupancyGrid3 occupancy_3d_;
  OccupancyGrid2 base_columns_;
  std::optional<OccupancyGrid2> upper_columns_;
  CellRange base_layers_, upper_layers_;
  SignedDistanceField3 field_3d_;
  SignedDistanceField2 base_field_2d_;
  std::vector<float> upper_values_;  // the upper band's field (without the offset)
  // Scratch, reused across updates.
  std::vector<Eigen::Vector3i> changed_3d_, changed_base_, changed_upper_;
  SignedDistanceWindowWorkspace window_workspace_;
  ColumnDistanceWorkspace column_workspace_;
};

}  // namespace topay
