#include "core/map/occupancy_grid2.h"
#include "tests/common/make_box.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/map/polygon_overlap.h"

namespace topay {
namespace {

const GridGeometry2 kRoom2 = GridGeometry2::FromBounds(
    Eigen::AlignedBox2d(Eigen::Vector2d(-2, -2), Eigen::Vector2d(2, 2)), 0.1);

TEST(OccupancyGrid2Test, FootprintMatchesExactPolygonOverlap) {
  Rng rng(5);
  int occupied_checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    OccupancyGrid2 grid(kRoom2);
    const OrientedBox box = MakeBox({rng.Uniform(-1, 1), rng.Uniform(-1, 1), 3.0},
                                    {rng.Uniform(0.03, 1.5), rng.Uniform(0.03, 1.5), 0.1},
                                    rng.Uniform(-std::numbers::pi, std::numbers::pi));
    grid.AddFootprint(box);  // height irrelevant here
    for (int iy = 0; iy < kRoom2.dims.y(); ++iy)
      for (int ix = 0; ix < kRoom2.dims.x(); ++ix) {
        const Eigen::Vector2d center = kRoom2.CellCenter(ix, iy);
        const double area = testing::FootprintSquareOverlapArea(
            box, center.array() - 0.05, center.array() + 0.05);
        ASSERT_EQ(grid.IsOccupied(ix, iy), area > 1e-12) << trial << " " << ix << " " << iy;
        occupied_checked += area > 1e-12;
      }
  }
  EXPECT_GT(occupied_checked, 1000);
}

TEST(OccupancyGrid2Test, BaseBandKeepsLegsAndDropsTableTop) {
  const HeightBand band{0.0, 0.155};
  OccupancyGrid2 grid(kRoom2);
  const OrientedBox top = MakeBox({0, 0, 0.725}, {1.0, 1.0, 0.05});
  const OrientedBox leg = MakeBox({0.45, 0.45, 0.35}, {0.05, 0.05, 0.7});
  const OrientedBox floor_mat = MakeBox({-1, -1, 0.005}, {0.3, 0.3, 0.01});
  const OrientedBox touching_band_top = MakeBox({1, -1, 0.655}, {0.3, 0.3, 1.0});  // [0.155, ..]
  EXPECT_FALSE(grid.AddBoxInBand(top, band));
  EXPECT_EQ(grid.CountOccupied(), 0);
  EXPECT_TRUE(grid.AddBoxInBand(leg, band));
  const Eigen::Vector2i leg_cell = kRoom2.CellOf(leg.center_W_m.head<2>());
  EXPECT_TRUE(grid.IsOccupied(leg_cell.x(), leg_cell.y()));
  EXPECT_TRUE(grid.AddBoxInBand(floor_mat, band));
  EXPECT_FALSE(grid.AddBoxInBand(touching_band_top, band));
  // Leg 0.05 m on a 0.1 m grid: 1, 2 or 4 cells; the mat 0.3 x 0.3 m: 9 to 16 cells.
  EXPECT_GE(grid.CountOccupied(), 1 + 9);
  EXPECT_LE(grid.CountOccupied(), 4 + 16);
  const Eigen::Vector2i top_cell = kRoom2.CellOf(Eigen::Vector2d(0, 0));
  EXPECT_FALSE(grid.IsOccupied(top_cell.x(), top_cell.y()));
}

TEST(OccupancyGrid2Test, ProjectBandUsesLayersOverlappingTheBand) {
  const GridGeometry3 geometry = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.6)), 0.1);
  OccupancyGrid3 grid3(geometry);
  grid3.AddBox(MakeBox({0, 0, 0.725}, {1.0, 1.0, 0.05}));         // top: layer 7 only
  grid3.AddBox(MakeBox({0.45, 0.45, 0.35}, {0.05, 0.05, 0.7}));   // leg: layers 0..6
  grid3.AddBox(MakeBox({-1.5, 1.5, 0.18}, {0.2, 0.2, 0.04}));     // [0.16, 0.2]: layer 1 only
  const OccupancyGrid2 base = OccupancyGrid2::ProjectBand(grid3, HeightBand{0.0, 0.155});
  const Eigen::Vector2i leg = base.geometry().CellOf(Eigen::Vector2d(0.45, 0.45));
  const Eigen::Vector2i top = base.geometry().CellOf(Eigen::Vector2d(0.0, 0.0));
  const Eigen::Vector2i shelf = base.geometry().CellOf(Eigen::Vector2d(-1.5, 1.5));
  EXPECT_TRUE(base.IsOccupied(leg.x(), leg.y()));
  EXPECT_FALSE(base.IsOccupied(top.x(), top.y()));
  // Layer 1 spans [0.1, 0.2] and overlaps the band, so at voxel level the box above the band
  // counts: this is why the scene builder projects boxes directly (AddBoxInBand).
  EXPECT_TRUE(base.IsOccupied(shelf.x(), shelf.y()));
  OccupancyGrid2 direct(base.geometry());
  EXPECT_FALSE(direct.AddBoxInBand(MakeBox({-1.5, 1.5, 0.18}, {0.2, 0.2, 0.04}),
                                   HeightBand{0.0, 0.155}));
  // Band [0.7, 0.8] holds the top (layer 7) and the leg (layer 6 spans [0.6, 0.7]: touches).
  const OccupancyGrid2 high = OccupancyGrid2::ProjectBand(grid3, HeightBand{0.7, 0.8});
  EXPECT_TRUE(high.IsOccupied(top.x(), top.y()));
  EXPECT_TRUE(high.IsOccupied(leg.x(), leg.y()));  // the top covers the leg's cell too
  EXPECT_GE(high.CountOccupied(), 100);  // 1 m x 1 m of 0.1 m cells, plus rounding at faces
  EXPECT_LE(high.CountOccupied(), 144);
}

TEST(OccupancyGrid2Test, MarkPointAndBadInput) {
  OccupancyGrid2 grid(kRoom2);
  EXPECT_TRUE(grid.MarkPoint(Eigen::Vector2d(-1.95, 1.95)));
  EXPECT_TRUE(grid.IsOccupied(0, 39));
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector2d(2.0, 0.0)));
  EXPECT_FALSE(grid.MarkPoint(Eigen::Vector2d(std::nan(""), 0.0)));
  EXPECT_EQ(grid.num_points_outside(), 2);
  grid.ClearAll();
  EXPECT_EQ(grid.CountOccupied(), 0);
  EXPECT_EQ(grid.num_points_outside(), 0);
  const OrientedBox box = MakeBox({0, 0, 0.1}, {0.2, 0.2, 0.2});
  EXPECT_THROW(grid.AddBoxInBand(box, HeightBand{0.2, 0.1}), std::invalid_argument);
  EXPECT_THROW(grid.AddBoxInBand(box, HeightBand{std::nan(""), 0.1}), std::invalid_argument);
  EXPECT_THROW(grid.AddFootprint(MakeBox({0, 0, 0}, {std::nan(""), 1, 1})),
               std::invalid_argument);
  const OccupancyGrid3 grid3(GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.1));
  EXPECT_THROW(OccupancyGrid2::ProjectBand(grid3, HeightBand{0.5, 0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace topay
