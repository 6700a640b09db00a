#include "core/map/occupancy_grid3.h"
#include "tests/common/make_box.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/map/polygon_overlap.h"

namespace topay {
namespace {

TEST(OccupancyGrid3Test, StartsFree) {
  const OccupancyGrid3 grid(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.1));
  EXPECT_EQ(grid.CountOccupied(), 0);
  EXPECT_EQ(grid.cells().size(), 1000u);
}

TEST(OccupancyGrid3Test, AxisAlignedBoxMarksExactlyTheCellsItOverlaps) {
  // Dyadic numbers: every coordinate is exact, so faces lie exactly on cell boundaries and the
  // cells merely touched by a face must stay free.
  OccupancyGrid3 grid(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.125));
  grid.AddBox(MakeBox({0.5, 0.25, 0.375}, {0.5, 0.25, 0.25}));  // x [.25,.75] y [.125,.375] z [.25,.5]
  for (int iz = 0; iz < 8; ++iz)
    for (int iy = 0; iy < 8; ++iy)
      for (int ix = 0; ix < 8; ++ix) {
        const bool inside = ix >= 2 && ix <= 5 && iy >= 1 && iy <= 2 && iz >= 2 && iz <= 3;
        EXPECT_EQ(grid.IsOccupied(ix, iy, iz), inside) << ix << " " << iy << " " << iz;
      }
  EXPECT_EQ(grid.CountOccupied(), 4 * 2 * 2);
}

TEST(OccupancyGrid3Test, RotatedBoxesMatchExactFootprintOverlap) {
  // Every cell near random rotated boxes: occupied iff the cell's z interval overlaps the box's
  // and the footprint polygon clipped to the cell's square has positive area.
  const double res = 0.1;
  const GridGeometry3 geometry = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1)), res);
  Rng rng(7);
  int occupied_checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    OccupancyGrid3 grid(geometry);
    const OrientedBox box = MakeBox(
        {rng.Uniform(-0.5, 0.5), rng.Uniform(-0.5, 0.5), rng.Uniform(0.2, 0.8)},
        {rng.Uniform(0.03, 1.0), rng.Uniform(0.03, 1.0), rng.Uniform(0.03, 0.5)},
        rng.Uniform(-std::numbers::pi, std::numbers::pi));
    grid.AddBox(box);
    const double z_low = box.center_W_m.z() - 0.5 * box.size_m.z();
    const double z_high = box.center_W_m.z() + 0.5 * box.size_m.z();
    for (int iz = 0; iz < geometry.dims.z(); ++iz)
      for (int iy = 0; iy < geometry.dims.y(); ++iy)
        for (int ix = 0; ix < geometry.dims.x(); ++ix) {
          const Eigen::Vector3d center = geometry.CellCenter(ix, iy, iz);
          const Eigen::Vector3d lo = center.array() - 0.5 * res;
          const Eigen::Vector3d hi = center.array() + 0.5 * res;
          const bool z_overlap = lo.z() < z_high && hi.z() > z_low;
          const double area =
              testing::FootprintSquareOverlapArea(box, lo.head<2>(), hi.head<2>());
          const bool expected = z_overlap && area > 1e-12;
          ASSERT_EQ(grid.IsOccupied(ix, iy, iz), expected)
              << "trial " << trial << " cell " << ix << " " << iy << " " << iz << " area "
              << area;
          occupied_checked += expected;
        }
  }
  EXPECT_GT(occupied_checked, 1000);
}

