#include "core/planning/base_free_space.h"

#include <algorithm>
#include <cmath>

namespace topay {
namespace {

// Guard step (m) past a patch boundary, so that flooring lands in the next
// patch.
constexpr double kPatchExitEpsilon_m = 1e-9;

}  // namespace

BaseFreeSpace::BaseFreeSpace(const SignedDistanceField2& field, double required_distance_m,
                             double min_step_m)
    : field_(&field),
      required_distance_m_(required_distance_m),
      min_step_m_(min_step_m > 0.0 ? min_step_m : 0.01 * field.geometry().resolution_m) {}

bool BaseFreeSpace::InsideGrid(const Eigen::Vector2d& p_W) const {
  return field_->geometry().Contains(p_W);  // false for NaN
}

bool BaseFreeSpace::IsFree(const Eigen::Vector2d& p_W) const {
  return InsideGrid(p_W) && field_->Distance(p_W) >= required_distance_m_;
}

bool BaseFreeSpace::PatchClear(const Eigen::Vector2d& p_W, const Eigen::Vector2d& u,
                               double max_step_m, double* step_m) const {
  const GridGeometry2& g = field_->geometry();
  const double inv_res = 1.0 / g.resolution_m;
  // Continuous index in which cell centre i sits at U = i (as
  // SignedDistanceField2).
  const Eigen::Vector2d index = (p_W - g.origin_W_m) * inv_res - Eigen::Vector2d::Constant(0.5);
  int base[2];
  double t0[2];
  for (int a = 0; a < 2; ++a) {
    base[a] = std::min(static_cast<int>(std::floor(index(a))), g.dims(a) - 2);
    t0[a] = index(a) - base[a];
  }
  // Distance (m) along u to the patch's boundary.
  const Eigen::Vector2d w = u * inv_res;  // dU/ds
  double exit_m = max_step_m;
  for (int a = 0; a < 2; ++a) {
    if (w(a) > 0.0) exit_m = std::min(exit_m, (1.0 - t0[a]) / w(a));
    if (w(a) < 0.0) exit_m = std::min(exit_m, -t0[a] / w(a));
  }
  exit_m = std::max(exit_m, 0.0);
  const double c00 = field_->CellValue(base[0], base[1]);
  const double c10 = field_->CellValue(base[0] + 1, base[1]);
  const double c01 = field_->CellValue(base[0], base[1] + 1);
  const double c11 = field_->CellValue(base[0] + 1, base[1] + 1);
  // Bilinear patch f = c00 + dx tx + dy ty + e tx ty along t = t0 + s w is the
  // quadratic f(s) = A + B s + C s^2 (substitute and collect powers of s).
  const double dx = c10 - c00, dy = c01 - c00, e = c00 - c10 - c01 + c11;
  const double A = c00 + dx * t0[0] + dy * t0[1] + e * t0[0] * t0[1];
  const double B = dx * w(0) + dy * w(1) + e * (t0[0] * w(1) + t0[1] * w(0));
  const double C = e * w(0) * w(1);
  double minimum = std::min(A, A + exit_m * (B + exit_m * C));
  if (C > 0.0) {
    const double vertex = -B / (2.0 * C);  // minimum of an upward parabola
    if (vertex > 0.0 && vertex < exit_m) minimum = std::min(minimum, A + vertex * (B + vertex * C));
  }
  *step_m = exit_m;
  return minimum >= required_distance_m_;
}

bool BaseFreeSpace::IsSegmentFree(const Eigen::Vector2d& a_W, const Eigen::Vector2d& b_W) const {
  if (!InsideGrid(a_W) || !InsideGrid(b_W)) return false;  // the grid is convex
  const Eigen::Vector2d delta = b_W - a_W;
  const double length = delta.norm();
  if (length == 0.0) return field_->Distance(a_W) >= required_distance_m_;
  const Eigen::Vector2d u = delta / length;
  const GridGeometry2& g = field_->geometry();
  // Lipschitz bound of the bilinear field along u: |df/ds| <= |u_x| + |u_y|.
  const double lipschitz = std::abs(u.x()) + std::abs(u.y());
  const Eigen::Vector2d centres_min =
      g.origin_W_m + Eigen::Vector2d::Constant(0.5 * g.resolution_m);
  const Eigen::Vector2d centres_max =
      g.origin_W_m + (g.dims.cast<double>() - Eigen::Vector2d::Constant(0.5)) * g.resolution_m;
  double s = 0.0;
  while (true) {
    const Eigen::Vector2d p = a_W + s * u;
    const double margin = field_->Distance(p) - required_distance_m_;
    if (!(margin >= 0.0)) return false;
    if (s >= length) return true;
    double step = margin / lipschitz;  // sphere tracing: free over this step
    if (step < g.resolution_m) {
      const bool in_patches =
          (p.array() >= centres_min.array()).all() && (p.array() <= centres_max.array()).all();
      if (in_patches) {
        // Near the boundary: the exact minimum of the field over the rest of
        // this patch.
        if (!PatchClear(p, u, length - s, &step)) return false;
        step += kPatchExitEpsilon_m;
      } else {
        // Outer half cell of the grid: conservative fixed steps.
        if (margin < lipschitz * min_step_m_) return false;
        step = std::max(step, min_step_m_);
      }
    }
    s = std::min(s + step, length);
  }
}

}  // namespace topay
