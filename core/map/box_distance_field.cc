#include "core/map/box_distance_field.h"

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

// Squared distance from the block [lo, hi] to a box's AABB (0 if they overlap).
double SquaredGap(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& lo,
                  const Eigen::Vector3d& hi) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double gap = std::max({box.min()(a) - hi(a), lo(a) - box.max()(a), 0.0});
    sum += gap * gap;
  }
  return sum;
}

struct Boxes {
  std::vector<BoxShape> shapes;
  std::vector<Eigen::AlignedBox3d> bounds;
};

Boxes CollectBoxes(std::span<const OrientedBox> boxes) {
  Boxes out;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string where = "BuildBoxDistanceField: box " + std::to_string(i);
    ValidateBox(boxes[i], where.c_str());
    out.shapes.emplace_back(boxes[i]);
    out.bounds.push_back(out.shapes.back().Bounds());
  }
  return out;
}

// min(cap, min over boxes of the distance from p), by the bucket grid.
double FieldAt(const Boxes& boxes, const BoxBucketGrid& grid, const Eigen::Vector3d& p,
               double cap_m, std::int64_t* evaluations) {
  double best = cap_m;
  grid.VisitNear(p.head<2>(), p.head<2>(), [&best] { return best; }, [&](int i) {
    const double gap_squared = SquaredGap(boxes.bounds[i], p, p);
    if (gap_squared > 0.0 && (best <= 0.0 || gap_squared >= best * best)) return;
    ++*evaluations;
    best = std::min(best, boxes.shapes[i].Distance(p.x(), p.y(), p.z()));
  });
  return best;
}

// The cells [i0, i1) of one block (per axis).
struct Block {
  Eigen::Vector3i i0, i1;
};

void FillBlock(const GridGeometry3& g, const Boxes& boxes, const BoxBucketGrid& grid,
               double cap_m, const Block& block, std::vector<int>* candidates,
               std::vector<float>* values, std::int64_t* evaluations) {
  const Eigen::Vector3d lo = g.CellCenter(block.i0.x(), block.i0.y(), block.i0.z());
  const Eigen::Vector3d hi = g.CellCenter(block.i1.x() - 1, block.i1.y() - 1, block.i1.z() - 1);
  // The field is 1-Lipschitz: every cell of the block is at most `bound` (a hair added for
  // round-off), so a box whose bounds are farther than that from the block cannot lower it.
  const double bound = std::min(
      cap_m, FieldAt(boxes, grid, 0.5 * (lo + hi), cap_m, evaluations) + 0.5 * (hi - lo).norm() +
                 1e-9);
  candidates->clear();
  grid.VisitNear(lo.head<2>(), hi.head<2>(), [bound] { return bound; }, [&](int i) {
    if (SquaredGap(boxes.bounds[i], lo, hi) <= bound * bound) candidates->push_back(i);
  });
  const float cap = static_cast<float>(cap_m);
  float* data = values->data();
  for (int iz = block.i0.z(); iz < block.i1.z(); ++iz) {
    const double z = g.origin_W_m.z() + (iz + 0.5) * g.resolution_m;
    for (int iy = block.i0.y(); iy < block.i1.y(); ++iy) {
      const double y = g.origin_W_m.y() + (iy + 0.5) * g.resolution_m;
      float* row = data + g.Index(0, iy, iz);
      for (int ix = block.i0.x(); ix < block.i1.x(); ++ix) {
        const double x = g.origin_W_m.x() + (ix + 0.5) * g.resolution_m;
        float value = cap;
        for (int i : *candidates) {
          value = std::min(value, static_cast<float>(boxes.shapes[i].Distance(x, y, z)));
        }
        row[ix] = value;
      }
    }
  }
  const Eigen::Vector3i n = block.i1 - block.i0;
  *evaluations += static_cast<std::int64_t>(candidates->size()) * n.prod();
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
  const Boxes all = CollectBoxes(boxes);
  local.num_boxes = static_cast<int>(all.shapes.size());
  // Unfilled cells read -cap_m (occupied): a field cut short by `stop` is conservative.
  std::vector<float> values(geometry.NumCells(), static_cast<float>(-cap_m));
  if (all.shapes.empty()) {
    std::fill(values.begin(), values.end(), static_cast<float>(cap_m));
  } else {
    const BoxBucketGrid grid(all.bounds);
    std::vector<int> candidates;
    const Eigen::Vector3i& dims = geometry.dims;
    for (int iz = 0; iz < dims.z() && !local.stopped; iz += kBlockCells) {
      for (int iy = 0; iy < dims.y(); iy += kBlockCells) {
        if (stop.stop_requested()) {
          local.stopped = true;
          break;
        }
        for (int ix = 0; ix < dims.x(); ix += kBlockCells) {
          const Eigen::Vector3i i0(ix, iy, iz);
          const Block block{i0, (i0 + Eigen::Vector3i::Constant(kBlockCells)).cwiseMin(dims)};
          FillBlock(geometry, all, grid, cap_m, block, &candidates, &values,
                    &local.num_distance_evaluations);
        }
      }
    }
  }
  if (summary) *summary = local;
  return SignedDistanceField3::FromCellValues(geometry, std::move(values), cap_m,
                                              0.5 * std::sqrt(3.0) * geometry.resolution_m);
}

}  // namespace topay
