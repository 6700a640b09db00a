#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "core/map/grid_geometry.h"

namespace topay {

/// The part of a segment p_WS -> p_WP inside a grid, in grid units and voxels: where the
/// voxel walk of TraverseVoxelRay starts and ends. Made by ClipVoxelRay.
struct VoxelRayClip {
  bool empty = true;          ///< The segment misses the grid (nothing to visit).
  double u_S[3] = {0, 0, 0};  ///< Segment start in grid units: (p_WS - origin) / resolution.
  double du[3] = {0, 0, 0};   ///< Segment in grid units: (p_WP - p_WS) / resolution.
  int first[3] = {0, 0, 0};   ///< Voxel where the clipped segment starts.
  int last[3] = {0, 0, 0};    ///< Voxel where it ends (the voxel of p_WP when inside).
};

/// Clips the closed segment p_WS -> p_WP to the grid's box (half-open on its maximum faces as
/// GridGeometry3::Contains, so a segment lying in a maximum face misses it) and finds its first
/// and last voxels: the voxel of each endpoint inside the grid (GridGeometry3::CellOf), else
/// of the entry or exit point, clamped to the grid. Throws std::invalid_argument if an
/// endpoint has a NaN or infinite coordinate.
VoxelRayClip ClipVoxelRay(const GridGeometry3& grid, const Eigen::Vector3d& p_WS,
                          const Eigen::Vector3d& p_WP);

/// Calls visit(const Eigen::Vector3i& voxel, std::int64_t index) for every voxel of `grid` the
/// segment p_WS -> p_WP passes through, in order from p_WS (3D digital differential analyser
/// of Amanatides & Woo, "A fast voxel traversal algorithm for ray tracing", 1987), with
/// index = grid.Index(voxel). Only the part inside the grid is walked (ClipVoxelRay); the
/// walk ends in the voxel of p_WP when p_WP is inside, so a ray's last voxel is its return's.
/// Where the segment crosses a voxel edge or corner exactly (ties between axes), all tied
/// axes step at once: voxels the segment only touches at an edge or corner are skipped
/// (up to rounding: a crossing that ties geometrically but not in floating point visits one
/// extra neighbour touching the segment). Each visited voxel is 6-connected or (at ties)
/// edge/corner-connected to the previous one, and the walk never leaves the grid.
/// A zero-length segment inside the grid visits its one voxel. If `visit` returns bool, false
/// stops the walk. Returns the voxels visited. Throws std::invalid_argument for a NaN or
/// infinite endpoint. Allocation-free; cost: one step per voxel boundary crossed.
template <typename Visitor>
int TraverseVoxelRay(const GridGeometry3& grid, const Eigen::Vector3d& p_WS,
                     const Eigen::Vector3d& p_WP, Visitor&& visit) {
  const VoxelRayClip clip = ClipVoxelRay(grid, p_WS, p_WP);
  if (clip.empty) return 0;
  const std::int64_t stride[3] = {1, std::int64_t{grid.dims.x()},
                                  std::int64_t{grid.dims.x()} * grid.dims.y()};
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::Vector3i voxel(clip.first[0], clip.first[1], clip.first[2]);
  int step[3];
  int remaining[3];        // boundary crossings left per axis before the last voxel
  double t_next[3];        // segment parameter of the next boundary crossed per axis
  double t_delta[3];       // parameter between two crossings per axis: 1 / |du|
  for (int a = 0; a < 3; ++a) {
    step[a] = clip.du[a] > 0.0 ? 1 : -1;
    remaining[a] = (clip.last[a] - clip.first[a]) * step[a];  // < 0 only by rounding
    if (remaining[a] <= 0) {
      remaining[a] = 0;
      t_next[a] = kInf;
      t_delta[a] = kInf;
      continue;
    }
    // Next boundary: the voxel's upper face (i + 1) stepping up, its lower face (i) down;
    // u_S + t du crosses it at t = (face - u_S) / du.
    const double face = voxel(a) + (step[a] > 0 ? 1 : 0);
    t_next[a] = (face - clip.u_S[a]) / clip.du[a];
    t_delta[a] = 1.0 / std::abs(clip.du[a]);
  }
  std::int64_t index = grid.Index(voxel.x(), voxel.y(), voxel.z());
  int visited = 0;
  while (true) {
    ++visited;
    if constexpr (std::is_same_v<std::invoke_result_t<Visitor&, const Eigen::Vector3i&,
                                                      std::int64_t>,
                                 bool>) {
      if (!visit(static_cast<const Eigen::Vector3i&>(voxel), index)) return visited;
    } else {
      visit(static_cast<const Eigen::Vector3i&>(voxel), index);
    }
    if (remaining[0] + remaining[1] + remaining[2] == 0) return visited;
    // The nearest boundary; every axis crossing it at the same parameter steps together.
    const double t = std::min(t_next[0], std::min(t_next[1], t_next[2]));
    for (int a = 0; a < 3; ++a) {
      if (t_next[a] != t) continue;
      voxel(a) += step[a];
      index += step[a] * stride[a];
      t_next[a] = --remaining[a] > 0 ? t_next[a] + t_delta[a] : kInf;
    }
  }
}

}  // namespace topay
