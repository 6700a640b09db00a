#include "core/map/voxel_ray.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace topay {
namespace {

// Voxel of an endpoint in grid units as GridGeometry3::CellOf: floor(u).
int CellOfVoxel(double u, int dim) { return std::clamp(static_cast<int>(std::floor(u)), 0, dim - 1); }

// Voxel of a clipped segment's entry (`entering`) or exit point on one axis, clamped to
// [0, dims) (the point may round to just outside): the voxel the segment is in just after
// entering / before exiting, so a point on a voxel boundary picks the voxel the segment
// crosses, not the one it touches. Moving up (du > 0) the voxel after u is floor(u), the one
// before it ceil(u) - 1; moving down the converse.
int ClippedVoxel(double u, double du, bool entering, int dim) {
  const bool up = du > 0.0;
  const double v = (du == 0.0 || up == entering) ? std::floor(u) : std::ceil(u) - 1.0;
  return std::clamp(static_cast<int>(v), 0, dim - 1);
}

}  // namespace

VoxelRayClip ClipVoxelRay(const GridGeometry3& grid, const Eigen::Vector3d& p_WS,
                          const Eigen::Vector3d& p_WP) {
  if (!p_WS.allFinite() || !p_WP.allFinite()) {
    throw std::invalid_argument("TraverseVoxelRay: p_WS and p_WP must be finite");
  }
  VoxelRayClip clip;
  double t_enter = 0.0, t_exit = 1.0;
  double u_P[3];
  for (int a = 0; a < 3; ++a) {
    // Grid units: u = (p - origin) / resolution, so voxel i covers [i, i + 1); computed as
    // GridGeometry3::CellOf does, so an endpoint's voxel is its CellOf.
    clip.u_S[a] = (p_WS(a) - grid.origin_W_m(a)) / grid.resolution_m;
    u_P[a] = (p_WP(a) - grid.origin_W_m(a)) / grid.resolution_m;
    clip.du[a] = u_P[a] - clip.u_S[a];
    const double dim = grid.dims(a);
    if (clip.du[a] == 0.0) {
      // Parallel to the slab 0 <= u < dim: inside for every t or for none.
      if (!(clip.u_S[a] >= 0.0 && clip.u_S[a] < dim)) return clip;
      continue;
    }
    // Slab method: u_S + t du in [0, dim] for t between the two face crossings.
    const double t_low = (0.0 - clip.u_S[a]) / clip.du[a];
    const double t_high = (dim - clip.u_S[a]) / clip.du[a];
    t_enter = std::max(t_enter, std::min(t_low, t_high));
    t_exit = std::min(t_exit, std::max(t_low, t_high));
  }
  if (t_enter > t_exit) return clip;
  for (int a = 0; a < 3; ++a) {
    // An endpoint inside keeps its own voxel (t = 0 or 1 exactly); clipped ends are clamped.
    clip.first[a] = t_enter == 0.0
                        ? CellOfVoxel(clip.u_S[a], grid.dims(a))
                        : ClippedVoxel(clip.u_S[a] + t_enter * clip.du[a], clip.du[a], true,
                                       grid.dims(a));
    clip.last[a] = t_exit == 1.0 ? CellOfVoxel(u_P[a], grid.dims(a))
                                 : ClippedVoxel(clip.u_S[a] + t_exit * clip.du[a], clip.du[a],
                                                false, grid.dims(a));
  }
  clip.empty = false;
  return clip;
}

}  // namespace topay
