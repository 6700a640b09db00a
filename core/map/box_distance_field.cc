#include "core/map/box_distance_field.h"

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
// matter for it (see BuildBoxDistanceField).
constexpr int kBlockCells = 8;

// One upright box, precomputed for distance queries.
struct BoxShape {
  double cx, cy, cz, c, s, hx, hy, hz;

  explicit BoxShape(const OrientedBox& box)
      : cx(box.center_W_m.x()),
        cy(box.center_W_m.y()),
        cz(box.center_W_m.z()),
        c(std::cos(box.yaw_rad)),
        s(std::sin(box.yaw_rad)),
        hx(0.5 * box.size_m.x()),
        hy(0.5 * box.size_m.y()),
        hz(0.5 * box.size_m.z()) {}

  // Signed distance from p to the box [-h, h] in its frame: |max(q, 0)| outside,
  // max(q_x, q_y, q_z) (<= 0) inside, with q = |p_B| - h.
  double Distance(double x, double y, double z) const {
    const double dx = x - cx, dy = y - cy;
    const double qx = std::abs(c * dx + s * dy) - hx;
    const double qy = std::abs(-s * dx + c * dy) - hy;
    const double qz = std::abs(z - cz) - hz;
    const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0), oz = std::max(qz, 0.0);
    return std::sqrt(ox * ox + oy * oy + oz * oz) + std::min(std::max({qx, qy, qz}), 0.0);
  }

  Eigen::AlignedBox3d Bounds() const {
    const double ex = std::abs(c) * hx + std::abs(s) * hy;
    const double ey = std::abs(s) * hx + std::abs(c) * hy;
    return {Eigen::Vector3d(cx - ex, cy - ey, cz - hz), Eigen::Vector3d(cx + ex, cy + ey, cz + hz)};
  }
};

capped_distance_fill::Shapes<BoxShape> CollectBoxes(std::span<const OrientedBox> boxes) {
  capped_distance_fill::Shapes<BoxShape> out;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string where = "BuildBoxDistanceField: box " + std::to_string(i);
    ValidateBox(boxes[i], where.c_str());
    out.shapes.emplace_back(boxes[i]);
    out.bounds.push_back(out.shapes.back().Bounds());
  }
  return out;
}

}  // namespace

SignedDistanceField3 BuildBoxDistanceField(const GridGeometry3& geometry,
                                           std::span<const OrientedBox> boxes, double cap_m,
                                           BoxDistanceFieldSummary* summary,
                                           std::stop_token stop) {
  geometry.Validate("BuildBoxDistanceField");
  if (!(cap_m > 0.0) || !std::isfinite(cap_m)) {
    throw std::invalid_argument("BuildBoxDistanceField: cap_m must be finite and > 0, got " +
                                std::to_string(cap_m));
  }
  BoxDistanceFieldSummary local;
  const capped_distance_fill::Shapes<BoxShape> all = CollectBoxes(boxes);
  local.num_boxes = static_cast<int>(all.shapes.size());
  std::vector<float> values;
  local.stopped = !capped_distance_fill::FillCappedDistances(
      geometry, all, cap_m, kBlockCells, stop, &values, &local.num_distance_evaluations);
  if (summary) *summary = local;
  return SignedDistanceField3::FromCellValues(geometry, std::move(values), cap_m,
                                              BoxDistanceFieldMargin(geometry.resolution_m));
}

}  // namespace topay
