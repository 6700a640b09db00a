#pragma once

#include <span>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"

namespace topay {

/// What BuildFootprintDistanceField did.
struct FootprintDistanceFieldSummary {
  int num_boxes_in_band = 0;
  std::int64_t num_distance_evaluations = 0;  ///< Cell-box pairs computed exactly.
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
/// compares with (base radius + clearance + margin). Cost: one evaluation per box and cell
/// within cap_m of its footprint's bounding box. No box in the band: every cell is cap_m.
/// Throws std::invalid_argument for an invalid geometry or band, cap_m <= 0, or a box with
/// NaN/inf values or negative sizes (naming its index).
SignedDistanceField2 BuildFootprintDistanceField(const GridGeometry2& geometry,
                                                 std::span<const OrientedBox> boxes,
                                                 const HeightBand& band, double cap_m,
                                                 FootprintDistanceFieldSummary* summary = nullptr);

}  // namespace topay
