#include "core/map/box_distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <stop_token>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

GridGeometry3 Grid(double resolution_m) {
  return GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.5)), resolution_m);
}

std::vector<OrientedBox> RandomBoxes(Rng* rng, int count, double max_size_m) {
  std::vector<OrientedBox> boxes;
  for (int i = 0; i < count; ++i) {
    OrientedBox box = MakeBox(
        Eigen::Vector3d(rng->Uniform(-2.3, 2.3), rng->Uniform(-2.3, 2.3), rng->Uniform(0.0, 1.6)),
        Eigen::Vector3d(rng->Uniform(0.01, max_size_m), rng->Uniform(0.01, max_size_m),
                        rng->Uniform(0.02, 0.6)));
    box.yaw_rad = rng->Uniform(-3.2, 3.2);
    boxes.push_back(box);
  }
  return boxes;
}

// The table-like scene of the exactness tests: a top, a leg, a floating cube.
std::vector<OrientedBox> TableBoxes() {
  std::vector<OrientedBox> boxes;
  OrientedBox top = MakeBox(Eigen::Vector3d(0.2, 0.1, 0.56), Eigen::Vector3d(1.2, 0.8, 0.05));
  top.yaw_rad = 0.4;
  boxes.push_back(top);
  boxes.push_back(MakeBox(Eigen::Vector3d(-0.8, 0.9, 0.27), Eigen::Vector3d(0.05, 0.05, 0.54)));
  OrientedBox cube = MakeBox(Eigen::Vector3d(-1.0, -1.0, 1.0), Eigen::Vector3d(0.3, 0.3, 0.3));
  cube.yaw_rad = -0.9;
  boxes.push_back(cube);
  return boxes;
}

double ExactDistance(const std::vector<OrientedBox>& boxes, const Eigen::Vector3d& p_W) {
  double d = std::numeric_limits<double>::infinity();
  for (const OrientedBox& box : boxes) d = std::min(d, SignedDistanceToBox(box, p_W));
  return d;
}

// The block-wise, bucketed build gives the values of a loop over every box and cell (to float
// round-off), from one box to dense clutter, with two caps and boxes crossing the grid's edge.
TEST(BoxDistanceFieldTest, EqualsTheBruteForceValuesOnRandomScenes) {
  Rng rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    const int count = trial < 2 ? 1 + trial : (trial < 4 ? 40 : 300);
    const double cap_m = trial % 2 == 0 ? 0.3 : 1.0;
    const std::vector<OrientedBox> boxes = RandomBoxes(&rng, count, trial >= 4 ? 0.1 : 0.8);
    const GridGeometry3 grid = Grid(trial % 2 == 0 ? 0.05 : 0.07);
    BoxDistanceFieldSummary summary;
    const SignedDistanceField3 field = BuildBoxDistanceField(grid, boxes, cap_m, &summary);
    EXPECT_EQ(summary.num_boxes, count);
    EXPECT_FALSE(summary.stopped);
    int differing = 0;
    for (int iz = 0; iz < grid.dims.z(); ++iz) {
      for (int iy = 0; iy < grid.dims.y(); ++iy) {
        for (int ix = 0; ix < grid.dims.x(); ++ix) {
          const double expected =
              std::min(cap_m, ExactDistance(boxes, grid.CellCenter(ix, iy, iz)));
          differing += std::abs(field.CellValue(ix, iy, iz) - expected) > 1e-5;
        }
      }
    }
    EXPECT_EQ(differing, 0) << "trial " << trial << ": " << count << " boxes";
  }
}

// The promise the planner relies on: Distance(p) never exceeds the exact distance by more than
// exactness_margin_m() = sqrt(3) / 2 x the cell size (below the cap), half the EDT field's,
// and the bound is not loose by much.
TEST(BoxDistanceFieldTest, InterpolantExceedsTheExactDistanceByAtMostTheMargin) {
  const GridGeometry3 grid = Grid(0.05);
  const std::vector<OrientedBox> boxes = TableBoxes();
  const double cap_m = 1.0;
  const SignedDistanceField3 field = BuildBoxDistanceField(grid, boxes, cap_m);
  EXPECT_NEAR(field.exactness_margin_m(), 0.5 * std::sqrt(3.0) * 0.05, 1e-12);
  Rng rng(3);
  double worst_excess = -1.0;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d p(rng.Uniform(-1.9, 1.9), rng.Uniform(-1.9, 1.9), rng.Uniform(0.05, 1.4));
    const double exact = ExactDistance(boxes, p);
    if (exact > cap_m - 0.1) continue;
    worst_excess = std::max(worst_excess, field.Distance(p) - exact);
  }
  std::printf("worst excess %.4f m, margin %.4f m\n", worst_excess, field.exactness_margin_m());
  EXPECT_LE(worst_excess, field.exactness_margin_m() + 1e-6);
  EXPECT_GT(worst_excess, 0.25 * field.exactness_margin_m());
}

// Under a table top 4.5 cm above a point, the field reads close to the truth (within the
// margin), where an EDT field of 5 cm cells could read 0.
TEST(BoxDistanceFieldTest, ReadsTheGapUnderATableTop) {
  const std::vector<OrientedBox> boxes = TableBoxes();
  const SignedDistanceField3 field = BuildBoxDistanceField(Grid(0.05), boxes, 1.0);
  const Eigen::Vector3d p(0.2, 0.1, 0.535 - 0.045);  // the top's bottom face is at 0.535 m
  EXPECT_NEAR(ExactDistance(boxes, p), 0.045, 1e-9);
  EXPECT_LE(field.Distance(p), 0.045 + field.exactness_margin_m());
  EXPECT_GE(field.Distance(p), 0.045 - field.exactness_margin_m());
}

TEST(BoxDistanceFieldTest, NoBoxGivesTheCapEverywhere) {
  const SignedDistanceField3 field = BuildBoxDistanceField(Grid(0.1), {}, 0.6);
  for (float v : field.values()) ASSERT_EQ(v, 0.6f);
}

// A stop ends the build early and leaves the field conservative (unfilled cells occupied).
TEST(BoxDistanceFieldTest, AStoppedBuildSaysSoAndIsConservative) {
  std::stop_source stop;
  stop.request_stop();
  BoxDistanceFieldSummary summary;
  const SignedDistanceField3 field =
      BuildBoxDistanceField(Grid(0.1), TableBoxes(), 0.7, &summary, stop.get_token());
  EXPECT_TRUE(summary.stopped);
  for (float v : field.values()) ASSERT_EQ(v, -0.7f);
}

TEST(BoxDistanceFieldTest, BadInputIsRefusedNamingIt) {
  EXPECT_THROW(BuildBoxDistanceField(Grid(0.1), TableBoxes(), 0.0), std::invalid_argument);
  EXPECT_THROW(BuildBoxDistanceField(Grid(0.1), TableBoxes(),
                                     std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  std::vector<OrientedBox> boxes = TableBoxes();
  boxes[2].size_m.x() = std::numeric_limits<double>::quiet_NaN();
  try {
    BuildBoxDistanceField(Grid(0.1), boxes, 0.5);
    FAIL() << "a NaN box was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("box 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay
