#pragma once

#include <vector>

#include "core/map/cell_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"

namespace topay {

/// Scratch of FillColumnDistanceWindow, reused across calls (no allocation once warmed up).
struct ColumnDistanceWorkspace {
  // Per source column of one row: the nearest occupied / free column at or before it and at or
  // after it (-1: none).
  std::vector<int> prev_occupied, next_occupied, prev_free, next_free;
  // Per target field column: x of its cell centres and the column of `columns` holding it.
  std::vector<double> x_m;
  std::vector<int> column_of_x;
  // Per source row and target field column: squared x distance to the nearest occupied / free
  // column square of that row (+inf: none within the source window).
  std::vector<double> squared_x_to_occupied, squared_x_to_free;
  // Per target field column of the current row: the squared distance so far.
  std::vector<double> best_to_occupied, best_to_free;
  std::vector<std::uint8_t> occupied_in_row;  ///< Per target field column: its point's phase.
};

/// The base's 2D field from voxel columns: the capped exact signed distance, at the centres of
/// a field grid (typically finer, e.g. 0.01 m under 0.05 m voxels), to the union of the
/// occupied cells' squares of `columns` (each a voxel column in a height band; the world
/// beyond `columns` is free):
///   free point p:     min(cap_m, distance from p to the union of occupied squares),
///   occupied point p: -min(cap_m, distance from p to the union of free squares and the
///                     outside of the grid),
/// where p is occupied if the cell of `columns` holding it is. This is the signed distance to
/// the union's boundary, 1-Lipschitz, so the bilinear interpolant is within field cell size /
/// sqrt(2) of it (the field's exactness margin, as BuildFootprintDistanceField's); and since a
/// voxel rasterised conservatively holds every part of the obstacles in it, the margin holds
/// for those obstacles too. An obstacle's true footprint lies inside its squares, so the field
/// reads at most one column diagonal (sqrt(2) x the voxel size) below the exact footprint
/// field of the same obstacles (tests/core/map/column_distance_field_test.cc).
///
/// FillColumnDistanceWindow fills the field cells in `target` (field cell indices; z unused)
/// of `values` (the whole field grid's, x fastest) from the columns within cap_m + one column
/// of the target only, with the same values as a fill of the whole grid, bitwise (every cell's
/// value is one formula of global coordinates; a column beyond the source window is farther
/// than the cap). The squared distance to a square separates into per-axis terms,
///   d(p, square(cx, cy))^2 = ex(p.x, cx)^2 + ey(p.y, cy)^2,
/// with e the distance from a coordinate to the square's interval (0 inside), so:
///  1. per source row cy and target field column: the squared x distance to the nearest
///     occupied (and free) square of the row, from the nearest such columns before and after
///     (two sweeps per row);
///  2. per target cell: the minimum over the rows within cap_m + one column of ey^2 + that
///     term (ey is the same along a target row, so these loops run over contiguous memory;
///     the distance to free squares only in rows with occupied points), then the point's
///     phase picks one.
/// Cost: (source rows x target columns) + (target cells x rows within the cap). Throws
/// std::invalid_argument for a target outside the field grid or cap_m not finite and > 0.
void FillColumnDistanceWindow(const OccupancyGrid2& columns, const GridGeometry2& field_geometry,
                              const CellBox& target, double cap_m,
                              ColumnDistanceWorkspace* workspace, float* values);

/// The whole field as a SignedDistanceField2 (FillColumnDistanceWindow over every cell;
/// max_distance_m = cap_m, exactness margin field cell size / sqrt(2)).
SignedDistanceField2 BuildColumnDistanceField(const OccupancyGrid2& columns,
                                              const GridGeometry2& field_geometry, double cap_m,
                                              ColumnDistanceWorkspace* workspace = nullptr);

/// The field cells (of field_geometry) whose value a change of the column square `column`
/// (cell of column_geometry, z unused) can alter: those whose centre lies within cap_m, plus
/// one field cell, of the square on each axis. Clipped to the field grid (may be empty).
CellBox FieldCellsNearColumns(const GridGeometry2& column_geometry, const CellBox& columns,
                              const GridGeometry2& field_geometry, double cap_m);

}  // namespace topay
