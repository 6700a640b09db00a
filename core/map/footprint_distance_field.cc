#include "core/map/footprint_distance_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/map/box_cell_overlap.h"
#include "core/map/capped_distance_fill.h"

namespace topay {
namespace {

// Cells per block side: the field is filled block by block, each from the boxes that can
// matter for it (see BuildFootprintDistanceField).
constexpr int kBlockCells = 8;

bool OverlapsBand(const OrientedBox& box, const HeightBand& band) {
  const double half_height = 0.5 * box.size_m.z();
  return box.center_W_m.z() - half_height < band.z_max_m &&
         box.center_W_m.z() + half_height > band.z_min_m;
}

// One box's footprint rectangle, precomputed for distance queries.
struct Footprint {
  double cx, cy, c, s, hx, hy;

  explicit Footprint(const OrientedBox& box)
      : cx(box.center_W_m.x()),
        cy(box.center_W_m.y()),
        c(std::cos(box.yaw_rad)),
        s(std::sin(box.yaw_rad)),
        hx(0.5 * box.size_m.x()),
        hy(0.5 * box.size_m.y()) {}

  // Signed xy distance from (x, y) to the rectangle [-h, h] in the box frame:
  // |max(q, 0)| outside, max(q_x, q_y) (<= 0) inside, with q = |p_B| - h. z is ignored.
  double Distance(double x, double y, double /*z*/) const {
    const double dx = x - cx, dy = y - cy;
    const double qx = std::abs(c * dx + s * dy) - hx;
    const double qy = std::abs(-s * dx + c * dy) - hy;
    const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
    return std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
  }

  // The footprint's axis-aligned bounds in W, of zero height at z = 0 (the fill's one layer).
  Eigen::AlignedBox3d Bounds() const {
    const double ex = std::abs(c) * hx + std::abs(s) * hy;
    const double ey = std::abs(s) * hx + std::abs(c) * hy;
    return {Eigen::Vector3d(cx - ex, cy - ey, 0.0), Eigen::Vector3d(cx + ex, cy + ey, 0.0)};
  }
};

capped_distance_fill::Shapes<Footprint> CollectBandBoxes(std::span<const OrientedBox> boxes,
                                                         const HeightBand& band) {
  capped_distance_fill::Shapes<Footprint> out;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string where = "BuildFootprintDistanceField: box " + std::to_string(i);
    ValidateBox(boxes[i], where.c_str());
    if (!OverlapsBand(boxes[i], band)) continue;
    out.shapes.emplace_back(boxes[i]);
    out.bounds.push_back(out.shapes.back().Bounds());
  }
  return out;
}

// The 2D grid as one layer of cells centred at z = 0 (the footprints' bounds' height).
GridGeometry3 AsOneLayer(const GridGeometry2& g) {
  GridGeometry3 layer;
  layer.origin_W_m = Eigen::Vector3d(g.origin_W_m.x(), g.origin_W_m.y(), -0.5 * g.resolution_m);
  layer.resolution_m = g.resolution_m;
  layer.dims = Eigen::Vector3i(g.dims.x(), g.dims.y(), 1);
  return layer;
}

}  // namespace

SignedDistanceField2 BuildFootprintDistanceField(const GridGeometry2& geometry,
                                                 std::span<const OrientedBox> boxes,
                                                 const HeightBand& band, double cap_m,
                                                 FootprintDistanceFieldSummary* summary,
                                                 std::stop_token stop) {
  geometry.Validate("BuildFootprintDistanceField");
  ValidateBand(band, "BuildFootprintDistanceField");
  if (!(cap_m > 0.0) || !std::isfinite(cap_m)) {
    throw std::invalid_argument("BuildFootprintDistanceField: cap_m must be finite and > 0, got " +
                                std::to_string(cap_m));
  }
  FootprintDistanceFieldSummary local;
  const capped_distance_fill::Shapes<Footprint> in_band = CollectBandBoxes(boxes, band);
  local.num_boxes_in_band = static_cast<int>(in_band.shapes.size());
  std::vector<float> values;
  local.stopped = !capped_distance_fill::FillCappedDistances(
      AsOneLayer(geometry), in_band, cap_m, kBlockCells, stop, &values,
      &local.num_distance_evaluations);
  if (summary) *summary = local;
  return SignedDistanceField2::FromCellValues(geometry, std::move(values), cap_m,
                                              geometry.resolution_m / std::sqrt(2.0));
}

}  // namespace topay
