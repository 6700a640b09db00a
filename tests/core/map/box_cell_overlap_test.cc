#include "core/map/box_cell_overlap.h"

#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/map/polygon_overlap.h"

namespace topay {
namespace {

TEST(CellsOverlappingTest, FacesOnCellBoundariesDoNotCount) {
  // Cells of 0.25 m from 0: (0.5, 1.0) overlaps cells 2 and 3 only.
  CellRange range = CellsOverlapping(0.5, 1.0, 0.0, 0.25, 10);
  EXPECT_EQ(range.begin, 2);
  EXPECT_EQ(range.end, 4);
  range = CellsOverlapping(0.55, 0.6, 0.0, 0.25, 10);  // inside cell 2
  EXPECT_EQ(range.begin, 2);
  EXPECT_EQ(range.end, 3);
  range = CellsOverlapping(-3.0, 0.3, 0.0, 0.25, 10);  // clipped below
  EXPECT_EQ(range.begin, 0);
  EXPECT_EQ(range.end, 2);
  range = CellsOverlapping(3.0, 4.0, 0.0, 0.25, 10);  // beyond the grid (2.5 m long)
  EXPECT_TRUE(range.empty());
}

TEST(FootprintCellOverlapTest, AgreesWithPolygonClipping) {
  Rng rng(17);
  int overlaps = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    OrientedBox box;
    box.center_W_m = {rng.Uniform(-1, 1), rng.Uniform(-1, 1), 0.0};
    box.size_m = {rng.Uniform(0.01, 1.0), rng.Uniform(0.01, 1.0), 1.0};
    box.yaw_rad = rng.Uniform(-std::numbers::pi, std::numbers::pi);
    const double cell = rng.Uniform(0.05, 0.3);
    const Eigen::Vector2d center(rng.Uniform(-1.5, 1.5), rng.Uniform(-1.5, 1.5));
    const FootprintCellOverlap test(box, cell);
    const double area = testing::FootprintSquareOverlapArea(
        box, center.array() - 0.5 * cell, center.array() + 0.5 * cell);
    ASSERT_EQ(test.Overlaps(center), area > 1e-12) << "trial " << trial << " area " << area;
    overlaps += area > 1e-12;
  }
  EXPECT_GT(overlaps, 1000);
  EXPECT_LT(overlaps, 19000);
}

TEST(ValidateBoxTest, RejectsNonFiniteAndNegative) {
  OrientedBox box;
  EXPECT_NO_THROW(ValidateBox(box, "here"));
  box.size_m.x() = -0.1;
  EXPECT_THROW(ValidateBox(box, "here"), std::invalid_argument);
  box.size_m.x() = 0.1;
  box.yaw_rad = std::nan("");
  EXPECT_THROW(ValidateBox(box, "here"), std::invalid_argument);
}

}  // namespace
}  // namespace topay
