#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

/// A broad phase for nearest-box queries: a uniform grid of square buckets in the world xy
/// plane, each listing the boxes whose world AABB overlaps it in xy (closed intervals). Built
/// once, in time linear in the number of boxes plus the buckets they cover plus the bucket
/// count; read-only afterwards (queries are const and thread-safe).
///
/// VisitNear visits the boxes in rings of buckets around a query rectangle, nearest ring first,
/// each box at most once, and stops as soon as every box not yet visited is provably farther
/// (in xy, hence in 3D and exactly) than a caller-given bound: the cost of a query grows with
/// the boxes near it, not with the scene's box count.
class BoxBucketGrid {
 public:
  /// Buckets of `bucket_size_m` (> 0, finite); 0 picks one from the boxes
  /// (DefaultBucketSize). Boxes with an empty or non-finite AABB are listed nowhere (never
  /// visited). At most max_buckets buckets: the size grows until the grid fits.
  explicit BoxBucketGrid(std::span<const Eigen::AlignedBox3d> bounds_W_m,
                         double bucket_size_m = 0.0, std::int64_t max_buckets = 1 << 22);

  /// About two boxes per bucket over the boxes' xy bounds: sqrt(2 area / count), at least the
  /// median box extent / 2 (so that a box lies in few buckets), 1 m for no box.
  static double DefaultBucketSize(std::span<const Eigen::AlignedBox3d> bounds_W_m);

  int num_boxes() const { return static_cast<int>(ranges_.size()); }
  double bucket_size_m() const { return size_m_; }
  Eigen::Vector2i dims() const { return {nx_, ny_}; }

  /// Calls visit(i) for box indices i, rings of buckets around the xy rectangle
  /// [q_min, q_max] first. Before each further ring it calls bound() (a distance, m) and stops
  /// if every unvisited box's xy AABB is farther than that from the rectangle (strictly
  /// farther: a box at exactly the bound is still visited). bound() may shrink as visit finds
  /// nearer boxes; +infinity visits every box.
  template <typename Bound, typename Visit>
  void VisitNear(const Eigen::Vector2d& q_min, const Eigen::Vector2d& q_max, Bound bound,
                 Visit visit) const;

 private:
  struct Range {
    int x0, y0, x1, y1;  // inclusive bucket ranges; x0 > x1 for a box listed nowhere
  };
  int BucketX(double x) const;
  int BucketY(double y) const;
  template <typename Visit>
  void VisitBucket(int bx, int by, int sx0, int sy0, int px0, int py0, int px1, int py1,
                   bool has_previous, Visit& visit) const;

  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  double size_m_ = 1.0;
  int nx_ = 0;
  int ny_ = 0;
  std::vector<Range> ranges_;               // per box
  std::vector<std::int32_t> bucket_start_;  // CSR: bucket b lists ids[start[b], start[b + 1])
  std::vector<std::int32_t> ids_;
};

// A box listed in several buckets is visited in exactly one of them: the first ring whose
// square S_r it overlaps, and there the lowest (y, x) bucket of its range clipped to S_r.
template <typename Visit>
void BoxBucketGrid::VisitBucket(int bx, int by, int sx0, int sy0, int px0, int py0, int px1,
                                int py1, bool has_previous, Visit& visit) const {
  const std::int64_t b = std::int64_t{by} * nx_ + bx;
  for (std::int32_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
    const int i = ids_[k];
    const Range& r = ranges_[i];
    if (std::max(r.x0, sx0) != bx || std::max(r.y0, sy0) != by) continue;
    // Already visited in an earlier ring if its range meets the previous square.
    if (has_previous && r.x0 <= px1 && r.x1 >= px0 && r.y0 <= py1 && r.y1 >= py0) continue;
    visit(i);
  }
}

template <typename Bound, typename Visit>
void BoxBucketGrid::VisitNear(const Eigen::Vector2d& q_min, const Eigen::Vector2d& q_max,
                              Bound bound, Visit visit) const {
  if (nx_ == 0 || ny_ == 0) return;
  // The query's bucket range, clamped to one bucket beyond the grid on each side.
  const int qx0 = BucketX(q_min.x()), qx1 = BucketX(q_max.x());
  const int qy0 = BucketY(q_min.y()), qy1 = BucketY(q_max.y());
  for (int ring = 0;; ++ring) {
    // The square S_ring = [qx0 - ring, qx1 + ring] x [qy0 - ring, qy1 + ring] of buckets.
    const int sx0 = qx0 - ring, sx1 = qx1 + ring, sy0 = qy0 - ring, sy1 = qy1 + ring;
    if (ring > 0) {
      // Every unvisited box lies outside S_{ring - 1}: at least `gap` from the query in xy.
      const int px0 = sx0 + 1, px1 = sx1 - 1, py0 = sy0 + 1, py1 = sy1 - 1;
      if (px0 <= 0 && py0 <= 0 && px1 >= nx_ - 1 && py1 >= ny_ - 1) return;  // all visited
      const double gap = std::min(
          {q_min.x() - (origin_m_.x() + px0 * size_m_),
           origin_m_.x() + (px1 + 1) * size_m_ - q_max.x(),
           q_min.y() - (origin_m_.y() + py0 * size_m_),
           origin_m_.y() + (py1 + 1) * size_m_ - q_max.y()});
      if (gap > bound()) return;
    }
    const int px0 = sx0 + 1, px1 = sx1 - 1, py0 = sy0 + 1, py1 = sy1 - 1;
    const bool has_previous = ring > 0;
    const int cx0 = std::max(sx0, 0), cx1 = std::min(sx1, nx_ - 1);
    const int cy0 = std::max(sy0, 0), cy1 = std::min(sy1, ny_ - 1);
    for (int by = cy0; by <= cy1; ++by) {
      const bool edge_row = !has_previous || by == sy0 || by == sy1;
      if (edge_row) {
        for (int bx = cx0; bx <= cx1; ++bx) {
          VisitBucket(bx, by, sx0, sy0, px0, py0, px1, py1, has_previous, visit);
        }
      } else {
        if (sx0 >= 0 && sx0 < nx_) {
          VisitBucket(sx0, by, sx0, sy0, px0, py0, px1, py1, has_previous, visit);
        }
        if (sx1 != sx0 && sx1 >= 0 && sx1 < nx_) {
          VisitBucket(sx1, by, sx0, sy0, px0, py0, px1, py1, has_previous, visit);
        }
      }
    }
  }
}

}  // namespace topay