TEST(OccupancyGrid3Test, ThinTableTopAndLegsAreNeverLost) {
  // A 0.05 m table top whose z extent [0.56, 0.61] holds no cell centre at 0.1 m (centres at
  // 0.55 and 0.65), and 0.05 m legs rotated arbitrarily: sampling cell centres would miss
  // them; conservative rasterisation keeps them.
  const GridGeometry3 geometry = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.6)), 0.1);
  OccupancyGrid3 grid(geometry);
  const OrientedBox top = MakeBox({0.03, -0.02, 0.585}, {1.0, 0.8, 0.05}, 0.3);
  grid.AddBox(top);
  // Layers 5 ([0.5, 0.6]) and 6 ([0.6, 0.7]) both hold the top; layers 4 and 7 do not.
  const Eigen::Vector3i c = geometry.CellOf(top.center_W_m);
  EXPECT_TRUE(grid.IsOccupied(c.x(), c.y(), 5));
  EXPECT_TRUE(grid.IsOccupied(c.x(), c.y(), 6));
  EXPECT_FALSE(grid.IsOccupied(c.x(), c.y(), 4));
  EXPECT_FALSE(grid.IsOccupied(c.x(), c.y(), 7));
  // Each layer holds at least the footprint's area in cells.
  const std::int64_t per_layer = grid.CountOccupied() / 2;
  EXPECT_EQ(grid.CountOccupied(), 2 * per_layer);
  EXPECT_GE(per_layer, static_cast<std::int64_t>(1.0 * 0.8 / 0.01));
  Rng rng(3);
  for (int leg = 0; leg < 50; ++leg) {
    const OrientedBox box = MakeBox({rng.Uniform(-1.5, 1.5), rng.Uniform(-1.5, 1.5), 0.28},
                                    {0.05, 0.05, 0.56}, rng.Uniform(-3.0, 3.0));
    OccupancyGrid3 leg_grid(geometry);
    leg_grid.AddBox(box);
    const Eigen::Vector3i cell = geometry.CellOf(box.center_W_m);
    for (int iz = 0; iz <= 5; ++iz) EXPECT_TRUE(leg_grid.IsOccupied(cell.x(), cell.y(), iz));
    EXPECT_FALSE(leg_grid.IsOccupied(cell.x(), cell.y(), 6));
    // A 0.05 m square covers at most 2 x 2 cells of 0.1 m in each layer.
    EXPECT_LE(leg_grid.CountOccupied(), 4 * 6);
    EXPECT_GE(leg_grid.CountOccupied(), 6);
  }
}

TEST(OccupancyGrid3Test, BoxesPartlyOutsideAreClippedAndOutsideOnesIgnored) {
  OccupancyGrid3 grid(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.125));
  grid.AddBox(MakeBox({5, 5, 5}, {1, 1, 1}));
  EXPECT_EQ(grid.CountOccupied(), 0);
  grid.AddBox(MakeBox({1.0, 0.5, 0.5}, {0.5, 0.25, 0.25}));  // x [.75, 1.25]: 2 cells inside
  EXPECT_EQ(grid.CountOccupied(), 2 * 2 * 2);
  EXPECT_TRUE(grid.IsOccupied(7, 3, 3));
}

TEST(OccupancyGrid3Test, MarkPointCountsOutsidePointsAndClearAllResets) {
  OccupancyGrid3 grid(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1)), 0.1));
  EXPECT_TRUE(grid.MarkPoint(Eigen::Vector3d(0.05, -0.95, 0.31)));
  EXPECT_TRUE(grid.IsOccupied(10, 0, 3));
  EXPECT_TRUE(grid.MarkPoint(Eigen::Vector3d(0.06, -0.96, 0.32)));  // same cell
  EXPECT_EQ(grid.CountOccupied(), 1);
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector3d(0, 0, 1.0)));   // max face excluded
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector3d(0, 0, -0.01)));
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector3d(std::nan(""), 0, 0.5)));
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector3d(INFINITY, 0, 0.5)));
  EXPECT_EQ(grid.num_points_outside(), 4);
  EXPECT_EQ(grid.CountOccupied(), 1);
  grid.ClearAll();
  EXPECT_EQ(grid.CountOccupied(), 0);
  EXPECT_EQ(grid.num_points_outside(), 0);
}

TEST(OccupancyGrid3Test, RejectsBadBoxes) {
  OccupancyGrid3 grid(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.1));
  EXPECT_THROW(grid.AddBox(MakeBox({std::nan(""), 0, 0}, {1, 1, 1})), std::invalid_argument);
  EXPECT_THROW(grid.AddBox(MakeBox({0, 0, 0}, {1, -1, 1})), std::invalid_argument);
  EXPECT_THROW(grid.AddBox(MakeBox({0, 0, 0}, {1, 1, 1}, INFINITY)), std::invalid_argument);
  EXPECT_EQ(grid.CountOccupied(), 0);
}

TEST(OccupancyGrid3Test, RejectsInvalidGeometry) {
  GridGeometry3 geometry;  // default: no cells
  EXPECT_THROW(OccupancyGrid3 grid(geometry), std::invalid_argument);
}

}  // namespace
}  // namespace topay
