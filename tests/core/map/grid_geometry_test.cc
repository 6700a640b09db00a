#include "core/map/grid_geometry.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(GridGeometry3Test, BenchmarkRoomHasWholeNumberOfCells) {
  const Eigen::AlignedBox3d room(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6));
  const GridGeometry3 coarse = GridGeometry3::FromBounds(room, 0.1);
  EXPECT_EQ(coarse.dims, Eigen::Vector3i(200, 200, 16));
  const GridGeometry3 fine = GridGeometry3::FromBounds(room, 0.05);
  EXPECT_EQ(fine.dims, Eigen::Vector3i(400, 400, 32));
  EXPECT_EQ(fine.NumCells(), 400 * 400 * 32);
  EXPECT_TRUE(fine.Bounds().isApprox(room));
}

TEST(GridGeometry3Test, PartialCellIsCoveredAndTinyAxisGetsTwoCells) {
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.05, 0.3, 0.01));
  const GridGeometry3 grid = GridGeometry3::FromBounds(bounds, 0.1);
  EXPECT_EQ(grid.dims, Eigen::Vector3i(11, 3, 2));
  EXPECT_TRUE(grid.Bounds().contains(bounds));
}

TEST(GridGeometry3Test, WorldToCellAndBack) {
  const GridGeometry3 grid = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-1, -2, 0.5), Eigen::Vector3d(1, 2, 1.5)), 0.25);
  for (int iz = 0; iz < grid.dims.z(); ++iz)
    for (int iy = 0; iy < grid.dims.y(); ++iy)
      for (int ix = 0; ix < grid.dims.x(); ++ix) {
        const Eigen::Vector3d center = grid.CellCenter(ix, iy, iz);
        EXPECT_TRUE(grid.Contains(center));
        EXPECT_EQ(grid.CellOf(center), Eigen::Vector3i(ix, iy, iz));
        EXPECT_EQ(grid.CellAt(grid.Index(ix, iy, iz)), Eigen::Vector3i(ix, iy, iz));
      }
  EXPECT_EQ(grid.Index(1, 2, 3), (3 * grid.dims.y() + 2) * grid.dims.x() + 1);
  EXPECT_FALSE(grid.Contains(Eigen::Vector3d(1.0, 0, 1)));  // max face is excluded
  EXPECT_TRUE(grid.Contains(Eigen::Vector3d(-1.0, -2.0, 0.5)));
  EXPECT_FALSE(grid.Contains(Eigen::Vector3d(0, std::nan(""), 1)));
}

TEST(GridGeometry3Test, RejectsBadInput) {
  const Eigen::AlignedBox3d good(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  EXPECT_THROW(GridGeometry3::FromBounds(good, 0.0), std::invalid_argument);
  EXPECT_THROW(GridGeometry3::FromBounds(good, -0.1), std::invalid_argument);
  EXPECT_THROW(GridGeometry3::FromBounds(good, std::nan("")), std::invalid_argument);
  EXPECT_THROW(GridGeometry3::FromBounds(Eigen::AlignedBox3d(), 0.1), std::invalid_argument);
  const Eigen::AlignedBox3d flat(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  EXPECT_THROW(GridGeometry3::FromBounds(flat, 0.1), std::invalid_argument);
  const Eigen::AlignedBox3d with_nan(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, std::nan(""), 1));
  EXPECT_THROW(GridGeometry3::FromBounds(with_nan, 0.1), std::invalid_argument);
  EXPECT_THROW(GridGeometry3::FromBounds(good, 1e-4), std::invalid_argument);  // 1e12 cells
  try {
    GridGeometry3::FromBounds(good, 0.0);
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("resolution_m"), std::string::npos);
  }
}

TEST(GridGeometry2Test, FootprintAndFromBounds) {
  const GridGeometry3 grid3 = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6)), 0.1);
  const GridGeometry2 grid2 = GridGeometry2::FootprintOf(grid3);
  EXPECT_EQ(grid2.dims, Eigen::Vector2i(200, 200));
  EXPECT_EQ(grid2.origin_W_m, Eigen::Vector2d(-10, -10));
  EXPECT_EQ(grid2.CellOf(grid2.CellCenter(17, 3)), Eigen::Vector2i(17, 3));
  EXPECT_EQ(grid2.Index(17, 3), 3 * 200 + 17);
  const GridGeometry2 direct = GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, 10)), 0.1);
  EXPECT_EQ(direct.dims, grid2.dims);
  EXPECT_THROW(GridGeometry2::FromBounds(Eigen::AlignedBox2d(), 0.1), std::invalid_argument);
}

TEST(GridGeometryTest, ValidateRejectsHandMadeBadGeometries) {
  GridGeometry3 grid3 = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 0.1);
  EXPECT_NO_THROW(grid3.Validate("test"));
  grid3.dims.z() = 1;
  EXPECT_THROW(grid3.Validate("test"), std::invalid_argument);
  grid3.dims.z() = 10;
  grid3.resolution_m = 0.0;
  EXPECT_THROW(grid3.Validate("test"), std::invalid_argument);
  GridGeometry2 grid2;  // default: no cells
  EXPECT_THROW(grid2.Validate("test"), std::invalid_argument);
  grid2.dims = Eigen::Vector2i(3, 3);
  grid2.origin_W_m.x() = std::nan("");
  EXPECT_THROW(grid2.Validate("test"), std::invalid_argument);
}

TEST(GridGeometry3Test, SameGeometryComparesOriginResolutionAndDims) {
  const GridGeometry3 g =
      GridGeometry3::FromBounds(Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 0.5)), 0.05);
  EXPECT_TRUE(SameGeometry(g, g));
  GridGeometry3 other = g;
  other.origin_W_m.x() += 0.05;
  EXPECT_FALSE(SameGeometry(g, other));
  other = g;
  other.resolution_m = 0.1;
  EXPECT_FALSE(SameGeometry(g, other));
  other = g;
  other.dims.z() += 1;
  EXPECT_FALSE(SameGeometry(g, other));
}

}  // namespace
}  // namespace topay
