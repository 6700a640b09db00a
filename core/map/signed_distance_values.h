#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/map/distance_transform.h"

namespace topay {

/// How the cell values of SignedDistanceField2/3 are placed relative to the occupied cells.
struct SignedDistanceFieldOptions {
  /// How far (in cells, from 0 to 0.5) inside the occupied region's boundary the zero level
  /// lies. Cell values are, with D the exact squared centre-to-centre distance in cells,
  ///   free cell:      (sqrt(D_out) - 1/2 + inset) res,
  ///   occupied cell: -(sqrt(D_in) - 1/2 - inset) res.
  /// 0.5 (default): zero on the centres of the boundary occupied cells. A conservatively
  ///   rasterised surface (or a point-cloud hit) lies somewhere inside its boundary cell, so
  ///   this is the unbiased choice: error within one cell of the exact signed distance (the
  ///   benchmark figure), but a one-cell-thick obstacle reads 0, not negative, at its centre.
  /// 0.0: zero on the faces between occupied and free cells (the classic half-cell
  ///   correction): value < 0 exactly on occupied cells, but for rasterised boxes the field
  ///   is biased low by half a cell on average and up to about 1.5 cells.
  double zero_level_inset_cells = 0.5;
};

/// Throws std::invalid_argument unless zero_level_inset_cells is in [0, 0.5].
void ValidateSignedDistanceFieldOptions(const SignedDistanceFieldOptions& options);

/// Turns the squared distances to the other phase (SquaredDistanceToOtherPhase, cell units) of
/// a binary grid of `dims` cells (x fastest; `num_axes` = 2 for a planar grid, whose dims.z()
/// is 1) into signed distances (m), in place over `squared_to_signed`, by the formulas of SignedDistanceFieldOptions. The world beyond
/// the grid counts as free for the inside distances (virtual free cells at index -1 and n on
/// each axis), so a wall standing on the grid's edge is shallow near both its faces. Infinite
/// squared distances (no site at all) become +-max_distance_m.
void SignedValuesFromSquaredDistances(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                      int num_axes, double resolution_m,
                                      double max_distance_m,
                                      const SignedDistanceFieldOptions& options,
                                      float* squared_to_signed);

/// SignedValuesFromSquaredDistances over a window of a larger grid (the same code: the whole
/// grid is the window at the origin): `cells` and `squared_to_signed` hold the window's
/// window_dims cells (x fastest), whose first cell is window_origin in the grid of grid_dims;
/// the virtual free cells beyond the grid are placed by the grid, not the window. Used by the
/// incremental fields (core/map/voxel_map_fields.h), whose values must equal a full build's.
void SignedValuesFromSquaredDistancesInWindow(const std::uint8_t* cells,
                                              const Eigen::Vector3i& window_dims,
                                              const Eigen::Vector3i& window_origin,
                                              const Eigen::Vector3i& grid_dims, int num_axes,
                                              double resolution_m, double max_distance_m,
                                              const SignedDistanceFieldOptions& options,
                                              float* squared_to_signed);

/// The whole signed-field build shared by SignedDistanceField2 and SignedDistanceField3:
/// validates `options`, sizes `values` to the grid, runs the distance transform (scratch from
/// `workspace`, or a local one if null) and converts to signed distances (m).
void BuildSignedDistanceValues(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                               int num_axes, double resolution_m, double max_distance_m,
                               const SignedDistanceFieldOptions& options,
                               EdtWorkspace* workspace, std::vector<float>* values);

}  // namespace topay
