#include "core/map/footprint_distance_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/box_bucket_grid.h"
#include "core/map/box_cell_overlap.h"

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
  // |max(q, 0)| outside, max(q_x, q_y) (<= 0) inside, with q = |p_B| - h.
  double Distance(double x, double y) const {
    const double dx = x - cx, dy = y - cy;
    const double qx = std::abs(c * dx + s * dy) - hx;
    const double qy = std::abs(-s * dx + c * dy) - hy;
    const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
    return std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
  }

  // The footprint's axis-aligned bounds in W (z unused, 0).
  Eigen::AlignedBox3d Bounds() const {
    const double ex = std::abs(c) * hx + std::abs(s) * hy;
    const double ey = std::abs(s) * hx + std::abs(c) * hy;
    return {Eigen::Vector3d(cx - ex, cy - ey, 0.0), Eigen::Vector3d(cx + ex, cy + ey, 0.0)};
  }
};

// Squared xy distance from a rectangle [lo, hi] to a box's AABB (0 if they overlap).
double SquaredGap(const Eigen::AlignedBox3d& box, const Eigen::Vector2d& lo,
                  const Eigen::Vector2d& hi) {
  const double gx = std::max({box.min().x() - hi.x(), lo.x() - box.max().x(), 0.0});
  const double gy = std::max({box.min().y() - hi.y(), lo.y() - box.max().y(), 0.0});
  return gx * gx + gy * gy;
}

// The footprints of the boxes in the band, their bounds, and a bucket grid over them.
struct BandBoxes {
  std::vector<Footprint> footprints;
  std::vector<Eigen::AlignedBox3d> bounds;
};

BandBoxes CollectBandBoxes(std::span<const OrientedBox> boxes, const HeightBand& band) {
  BandBoxes out;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string where = "BuildFootprintDistanceField: box " + std::to_string(i);
    ValidateBox(boxes[i], where.c_str());
    if (!OverlapsBand(boxes[i], band)) continue;
    out.footprints.emplace_back(boxes[i]);
    out.bounds.push_back(out.footprints.back().Bounds());
  }
  return out;
}

// The field of the point p: min(cap, min over boxes of the footprint distance), by the
// bucket grid (boxes whose bounds are farther than the best so far are skipped).
double FieldAt(const BandBoxes& band, const BoxBucketGrid& grid, const Eigen::Vector2d& p,
               double cap_m, std::int64_t* evaluations) {
  double best = cap_m;
  grid.VisitNear(p, p, [&best] { return best; }, [&](int i) {
    const double gap_squared = SquaredGap(band.bounds[i], p, p);
    if (gap_squared > 0.0 && (best <= 0.0 || gap_squared >= best * best)) return;
    ++*evaluations;
    best = std::min(best, band.footprints[i].Distance(p.x(), p.y()));
  });
  return best;
}

// Fills the cells [ix0, ix1) x [iy0, iy1) of one block.
void FillBlock(const GridGeometry2& g, const BandBoxes& band, const BoxBucketGrid& grid,
               double cap_m, int ix0, int ix1, int iy0, int iy1, std::vector<int>* candidates,
               std::vector<float>* values, std::int64_t* evaluations) {
  const Eigen::Vector2d lo = g.CellCenter(ix0, iy0), hi = g.CellCenter(ix1 - 1, iy1 - 1);
  const Eigen::Vector2d center = 0.5 * (lo + hi);
  // The field is 1-Lipschitz: every cell of the block is at most `bound` (a hair added for
  // round-off), so a box whose bounds are farther than that from the block cannot lower it.
  const double bound = std::min(
      cap_m, FieldAt(band, grid, center, cap_m, evaluations) + 0.5 * (hi - lo).norm() + 1e-9);
  candidates->clear();
  grid.VisitNear(lo, hi, [bound] { return bound; }, [&](int i) {
    if (SquaredGap(band.bounds[i], lo, hi) <= bound * bound) candidates->push_back(i);
  });
  const float cap = static_cast<float>(cap_m);
  float* data = values->data();
  for (int iy = iy0; iy < iy1; ++iy) {
    const double y = g.origin_W_m.y() + (iy + 0.5) * g.resolution_m;
    float* row = data + g.Index(0, iy);
    for (int ix = ix0; ix < ix1; ++ix) {
      const double x = g.origin_W_m.x() + (ix + 0.5) * g.resolution_m;
      float value = cap;
      for (int i : *candidates) {
        value = std::min(value, static_cast<float>(band.footprints[i].Distance(x, y)));
      }
      row[ix] = value;
    }
  }
  *evaluations += static_cast<std::int64_t>(candidates->size()) * (ix1 - ix0) * (iy1 - iy0);
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
  const BandBoxes in_band = CollectBandBoxes(boxes, band);
  local.num_boxes_in_band = static_cast<int>(in_band.footprints.size());
  // Unfilled cells read -cap_m (occupied): a field cut short by `stop` is conservative.
  std::vector<float> values(geometry.NumCells(), static_cast<float>(-cap_m));
  if (in_band.footprints.empty()) {
    std::fill(values.begin(), values.end(), static_cast<float>(cap_m));
  } else {
    const BoxBucketGrid grid(in_band.bounds);
    std::vector<int> candidates;
    for (int iy = 0; iy < geometry.dims.y() && !local.stopped; iy += kBlockCells) {
      if (stop.stop_requested()) {
        local.stopped = true;
        break;
      }
      const int iy1 = std::min(iy + kBlockCells, geometry.dims.y());
      for (int ix = 0; ix < geometry.dims.x(); ix += kBlockCells) {
        FillBlock(geometry, in_band, grid, cap_m, ix, std::min(ix + kBlockCells, geometry.dims.x()),
                  iy, iy1, &candidates, &values, &local.num_distance_evaluations);
      }
    }
  }
  if (summary) *summary = local;
  return SignedDistanceField2::FromCellValues(geometry, std::move(values), cap_m,
                                              geometry.resolution_m / std::sqrt(2.0));
}

}  // namespace topay
