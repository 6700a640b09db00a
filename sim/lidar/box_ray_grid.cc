#include "sim/lidar/box_ray_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace topay::sim {
namespace {

// Intersects [*t0, *t1] with the t interval on which o + t d lies in [lo, hi] on one axis.
bool ClipAxis(double o, double d, double lo, double hi, double* t0, double* t1) {
  if (d == 0.0) return o >= lo && o <= hi;
  double a = (lo - o) / d;
  double b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  *t0 = std::max(*t0, a);
  *t1 = std::min(*t1, b);
  return *t0 <= *t1;
}

}  // namespace

BoxRayGrid::BoxRayGrid(double cell_m, std::int64_t max_cells)
    : requested_cell_m_(cell_m), max_cells_(max_cells), cell_m_(cell_m) {}

void BoxRayGrid::Build(const std::vector<OrientedBox>& boxes) {
  boxes_.clear();
  boxes_.reserve(boxes.size());
  lo_m_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  hi_m_ = -lo_m_;
  std::vector<Eigen::AlignedBox3d> bounds;
  bounds.reserve(boxes.size());
  for (const OrientedBox& box : boxes) {
    const bool finite = box.center_W_m.allFinite() && box.size_m.allFinite() &&
                        std::isfinite(box.yaw_rad) && (box.size_m.array() >= 0.0).all();
    boxes_.push_back({std::cos(box.yaw_rad), std::sin(box.yaw_rad), box.center_W_m,
                      box.HalfSize(), finite});
    Eigen::AlignedBox3d aabb;  // empty unless finite
    if (finite) {
      aabb = box.WorldBounds();
      aabb.min().array() -= kPadM;
      aabb.max().array() += kPadM;
      lo_m_ = lo_m_.cwiseMin(aabb.min());
      hi_m_ = hi_m_.cwiseMax(aabb.max());
    }
    bounds.push_back(aabb);
  }
  stamp_.assign(boxes_.size(), 0);
  ray_stamp_ = 0;
  box_tests_ = 0;
  cell_start_.clear();
  ids_.clear();
  nx_ = ny_ = 0;
  if (!(lo_m_.x() <= hi_m_.x())) return;  // nothing finite: an empty grid, every ray misses

  // Cells: the requested side, grown until the extent fits in max_cells.
  cell_m_ = requested_cell_m_;
  const Eigen::Vector2d extent = (hi_m_ - lo_m_).head<2>();
  for (;;) {
    nx_ = std::max(1, static_cast<int>(std::ceil(extent.x() / cell_m_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(extent.y() / cell_m_)));
    if (std::int64_t{nx_} * ny_ <= max_cells_) break;
    cell_m_ *= 2.0;
  }
  origin_m_ = lo_m_.head<2>();
  const std::int64_t cells = std::int64_t{nx_} * ny_;
  auto range = [&](const Eigen::AlignedBox3d& b, int axis, int n) {
    const int i0 = static_cast<int>(std::floor((b.min()(axis) - origin_m_(axis)) / cell_m_));
    const int i1 = static_cast<int>(std::floor((b.max()(axis) - origin_m_(axis)) / cell_m_));
    return Eigen::Vector2i(std::clamp(i0, 0, n - 1), std::clamp(i1, 0, n - 1));
  };
  // Counting pass, then the fill pass (compressed rows).
  cell_start_.assign(cells + 1, 0);
  cell_z_lo_.assign(cells, std::numeric_limits<double>::infinity());
  cell_z_hi_.assign(cells, -std::numeric_limits<double>::infinity());
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::int32_t> fill;
    if (pass == 1) {
      for (std::int64_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
      ids_.assign(cell_start_[cells], 0);
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (int i = 0; i < num_boxes(); ++i) {
      if (bounds[i].isEmpty()) continue;
      const Eigen::Vector2i rx = range(bounds[i], 0, nx_), ry = range(bounds[i], 1, ny_);
      for (int iy = ry(0); iy <= ry(1); ++iy) {
        for (int ix = rx(0); ix <= rx(1); ++ix) {
          const std::int64_t c = std::int64_t{iy} * nx_ + ix;
          if (pass == 0) {
            ++cell_start_[c + 1];
            cell_z_lo_[c] = std::min(cell_z_lo_[c], bounds[i].min().z());
            cell_z_hi_[c] = std::max(cell_z_hi_[c], bounds[i].max().z());
          } else {
            ids_[fill[c]++] = i;
          }
        }
      }
    }
  }
}

double BoxRayGrid::Entry(int i, const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W) const {
  const PackedBox& b = boxes_[i];
  // Into the box frame: v_B = Rz(yaw)^T v_W for directions, and for the origin after
  // subtracting the centre.
  const double rx = p_WO.x() - b.center_m.x(), ry = p_WO.y() - b.center_m.y();
  const Eigen::Vector3d o_B(b.cos_yaw * rx + b.sin_yaw * ry, -b.sin_yaw * rx + b.cos_yaw * ry,
                            p_WO.z() - b.center_m.z());
  const Eigen::Vector3d d_B(b.cos_yaw * d_W.x() + b.sin_yaw * d_W.y(),
                            -b.sin_yaw * d_W.x() + b.cos_yaw * d_W.y(), d_W.z());
  return RayCenteredBoxEntry(o_B, d_B, b.half_m);
}

BoxRayGrid::Hit BoxRayGrid::FirstHitBruteForce(const Eigen::Vector3d& p_WO,
                                               const Eigen::Vector3d& d_W,
                                               double t_max_m) const {
  Hit best;
  for (int i = 0; i < num_boxes(); ++i) {
    if (!boxes_[i].finite) continue;
    const double t = Entry(i, p_WO, d_W);
    if (t <= t_max_m && t < best.t_m) best = {t, i};  // strict: ties keep the lower index
  }
  return best;
}

void BoxRayGrid::NextStamp() {
  if (++ray_stamp_ == 0) {  // wrapped: forget every old stamp
    std::fill(stamp_.begin(), stamp_.end(), 0);
    ray_stamp_ = 1;
  }
}

void BoxRayGrid::TestCell(std::int64_t cell, const Eigen::Vector3d& p_WO,
                          const Eigen::Vector3d& d_W, double t_max_m, Hit* best) {
  for (std::int32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    const int i = ids_[k];
    if (stamp_[i] == ray_stamp_) continue;
    stamp_[i] = ray_stamp_;
    ++box_tests_;
    const double t = Entry(i, p_WO, d_W);
    if (t <= t_max_m && (t < best->t_m || (t == best->t_m && i < best->box))) *best = {t, i};
  }
}

BoxRayGrid::Hit BoxRayGrid::FirstHit(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W,
                                     double t_max_m) {
  Hit best;
  if (nx_ == 0) return best;
  // The part of the ray inside the grown union of the boxes' AABBs.
  double t_enter = 0.0, t_end = t_max_m;
  for (int axis = 0; axis < 3; ++axis) {
    if (!ClipAxis(p_WO(axis), d_W(axis), lo_m_(axis), hi_m_(axis), &t_enter, &t_end)) {
      return best;
    }
  }
  NextStamp();
  // Amanatides-Woo: the cell of the entry point, the t of the next x and y cell borders and
  // the t between two borders; step into whichever border comes first.
  const double inf = std::numeric_limits<double>::infinity();
  const auto start_cell = [&](int axis, int n) {
    const double p = p_WO(axis) + t_enter * d_W(axis);
    return std::clamp(static_cast<int>(std::floor((p - origin_m_(axis)) / cell_m_)), 0, n - 1);
  };
  int ix = start_cell(0, nx_), iy = start_cell(1, ny_);
  const int step_x = d_W.x() > 0.0 ? 1 : (d_W.x() < 0.0 ? -1 : 0);
  const int step_y = d_W.y() > 0.0 ? 1 : (d_W.y() < 0.0 ? -1 : 0);
  // The next border on the side the ray moves to: cell index + 1 going up, + 0 going down.
  double t_next_x = step_x == 0 ? inf
                                : (origin_m_.x() + (ix + (step_x > 0)) * cell_m_ - p_WO.x()) /
                                      d_W.x();
  double t_next_y = step_y == 0 ? inf
                                : (origin_m_.y() + (iy + (step_y > 0)) * cell_m_ - p_WO.y()) /
                                      d_W.y();
  const double t_delta_x = step_x == 0 ? inf : cell_m_ / std::abs(d_W.x());
  const double t_delta_y = step_y == 0 ? inf : cell_m_ / std::abs(d_W.y());
  double z_enter = p_WO.z() + t_enter * d_W.z();
  for (;;) {
    const double t_exit = std::min(std::min(t_next_x, t_next_y), t_end);
    const double z_exit = p_WO.z() + t_exit * d_W.z();
    const std::int64_t cell = std::int64_t{iy} * nx_ + ix;
    // The ray's z over this cell against the cell's boxes' z range (empty cells: none).
    if (std::max(z_enter, z_exit) >= cell_z_lo_[cell] &&
        std::min(z_enter, z_exit) <= cell_z_hi_[cell]) {
      TestCell(cell, p_WO, d_W, t_max_m, &best);
    }
    if (best.t_m < t_exit || t_exit >= t_end) break;
    if (t_next_x < t_next_y) {
      ix += step_x;
      if (ix < 0 || ix >= nx_) break;
      t_next_x += t_delta_x;
    } else {
      iy += step_y;
      if (iy < 0 || iy >= ny_) break;
      t_next_y += t_delta_y;
    }
    z_enter = z_exit;
  }
  return best;
}

}  // namespace topay::sim
