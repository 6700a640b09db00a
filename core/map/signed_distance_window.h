#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/map/cell_box.h"
#include "core/map/distance_transform.h"
#include "core/map/signed_distance_values.h"

namespace topay {

/// Scratch of RecomputeSignedDistanceWindow, reused across calls (no allocation once warmed
/// up to the largest window). Not thread safe: one per thread.
struct SignedDistanceWindowWorkspace {
  EdtWorkspace edt;
  std::vector<std::uint8_t> cells;         ///< The source window's cells.
  std::vector<float> values;               ///< The source window's squared distances.
  std::vector<std::uint8_t> target_cells;  ///< The target's cells, contiguous.
  std::vector<float> target_values;        ///< The target's squared, then signed, distances.
};

/// How many cells away an occupancy change can alter a signed field capped at cap_m (m) with
/// cells of resolution_m (m): a value below the cap is at most (sqrt(D) + 1/2 + inset) cells
/// (inside, inset <= 1/2) from its nearest site, so sqrt(D) < cap / res + 1; one cell more for
/// round-off. Both the cells a change reaches and the sites a recomputed cell needs lie within
/// this many cells on every axis. Throws std::invalid_argument unless cap_m and resolution_m are
/// finite and positive.
int SignedDistanceReachCells(double cap_m, double resolution_m);

/// Recomputes the cells in `target` of signed distance values capped at cap_m, as
/// BuildSignedDistanceValues(cells, dims, num_axes, resolution_m, cap_m, options) computes them
/// for the whole grid, bitwise equal, from the cells within SignedDistanceReachCells of the
/// target only:
///  1. copy the source window (the target grown by the reach, clipped to the grid) into
///     scratch;
///  2. the exact squared EDT of both phases over that window alone, its y and z passes only on
///     the lines through the target (SquaredDistanceToOtherPhaseAt): every site within the
///     reach of a target cell lies in the window, and a site beyond it could only give a value
///     at the cap, which the window then gives as well (its distance is no smaller);
///  3. the same conversion to signed, capped values as the full build, on the target's cells
///     gathered into a block, with the virtual free cells beyond the grid placed by the grid
///     (SignedValuesFromSquaredDistancesInWindow);
///  4. copy the target's values into `values` (the whole grid's, x fastest).
/// A target that is the whole grid runs in place on `values` (the full build). Cost: the
/// source window's cells (EDT) plus the target's (copies). Throws std::invalid_argument for a
/// target outside the grid or bad options.
void RecomputeSignedDistanceWindow(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                   int num_axes, double resolution_m, double cap_m,
                                   const SignedDistanceFieldOptions& options, const CellBox& target,
                                   SignedDistanceWindowWorkspace* workspace, float* values);

}  // namespace topay
