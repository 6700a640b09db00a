#pragma once

#include <span>
#include <stop_token>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"

namespace topay {

/// What BuildFootprintDistanceField did.
struct FootprintDistanceFieldSummary {
  int num_boxes_in_band = 0;
  std::int64_t num_distance_evaluations = 0;  ///< Point-box distances computed exactly.
  bool stopped = false;  ///< `stop` ended the build early: the field is incomplete.
};

/// The base's 2D field from the exact footprints of the boxes in `band` (those whose z extent
/// overlaps the band's interior, as OccupancyGrid2::AddBoxInBand): each cell holds
///   min(cap_m, min over those boxes of the exact signed xy distance from the cell's centre to
///       the box's footprint rectangle)
/// (negative inside a footprint). The minimum of 1-Lipschitz functions and a constant is
/// 1-Lipschitz, so the bilinear interpolant is within cell size / sqrt(2) of the capped exact
/// distance: the field's exactness_margin_m(), half that of a field rasterised and built by the
/// EDT (sqrt(2) x the cell size), which lets the base through gaps 2.8 cm narrower at 2 cm
/// cells. Values are exact only below cap_m: choose it above every distance the planner
/// compares with (base radius + clearance + margin). No box in the band: every cell is cap_m.
///
/// Cost: the boxes go into a uniform bucket grid (BoxBucketGrid, linear in the boxes); the
/// cells are filled in blocks of 8 x 8, each from the boxes within
///   bound = min(cap_m, field at the block's centre + the block's half diagonal)
/// of the block (the field is 1-Lipschitz, so no other box can lower a cell of it): per
/// cell, the boxes near it, not every box within cap_m. The values are the same as a loop
/// over every box and cell (tests/core/map/footprint_distance_field_test.cc checks it).
/// `stop`, polled once per row of blocks, ends the build early: summary->stopped is set and
/// the cells not yet filled read -cap_m (occupied), so the field is conservative but not the
/// one asked for; do not plan on it.
/// Throws std::invalid_argument for an invalid geometry or band, cap_m <= 0, or a box with
/// NaN/inf values or negative sizes (naming its index).
SignedDistanceField2 BuildFootprintDistanceField(const GridGeometry2& geometry,
                                                 std::span<const OrientedBox> boxes,
                                                 const HeightBand& band, double cap_m,
                                                 FootprintDistanceFieldSummary* summary = nullptr,
                                                 std::stop_token stop = {});

}  // namespace topay
