#include "core/geometry/box_bucket_grid.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

bool Usable(const Eigen::AlignedBox3d& box) {
  return box.min().allFinite() && box.max().allFinite() && !box.isEmpty();
}

}  // namespace

double BoxBucketGrid::DefaultBucketSize(std::span<const Eigen::AlignedBox3d> bounds_W_m) {
  Eigen::AlignedBox2d all;
  std::vector<double> extents;
  extents.reserve(bounds_W_m.size());
  for (const Eigen::AlignedBox3d& box : bounds_W_m) {
    if (!Usable(box)) continue;
    all.extend(Eigen::AlignedBox2d(box.min().head<2>(), box.max().head<2>()));
    extents.push_back(box.sizes().head<2>().maxCoeff());
  }
  if (extents.empty()) return 1.0;
  const double area = std::max(all.sizes().prod(), 1e-6);
  std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
  const double median_extent = extents[extents.size() / 2];
  const double size = std::max(std::sqrt(2.0 * area / extents.size()), 0.5 * median_extent);
  return std::max(size, 1e-3);
}

BoxBucketGrid::BoxBucketGrid(std::span<const Eigen::AlignedBox3d> bounds_W_m,
                             double bucket_size_m, std::int64_t max_buckets) {
  if (!(std::isfinite(bucket_size_m) && bucket_size_m >= 0.0) || max_buckets < 1) {
    throw std::invalid_argument("BoxBucketGrid: bucket_size_m must be finite and >= 0 (0: "
                                "automatic) and max_buckets >= 1, got " +
                                std::to_string(bucket_size_m));
  }
  if (bounds_W_m.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::invalid_argument("BoxBucketGrid: more than 2^31 - 1 boxes");
  }
  Eigen::AlignedBox2d all;
  for (const Eigen::AlignedBox3d& box : bounds_W_m) {
    if (Usable(box)) all.extend(Eigen::AlignedBox2d(box.min().head<2>(), box.max().head<2>()));
  }
  ranges_.assign(bounds_W_m.size(), Range{0, 0, -1, -1});
  if (all.isEmpty()) {
    bucket_start_.assign(1, 0);
    return;
  }
  size_m_ = bucket_size_m > 0.0 ? bucket_size_m : DefaultBucketSize(bounds_W_m);
  origin_m_ = all.min();
  for (;;) {
    const double nx = std::floor(all.sizes().x() / size_m_) + 1.0;
    const double ny = std::floor(all.sizes().y() / size_m_) + 1.0;
    if (nx * ny <= static_cast<double>(max_buckets)) {
      nx_ = static_cast<int>(nx);
      ny_ = static_cast<int>(ny);
      break;
    }
    size_m_ *= 1.5;
  }
  // Counting pass, then the lists (CSR).
  const std::int64_t num_buckets = std::int64_t{nx_} * ny_;
  std::vector<std::int64_t> counts(num_buckets + 1, 0);
  for (std::size_t i = 0; i < bounds_W_m.size(); ++i) {
    const Eigen::AlignedBox3d& box = bounds_W_m[i];
    if (!Usable(box)) continue;
    Range r{std::max(BucketX(box.min().x()), 0), std::max(BucketY(box.min().y()), 0),
            std::min(BucketX(box.max().x()), nx_ - 1), std::min(BucketY(box.max().y()), ny_ - 1)};
    ranges_[i] = r;
    for (int by = r.y0; by <= r.y1; ++by) {
      for (int bx = r.x0; bx <= r.x1; ++bx) ++counts[std::int64_t{by} * nx_ + bx + 1];
    }
  }
  for (std::int64_t b = 0; b < num_buckets; ++b) counts[b + 1] += counts[b];
  if (counts[num_buckets] > std::numeric_limits<std::int32_t>::max()) {
    throw std::invalid_argument("BoxBucketGrid: more than 2^31 - 1 bucket entries");
  }
  bucket_start_.assign(counts.begin(), counts.end());
  ids_.resize(counts[num_buckets]);
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    const Range& r = ranges_[i];
    for (int by = r.y0; by <= r.y1; ++by) {
      for (int bx = r.x0; bx <= r.x1; ++bx) {
        ids_[counts[std::int64_t{by} * nx_ + bx]++] = static_cast<std::int32_t>(i);
      }
    }
  }
}

int BoxBucketGrid::BucketX(double x) const {
  const double u = std::floor((x - origin_m_.x()) / size_m_);
  if (!(u >= -1.0)) return -1;  // also NaN
  return static_cast<int>(std::min(u, static_cast<double>(nx_)));
}

int BoxBucketGrid::BucketY(double y) const {
  const double u = std::floor((y - origin_m_.y()) / size_m_);
  if (!(u >= -1.0)) return -1;  // also NaN
  return static_cast<int>(std::min(u, static_cast<double>(ny_)));
}

}  // namespace topay
