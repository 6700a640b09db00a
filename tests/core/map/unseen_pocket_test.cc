// FindUnseenPocket on hand-made grids: what the map shows closed is enclosed, anything with an
// opening, a seen-free voxel, or more room than the reach is not.

#include "core/map/unseen_pocket.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/map/voxel_state.h"

namespace topay {
namespace {

// A 4 x 4 x 1 m grid of 10 cm voxels from (0, 0, 0): every voxel free (seen) unless set.
class Grid {
 public:
  Grid() {
    geometry_.origin_W_m = Eigen::Vector3d::Zero();
    geometry_.resolution_m = 0.1;
    geometry_.dims = Eigen::Vector3i(40, 40, 10);
    states_.assign(geometry_.NumCells(), static_cast<std::uint8_t>(VoxelState::kFree));
  }
  void Set(int ix, int iy, int iz, VoxelState s) { states_[geometry_.Index(ix, iy, iz)] = static_cast<std::uint8_t>(s); }
  // Cells [x0, x1] x [y0, y1] of layer iz set to s.
  void Fill(int x0, int x1, int y0, int y1, int iz, VoxelState s) {
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) Set(ix, iy, iz, s);
    }
  }
  // A solid box as a LiDAR leaves it: its inside unknown, the ring of its sides occupied.
  void Box(int x0, int x1, int y0, int y1, int iz) {
    Fill(x0, x1, y0, y1, iz, VoxelState::kOccupied);
    Fill(x0 + 1, x1 - 1, y0 + 1, y1 - 1, iz, VoxelState::kUnknown);
  }
  UnseenPocket Find(const Eigen::Vector3d& p_W, double reach_m = 1.0) const {
    UnseenPocketOptions options;
    options.max_reach_m = reach_m;
    return FindUnseenPocket(geometry_, states_, p_W, options);
  }

  GridGeometry3 geometry_;
  std::vector<std::uint8_t> states_;
};

TEST(UnseenPocketTest, TheInsideOfABoxSeenOnEverySideIsEnclosed) {
  Grid g;
  g.Box(10, 15, 20, 24, 5);  // inside: cells 11..14 x 21..23 = 4 x 3
  const UnseenPocket p = g.Find({1.25, 2.25, 0.55});
  EXPECT_TRUE(p.enclosed) << p.open_because;
  EXPECT_EQ(p.voxels, 12);
  EXPECT_EQ(p.open_because, "");
  EXPECT_NEAR(p.extent_W_m.min().x(), 1.1, 1e-9);
  EXPECT_NEAR(p.extent_W_m.max().x(), 1.5, 1e-9);
  EXPECT_NEAR(p.extent_W_m.min().y(), 2.1, 1e-9);
  EXPECT_NEAR(p.extent_W_m.max().y(), 2.4, 1e-9);
}

TEST(UnseenPocketTest, ABoxWithASideNotSeenIsOpen) {
  Grid g;
  g.Box(10, 15, 20, 24, 5);
  g.Fill(15, 15, 20, 24, 5, VoxelState::kUnknown);  // its +x side never seen, nor its shadow
  g.Fill(16, 39, 18, 26, 5, VoxelState::kUnknown);  // behind it, to the map's end
  const UnseenPocket p = g.Find({1.25, 2.25, 0.55});
  EXPECT_FALSE(p.enclosed);
  EXPECT_EQ(p.open_because, "its unseen pocket reaches farther than 1.00 m");
}

TEST(UnseenPocketTest, AGapInASideLeavesItsRimMostlyOccupied) {
  Grid g;
  g.Box(10, 15, 20, 24, 5);
  g.Set(12, 20, 5, VoxelState::kUnknown);  // not sampled at this height yet
  const UnseenPocket p = g.Find({1.25, 2.25, 0.55});
  EXPECT_TRUE(p.enclosed) << p.open_because;
  EXPECT_EQ(p.voxels, 13);
  EXPECT_EQ(p.rim_free, 1);       // the one seen voxel outside the gap
  EXPECT_EQ(p.rim_occupied, 13);  // the ring's sides (its corners touch no inside voxel)
}

TEST(UnseenPocketTest, ARimMostlySeenFreeIsNoBody) {
  Grid g;
  g.Set(20, 20, 5, VoxelState::kUnknown);  // a gap between rays in the open
  const UnseenPocket gap = g.Find({2.05, 2.05, 0.55});
  EXPECT_FALSE(gap.enclosed);
  EXPECT_EQ(gap.rim_free, 4);
  EXPECT_NE(gap.open_because.find("mostly seen free (0 of 4"), std::string::npos) << gap.open_because;
  // A box with three of its sides seen free and one occupied: 3 of 14 (the share is 0.5).
  g.Box(10, 15, 20, 24, 5);
  g.Fill(10, 10, 20, 24, 5, VoxelState::kFree);
  g.Fill(10, 15, 20, 20, 5, VoxelState::kFree);
  g.Fill(10, 15, 24, 24, 5, VoxelState::kFree);
  const UnseenPocket one_side = g.Find({1.25, 2.25, 0.55});
  EXPECT_FALSE(one_side.enclosed);
  EXPECT_EQ(one_side.rim_occupied, 3);
  EXPECT_EQ(one_side.rim_free, 11);
}

