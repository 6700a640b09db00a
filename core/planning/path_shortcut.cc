#include "core/planning/path_shortcut.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/planning/base_path.h"

namespace topay {
namespace {

// Inserts points so that no segment is longer than step_m (end points and
// vertices kept).
std::vector<Eigen::Vector2d> Densify(const std::vector<Eigen::Vector2d>& path, double step_m) {
  std::vector<Eigen::Vector2d> dense;
  if (path.empty()) return dense;
  dense.push_back(path.front());
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d& a = path[i - 1];
    const Eigen::Vector2d& b = path[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_m)));
    for (int k = 1; k < pieces; ++k) dense.push_back(a + (b - a) * (double(k) / pieces));
    dense.push_back(b);  // exactly, so vertices (and the end point) survive bit for bit
  }
  return dense;
}

// One greedy pass: anchor, walk forward while visible, take the last visible
// point. False (output incomplete) if `stop` fired during the pass.
bool GreedyPass(const BaseFreeSpace& free_space, const std::vector<Eigen::Vector2d>& points,
                const std::stop_token& stop, std::vector<Eigen::Vector2d>* out) {
  out->assign(1, points.front());
  std::size_t anchor = 0;
  const std::size_t last = points.size() - 1;
  while (anchor < last) {
    std::size_t next = anchor + 1;  // kept even if not free: guarantees progress
    while (next < last) {
      if (stop.stop_requested()) return false;
      if (!free_space.IsSegmentFree(points[anchor], points[next + 1])) break;
      ++next;
    }
    out->push_back(points[next]);
    anchor = next;
  }
  return true;
}

}  // namespace

std::vector<Eigen::Vector2d> ShortcutPath(const BaseFreeSpace& free_space,
                                          const std::vector<Eigen::Vector2d>& path_W_m,
                                          const PathShortcutOptions& options,
                                          const std::stop_token& stop) {
  if (path_W_m.size() <= 2) return path_W_m;
  const double step = options.resample_step_m > 0.0 ? options.resample_step_m
                                                    : free_space.field().geometry().resolution_m;
  std::vector<Eigen::Vector2d> path = path_W_m;
  for (int pass = 0; pass < std::max(1, options.max_passes); ++pass) {
    // Alternate directions: a one-way greedy pass can stall at a vertex the
    // anchor sees tangentially; the pass from the other end slides that vertex
    // along. Each new segment replaces a sub-path between its end points: never
    // longer (triangle inequality).
    std::vector<Eigen::Vector2d> dense = Densify(path, step);
    if (pass % 2 == 1) std::reverse(dense.begin(), dense.end());
    std::vector<Eigen::Vector2d> shorter;
    if (!GreedyPass(free_space, dense, stop, &shorter)) break;  // keep the last full pass
    if (pass % 2 == 1) std::reverse(shorter.begin(), shorter.end());
    const bool improved = PolylineLength(shorter) < PolylineLength(path) - 1e-9;
    path = std::move(shorter);
    if (!improved && pass > 0) break;  // both directions tried without gain
  }
  return path;
}

std::vector<std::vector<Eigen::Vector2d>> ShortcutPaths(
    const BaseFreeSpace& free_space, const std::vector<std::vector<Eigen::Vector2d>>& paths_W_m,
    const PathShortcutOptions& options, const std::stop_token& stop) {
  std::vector<std::vector<Eigen::Vector2d>> out(paths_W_m.size());
  tbb::parallel_for(std::size_t{0}, paths_W_m.size(), [&](std::size_t i) {
    out[i] = stop.stop_requested() ? paths_W_m[i]
                                   : ShortcutPath(free_space, paths_W_m[i], options, stop);
  });
  return out;
}

std::vector<Eigen::Vector2d> ResampleUniform(const std::vector<Eigen::Vector2d>& path_W_m,
                                             int num_points) {
  num_points = std::max(num_points, 2);
  std::vector<Eigen::Vector2d> out;
  out.reserve(num_points);
  if (path_W_m.empty()) return out;
  const double total = PolylineLength(path_W_m);
  if (path_W_m.size() == 1 || total == 0.0) {
    out.assign(num_points, path_W_m.front());
    return out;
  }
  std::size_t segment = 1;
  double walked = 0.0;  // arc length at path_W_m[segment - 1]
  for (int k = 0; k < num_points; ++k) {
    const double s = total * k / (num_points - 1);
    double seg_len = (path_W_m[segment] - path_W_m[segment - 1]).norm();
    while (segment + 1 < path_W_m.size() && walked + seg_len < s) {
      walked += seg_len;
      ++segment;
      seg_len = (path_W_m[segment] - path_W_m[segment - 1]).norm();
    }
    const double t = seg_len > 0.0 ? std::clamp((s - walked) / seg_len, 0.0, 1.0) : 1.0;
    out.push_back(path_W_m[segment - 1] + t * (path_W_m[segment] - path_W_m[segment - 1]));
  }
  out.back() = path_W_m.back();
  return out;
}

}  // namespace topay
