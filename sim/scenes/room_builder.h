#pragma once

#include <string>
#include <vector>

#include "core/common/random.h"
#include "sim/scenes/generated_scene.h"
#include "sim/scenes/keep_out.h"
#include "sim/scenes/room_options.h"

namespace topay {

/// Fills a GeneratedScene with the parts of a benchmark room, one kind of object at a time,
/// drawing from the caller's Rng in a fixed order (so a seed fixes the scene). Every object is
/// placed by rejection sampling: yaw and sizes are drawn, then the centre uniformly over the
/// positions whose world AABB lies inside the walls; the object is redrawn while any of its
/// boxes (after rounding to the 1e-6 grid, see quantize.h) leaves the interior or enters a
/// keep-out region, at most RoomOptions::max_tries_per_object times (then std::runtime_error).
/// Bad options (negative counts or sizes, min > max, objects larger than the room) throw
/// std::invalid_argument naming the option.
class RoomBuilder {
 public:
  RoomBuilder(const RoomOptions& room, const KeepOutRegions& keep_out, Rng* rng,
              GeneratedScene* out);

  /// Four walls along the room's border, inside the size_x_m x size_y_m square.
  void AddWalls();
  void AddGroundedBoxes(const GroundedBoxOptions& options);
  void AddFloatingCubes(const FloatingCubeOptions& options);
  void AddTableGroups(const TableGroupOptions& options);

 private:
  // Draws a centre for a box of the given yaw and size (uniform where its AABB fits inside the
  // walls), rounds it to the grid and checks it. Returns false if it does not fit.
  bool TryPlaceBox(const Eigen::Vector3d& size_m, double yaw_rad, double center_z_m,
                   OrientedBox* box);
  bool Fits(const OrientedBox& box) const;
  void Append(const OrientedBox& box, BoxRole role);
  [[noreturn]] void ThrowNoRoom(const std::string& what, int index, int count) const;

  RoomOptions room_;
  const KeepOutRegions& keep_out_;
  Rng& rng_;
  GeneratedScene& out_;
  Eigen::Vector2d interior_min_m_;
  Eigen::Vector2d interior_max_m_;
};

}  // namespace topay