TEST(UnseenPocketTest, ADiagonalFaceOfCornerTouchingVoxelsStillCloses) {
  // A box turned 45 degrees: its faces rasterise to voxels touching at corners only.
  Grid g;
  g.Fill(0, 39, 0, 39, 5, VoxelState::kFree);
  const int cx = 20, cy = 20, r = 4;
  for (int ix = cx - r - 1; ix <= cx + r + 1; ++ix) {
    for (int iy = cy - r - 1; iy <= cy + r + 1; ++iy) {
      const int d = std::abs(ix - cx) + std::abs(iy - cy);
      if (d == r) g.Set(ix, iy, 5, VoxelState::kOccupied);
      if (d < r) g.Set(ix, iy, 5, VoxelState::kUnknown);
    }
  }
  const UnseenPocket p = g.Find({2.05, 2.05, 0.55});
  EXPECT_TRUE(p.enclosed) << p.open_because;
  EXPECT_EQ(p.voxels, 25);  // |dx| + |dy| < 4: 1 + 3 + 5 + 7 + 5 + 3 + 1
}

TEST(UnseenPocketTest, OnlyTheTargetsLayerCounts) {
  Grid g;
  g.Box(10, 15, 20, 24, 5);
  // The layer above has the box's top unseen and open to the room: still enclosed at 0.55 m.
  g.Fill(10, 15, 20, 24, 6, VoxelState::kUnknown);
  EXPECT_TRUE(g.Find({1.25, 2.25, 0.55}).enclosed);
  // A target one layer up is in the unseen space above the box, which opens onto the room.
  EXPECT_FALSE(g.Find({1.25, 2.25, 0.65}).enclosed);
}

TEST(UnseenPocketTest, AboveATableTopIsNotEnclosed) {
  // The top (layer 7, 0.7-0.8 m) seen from below; the air just above it never seen by a LiDAR
  // lower than the table; the room around seen free.
  Grid g;
  g.Fill(10, 20, 10, 20, 7, VoxelState::kOccupied);
  g.Fill(10, 20, 10, 20, 8, VoxelState::kUnknown);
  const UnseenPocket p = g.Find({1.5, 1.5, 0.85});
  EXPECT_FALSE(p.enclosed);
  EXPECT_NE(p.open_because.find("seen free"), std::string::npos) << p.open_because;
}

TEST(UnseenPocketTest, APocketWiderThanTheReachIsNotEnclosed) {
  Grid g;
  g.Box(5, 30, 5, 30, 5);  // 2.4 m inside: an unseen room, not an obstacle
  const UnseenPocket wide = g.Find({1.75, 1.75, 0.55}, 1.0);
  EXPECT_FALSE(wide.enclosed);
  EXPECT_NE(wide.open_because.find("farther than 1.00 m"), std::string::npos) << wide.open_because;
  EXPECT_TRUE(g.Find({1.75, 1.75, 0.55}, 1.5).enclosed);
}

TEST(UnseenPocketTest, APocketAtTheMapsEdgeIsNotEnclosed) {
  Grid g;
  g.Fill(0, 5, 0, 5, 5, VoxelState::kOccupied);
  g.Fill(0, 4, 0, 4, 5, VoxelState::kUnknown);  // walled on +x and +y only: the map ends there
  const UnseenPocket p = g.Find({0.25, 0.25, 0.55});
  EXPECT_FALSE(p.enclosed);
  EXPECT_EQ(p.open_because, "its unseen pocket reaches the map's edge");
}

TEST(UnseenPocketTest, ASeenVoxelIsNeverAnUnseenPocket) {
  Grid g;
  g.Box(10, 15, 20, 24, 5);
  g.Set(12, 22, 5, VoxelState::kFree);
  EXPECT_EQ(g.Find({1.25, 2.25, 0.55}).open_because, "the target's voxel was seen free");
  g.Set(12, 22, 5, VoxelState::kOccupied);
  EXPECT_EQ(g.Find({1.25, 2.25, 0.55}).open_because, "the target's voxel is occupied");
  EXPECT_EQ(g.Find({5.0, 1.0, 0.5}).open_because, "the target is outside the map");
}

TEST(UnseenPocketTest, BadInputsThrow) {
  Grid g;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(g.Find({nan, 1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(g.Find({1.0, 1.0, 0.5}, 0.0), std::invalid_argument);
  EXPECT_THROW(g.Find({1.0, 1.0, 0.5}, nan), std::invalid_argument);
  const std::vector<std::uint8_t> short_states(10, 0);
  EXPECT_THROW(FindUnseenPocket(g.geometry_, short_states, {1.0, 1.0, 0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace topay
