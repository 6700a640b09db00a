#pragma once
// Test support for the map codec and receiver: seeded voxel grids with structure (free space,
// occupied boxes, unknown elsewhere), random change lists, the sender's side of the protocol
// and a real LCM encode/decode.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/common/random.h"
#include "core/map/grid_geometry.h"
#include "core/map/voxel_map_fields.h"
#include "topay/map_update_t.hpp"
#include "topay_msgs/checked_decode.h"

namespace topay::msgs::test {

// A 40 x 30 x 8 grid at 0.05 m (9600 voxels).
inline GridGeometry3 SmallGeometry() {
  GridGeometry3 geometry;
  geometry.origin_W_m = Eigen::Vector3d(-1.0, -0.75, 0.0);
  geometry.resolution_m = 0.05;
  geometry.dims = Eigen::Vector3i(40, 30, 8);
  return geometry;
}

// Sets the voxels of the box [lo, hi) (clipped to the grid) to `state`.
inline void FillBox(const GridGeometry3& geometry, Eigen::Vector3i lo, Eigen::Vector3i hi,
                    VoxelState state, std::vector<std::uint8_t>* states) {
  lo = lo.cwiseMax(0);
  hi = hi.cwiseMin(geometry.dims);
  for (int iz = lo.z(); iz < hi.z(); ++iz) {
    for (int iy = lo.y(); iy < hi.y(); ++iy) {
      for (int ix = lo.x(); ix < hi.x(); ++ix) {
        (*states)[geometry.Index(ix, iy, iz)] = static_cast<std::uint8_t>(state);
      }
    }
  }
}

// Unknown, with `num_boxes` random free boxes and as many occupied ones, and a few voxels
// flipped at random (so that runs of one voxel occur too).
inline std::vector<std::uint8_t> RandomStates(const GridGeometry3& geometry, std::uint64_t seed,
                                              int num_boxes = 6) {
  Rng rng(seed);
  std::vector<std::uint8_t> states(geometry.NumCells(),
                                   static_cast<std::uint8_t>(VoxelState::kUnknown));
  const auto random_box = [&](VoxelState state) {
    Eigen::Vector3i lo, size;
    for (int a = 0; a < 3; ++a) {
      lo(a) = static_cast<int>(rng.UniformInt(0, geometry.dims(a) - 1));
      size(a) = static_cast<int>(rng.UniformInt(1, std::max(1, geometry.dims(a) / 2)));
    }
    FillBox(geometry, lo, lo + size, state, &states);
  };
  for (int b = 0; b < num_boxes; ++b) random_box(VoxelState::kFree);
  for (int b = 0; b < num_boxes; ++b) random_box(VoxelState::kOccupied);
  for (int k = 0; k < static_cast<int>(states.size()) / 50; ++k) {
    states[rng.UniformInt(0, geometry.NumCells() - 1)] =
        static_cast<std::uint8_t>(rng.UniformInt(0, 2));
  }
  return states;
}

// `n` random changes, some voxels listed several times.
inline std::vector<VoxelChange> RandomChanges(const GridGeometry3& geometry, int n,
                                              std::uint64_t seed) {
  Rng rng(seed);
  std::vector<VoxelChange> changes(n);
  for (int k = 0; k < n; ++k) {
    if (k > 0 && rng.Uniform01() < 0.2) {
      changes[k].voxel = changes[rng.UniformInt(0, k - 1)].voxel;
    } else {
      for (int a = 0; a < 3; ++a) {
        changes[k].voxel(a) = static_cast<int>(rng.UniformInt(0, geometry.dims(a) - 1));
      }
    }
    changes[k].state = static_cast<VoxelState>(rng.UniformInt(0, 2));
  }
  return changes;
}

// Applies the changes in order to the states.
inline void ApplyTo(const GridGeometry3& geometry, const std::vector<VoxelChange>& changes,
                    std::vector<std::uint8_t>* states) {
  for (const VoxelChange& change : changes) {
    (*states)[geometry.Index(change.voxel.x(), change.voxel.y(), change.voxel.z())] =
        static_cast<std::uint8_t>(change.state);
  }
}

// The message through the generated LCM encoder and the checked decoder (fails the test if
// the bytes do not decode).
inline map_update_t ThroughLcm(const map_update_t& msg) {
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  EXPECT_EQ(msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  std::string error;
  const std::optional<map_update_t> back =
      CheckedDecode<map_update_t>(bytes.data(), bytes.size(), &error);
  EXPECT_TRUE(back) << error;
  return back.value_or(map_update_t{});
}

// Encoded size on the bus (LCM bytes), for size checks.
inline int BusBytes(const map_update_t& msg) { return msg.getEncodedSize(); }

}  // namespace topay::msgs::test
