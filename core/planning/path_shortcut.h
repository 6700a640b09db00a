#pragma once

#include <Eigen/Core>
#include <stop_token>
#include <vector>

#include "core/planning/base_free_space.h"

namespace topay {

/// Options of ShortcutPath.
struct PathShortcutOptions {
  /// The input is resampled at this spacing before shortcutting (finer: tighter
  /// corners);
  /// <= 0: the field's cell size.
  double resample_step_m = 0.0;
  /// Greedy passes, alternating direction (start -> goal first); after the
  /// first pass, a pass that does not shorten the path ends the loop.
  int max_passes = 4;
};

/// Greedy visibility shortcut of a free polyline: from an anchor, walk along
/// the (resampled) path while the anchor still sees the next point; the last
/// visible point becomes the next vertex and anchor. Passes alternate
/// direction, since a one-way pass stalls at a vertex that its anchor sees
/// tangentially. Keeps first and last points (bit for bit). Each output segment
/// is free in `free_space`; the output is never longer than the input. If an
/// input segment is not free the function still terminates (it keeps that
/// segment as is). `stop` is polled before every visibility test: once it
/// fires, the path after the last completed pass is returned (the input if no
/// pass completed), so the return follows within one segment test.
std::vector<Eigen::Vector2d> ShortcutPath(const BaseFreeSpace& free_space,
                                          const std::vector<Eigen::Vector2d>& path_W_m,
                                          const PathShortcutOptions& options = {},
                                          const std::stop_token& stop = {});

/// Shortcuts every path, in parallel (TBB parallel_for); output order = input
/// order. Once `stop` fires, paths not yet started are returned unchanged and
/// those in progress as ShortcutPath leaves them.
std::vector<std::vector<Eigen::Vector2d>> ShortcutPaths(
    const BaseFreeSpace& free_space, const std::vector<std::vector<Eigen::Vector2d>>& paths_W_m,
    const PathShortcutOptions& options = {}, const std::stop_token& stop = {});

/// Points spaced uniformly by arc length along a polyline: num_points >= 2
/// points, the first and last being the polyline's end points. A single-point
/// polyline is repeated.
std::vector<Eigen::Vector2d> ResampleUniform(const std::vector<Eigen::Vector2d>& path_W_m,
                                             int num_points);

}  // namespace topay
