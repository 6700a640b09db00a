#pragma once

// Test helper: a room-like scene of random, pairwise disjoint upright boxes, so that the exact
// signed distance to the union is the minimum over the boxes of SignedDistanceToBox.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "core/common/random.h"
#include "core/geometry/oriented_box.h"
#include "core/geometry/scene.h"

namespace topay::testing {

// True if the boxes' world AABBs, grown by gap_m, overlap.
inline bool TooClose(const OrientedBox& a, const OrientedBox& b, double gap_m) {
  Eigen::AlignedBox3d grown = a.WorldBounds();
  grown.min().array() -= gap_m;
  grown.max().array() += gap_m;
  return grown.intersects(b.WorldBounds());
}

// A room of side room_m (centred at the origin, z in [0, 1.6]): four 0.2 m walls 1 m tall that
// do not overlap, then up to num_boxes random boxes of random yaw, at least gap_m apart: a mix
// of grounded boxes, floating cubes, thin floating slabs (0.05 m, table-top like) and thin
// grounded posts (0.05 m, leg like).
inline Scene RandomDisjointRoom(std::uint64_t seed, double room_m, int num_boxes,
                                double gap_m) {
  Scene scene;
  scene.kind = "test room";
  scene.seed = seed;
  const double h = 0.5 * room_m;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-h, -h, 0.0), Eigen::Vector3d(h, h, 1.6));
  const double wall = 0.2;
  auto make_box = [](Eigen::Vector3d center, Eigen::Vector3d size, double yaw) {
    OrientedBox box;
    box.center_W_m = center;
    box.size_m = size;
    box.yaw_rad = yaw;
    return box;
  };
  scene.boxes.push_back(make_box({0, -h + wall / 2, 0.5}, {room_m, wall, 1.0}, 0.0));
  scene.boxes.push_back(make_box({0, h - wall / 2, 0.5}, {room_m, wall, 1.0}, 0.0));
  scene.boxes.push_back(
      make_box({-h + wall / 2, 0, 0.5}, {wall, room_m - 2 * wall - 2 * gap_m, 1.0}, 0.0));
  scene.boxes.push_back(
      make_box({h - wall / 2, 0, 0.5}, {wall, room_m - 2 * wall - 2 * gap_m, 1.0}, 0.0));
  Rng rng(seed);
  const int num_walls = 4;
  for (int attempt = 0; attempt < 50 * num_boxes &&
                        static_cast<int>(scene.boxes.size()) < num_walls + num_boxes;
       ++attempt) {
    Eigen::Vector3d size;
    double bottom = 0.0;
    switch (attempt % 4) {
      case 0:  // grounded box
        size = {rng.Uniform(0.2, 0.8), rng.Uniform(0.2, 0.8), rng.Uniform(0.4, 1.5)};
        break;
      case 1:  // floating cube
        size.setConstant(rng.Uniform(0.3, 0.6));
        bottom = rng.Uniform(0.4, 0.8);
        break;
      case 2:  // thin slab
        size = {rng.Uniform(0.75, 1.25), rng.Uniform(0.75, 1.25), 0.05};
        bottom = rng.Uniform(0.5, 1.0);
        break;
      default:  // thin post
        size = {0.05, 0.05, rng.Uniform(0.5, 1.0)};
        break;
    }
    const double margin = h - wall - 0.8;
    const Eigen::Vector3d center(rng.Uniform(-margin, margin), rng.Uniform(-margin, margin),
                                 bottom + 0.5 * size.z());
    const OrientedBox box =
        make_box(center, size, rng.Uniform(-std::numbers::pi, std::numbers::pi));
    const bool clear = std::none_of(scene.boxes.begin(), scene.boxes.end(),
                                    [&](const OrientedBox& other) {
                                      return TooClose(box, other, gap_m);
                                    });
    if (clear) scene.boxes.push_back(box);
  }
  return scene;
}

// Exact signed distance to the union of pairwise disjoint boxes.
inline double ExactSignedDistance(const std::vector<OrientedBox>& boxes,
                                  const Eigen::Vector3d& p_W) {
  double best = std::numeric_limits<double>::infinity();
  for (const OrientedBox& box : boxes) best = std::min(best, SignedDistanceToBox(box, p_W));
  return best;
}

// Exact signed distance in xy to the union of pairwise disjoint footprints.
inline double ExactSignedDistance2d(const std::vector<OrientedBox>& boxes,
                                    const Eigen::Vector2d& p_W) {
  double best = std::numeric_limits<double>::infinity();
  for (const OrientedBox& box : boxes) {
    best = std::min(best, SignedDistanceToFootprint(box, p_W));
  }
  return best;
}

}  // namespace topay::testing
