#include "core/map/footprint_distance_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/map/box_cell_overlap.h"

namespace topay {
namespace {

bool OverlapsBand(const OrientedBox& box, const HeightBand& band) {
  const double half_height = 0.5 * box.size_m.z();
  return box.center_W_m.z() - half_height < band.z_max_m &&
         box.center_W_m.z() + half_height > band.z_min_m;
}

// Lowers the cells within cap_m of the box's footprint to their exact signed distance to it.
// Returns the number of cells evaluated.
std::int64_t LowerToFootprint(const GridGeometry2& g, const OrientedBox& box, double cap_m,
                              std::vector<float>* values) {
  const double c = std::cos(box.yaw_rad), s = std::sin(box.yaw_rad);
  const double hx = 0.5 * box.size_m.x(), hy = 0.5 * box.size_m.y();
  // Half extents of the footprint's axis-aligned bounds, grown by the cap.
  const double ex = std::abs(c) * hx + std::abs(s) * hy + cap_m;
  const double ey = std::abs(s) * hx + std::abs(c) * hy + cap_m;
  const double cx = box.center_W_m.x(), cy = box.center_W_m.y();
  const double inv_res = 1.0 / g.resolution_m;
  // Cells whose centre o + (i + 1/2) res lies in [cx - ex, cx + ex].
  const int ix0 = std::max(0, static_cast<int>(std::ceil((cx - ex - g.origin_W_m.x()) * inv_res - 0.5)));
  const int ix1 = std::min(g.dims.x() - 1,
                           static_cast<int>(std::floor((cx + ex - g.origin_W_m.x()) * inv_res - 0.5)));
  const int iy0 = std::max(0, static_cast<int>(std::ceil((cy - ey - g.origin_W_m.y()) * inv_res - 0.5)));
  const int iy1 = std::min(g.dims.y() - 1,
                           static_cast<int>(std::floor((cy + ey - g.origin_W_m.y()) * inv_res - 0.5)));
  if (ix0 > ix1 || iy0 > iy1) return 0;
  float* data = values->data();
  for (int iy = iy0; iy <= iy1; ++iy) {
    const double dy = g.origin_W_m.y() + (iy + 0.5) * g.resolution_m - cy;
    float* row = data + g.Index(0, iy);
    for (int ix = ix0; ix <= ix1; ++ix) {
      const double dx = g.origin_W_m.x() + (ix + 0.5) * g.resolution_m - cx;
      // The centre in the box frame, then the signed distance to the rectangle [-h, h]:
      // |max(q, 0)| outside, max(q_x, q_y) (<= 0) inside, with q = |p_B| - h.
      const double qx = std::abs(c * dx + s * dy) - hx;
      const double qy = std::abs(-s * dx + c * dy) - hy;
      const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
      const double distance = std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
      row[ix] = std::min(row[ix], static_cast<float>(distance));
    }
  }
  return std::int64_t{ix1 - ix0 + 1} * (iy1 - iy0 + 1);
}

}  // namespace

SignedDistanceField2 BuildFootprintDistanceField(const GridGeometry2& geometry,
                                                 std::span<const OrientedBox> boxes,
                                                 const HeightBand& band, double cap_m,
                                                 FootprintDistanceFieldSummary* summary) {
  geometry.Validate("BuildFootprintDistanceField");
  ValidateBand(band, "BuildFootprintDistanceField");
  if (!(cap_m > 0.0) || !std::isfinite(cap_m)) {
    throw std::invalid_argument("BuildFootprintDistanceField: cap_m must be finite and > 0, got " +
                                std::to_string(cap_m));
  }
  FootprintDistanceFieldSummary local;
  std::vector<float> values(geometry.NumCells(), static_cast<float>(cap_m));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string where = "BuildFootprintDistanceField: box " + std::to_string(i);
    ValidateBox(boxes[i], where.c_str());
    if (!OverlapsBand(boxes[i], band)) continue;
    ++local.num_boxes_in_band;
    local.num_distance_evaluations += LowerToFootprint(geometry, boxes[i], cap_m, &values);
  }
  if (summary) *summary = local;
  return SignedDistanceField2::FromCellValues(geometry, std::move(values), cap_m,
                                              geometry.resolution_m / std::sqrt(2.0));
}

}  // namespace topay
