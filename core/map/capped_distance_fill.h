#pragma once

// The block-wise fill shared by the exact-distance fields (BuildFootprintDistanceField in 2D,
// BuildBoxDistanceField in 3D): each cell of a grid gets min(cap, min over the shapes of the
// exact signed distance from its centre). Internal to core/map.

#include <algorithm>
#include <cstdint>
#include <stop_token>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/box_bucket_grid.h"
#include "core/map/grid_geometry.h"

namespace topay::capped_distance_fill {

/// Shapes with Distance(x, y, z) (signed, 1-Lipschitz) and their AABBs in W. A 2D field's
/// shapes ignore z and have bounds of zero height at z = 0 (its grid: one layer centred there).
template <typename Shape>
struct Shapes {
  std::vector<Shape> shapes;
  std::vector<Eigen::AlignedBox3d> bounds;
};

/// Squared distance from the block [lo, hi] to an AABB (0 if they overlap).
inline double SquaredGap(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& lo,
                         const Eigen::Vector3d& hi) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double gap = std::max({box.min()(a) - hi(a), lo(a) - box.max()(a), 0.0});
    sum += gap * gap;
  }
  return sum;
}

/// min(cap, min over the shapes of the distance from p), by the bucket grid (shapes whose
/// bounds are farther than the best so far are skipped).
template <typename Shape>
double FieldAt(const Shapes<Shape>& set, const BoxBucketGrid& grid, const Eigen::Vector3d& p,
               double cap_m, std::int64_t* evaluations) {
  double best = cap_m;
  grid.VisitNear(p.head<2>(), p.head<2>(), [&best] { return best; }, [&](int i) {
    const double gap_squared = SquaredGap(set.bounds[i], p, p);
    if (gap_squared > 0.0 && (best <= 0.0 || gap_squared >= best * best)) return;
    ++*evaluations;
    best = std::min(best, set.shapes[i].Distance(p.x(), p.y(), p.z()));
  });
  return best;
}

/// Fills the cells [i0, i1) (per axis) of one block from the shapes that can lower them.
template <typename Shape>
void FillBlock(const GridGeometry3& g, const Shapes<Shape>& set, const BoxBucketGrid& grid,
               double cap_m, const Eigen::Vector3i& i0, const Eigen::Vector3i& i1,
               std::vector<int>* candidates, std::vector<float>* values,
               std::int64_t* evaluations) {
  const Eigen::Vector3d lo = g.CellCenter(i0.x(), i0.y(), i0.z());
  const Eigen::Vector3d hi = g.CellCenter(i1.x() - 1, i1.y() - 1, i1.z() - 1);
  // The field is 1-Lipschitz: every cell of the block is at most `bound` (a hair added for
  // round-off), so a shape whose bounds are farther than that from the block cannot lower it.
  const double bound =
      std::min(cap_m, FieldAt(set, grid, 0.5 * (lo + hi), cap_m, evaluations) +
                          0.5 * (hi - lo).norm() + 1e-9);
  candidates->clear();
  grid.VisitNear(lo.head<2>(), hi.head<2>(), [bound] { return bound; }, [&](int i) {
    if (SquaredGap(set.bounds[i], lo, hi) <= bound * bound) candidates->push_back(i);
  });
  const float cap = static_cast<float>(cap_m);
  float* data = values->data();
  for (int iz = i0.z(); iz < i1.z(); ++iz) {
    const double z = g.origin_W_m.z() + (iz + 0.5) * g.resolution_m;
    for (int iy = i0.y(); iy < i1.y(); ++iy) {
      const double y = g.origin_W_m.y() + (iy + 0.5) * g.resolution_m;
      float* row = data + g.Index(0, iy, iz);
      for (int ix = i0.x(); ix < i1.x(); ++ix) {
        const double x = g.origin_W_m.x() + (ix + 0.5) * g.resolution_m;
        float value = cap;
        for (int i : *candidates) {
          value = std::min(value, static_cast<float>(set.shapes[i].Distance(x, y, z)));
        }
        row[ix] = value;
      }
    }
  }
  *evaluations += static_cast<std::int64_t>(candidates->size()) * (i1 - i0).prod();
}

/// The capped distances of every cell, in blocks of block_cells per axis. `stop`, polled once
/// per row of blocks, ends the fill early (returns false): the cells not yet filled read
/// -cap_m (occupied), a conservative field. No shape: every cell is cap_m.
template <typename Shape>
bool FillCappedDistances(const GridGeometry3& g, const Shapes<Shape>& set, double cap_m,
                         int block_cells, std::stop_token stop, std::vector<float>* values,
                         std::int64_t* evaluations) {
  values->assign(g.NumCells(), static_cast<float>(-cap_m));
  if (set.shapes.empty()) {
    std::fill(values->begin(), values->end(), static_cast<float>(cap_m));
    return true;
  }
  const BoxBucketGrid grid(set.bounds);
  std::vector<int> candidates;
  const Eigen::Vector3i block = Eigen::Vector3i::Constant(block_cells);
  for (int iz = 0; iz < g.dims.z(); iz += block_cells) {
    for (int iy = 0; iy < g.dims.y(); iy += block_cells) {
      if (stop.stop_requested()) return false;
      for (int ix = 0; ix < g.dims.x(); ix += block_cells) {
        const Eigen::Vector3i i0(ix, iy, iz);
        FillBlock(g, set, grid, cap_m, i0, (i0 + block).cwiseMin(g.dims), &candidates, values,
                  evaluations);
      }
    }
  }
  return true;
}

}  // namespace topay::capped_distance_fill
