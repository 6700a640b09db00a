#include "core/map/footprint_distance_field.h"

#include <cmath>
#include <stdexcept>
#include <stop_token>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/map/occupancy_grid2.h"
#include "core/map/signed_distance_field2.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

GridGeometry2 Grid(double resolution_m) {
  return GridGeometry2::FromBounds(Eigen::AlignedBox2d(Eigen::Vector2d(-3, -3), Eigen::Vector2d(3, 3)),
                                   resolution_m);
}

std::vector<OrientedBox> Boxes() {
  std::vector<OrientedBox> boxes;
  OrientedBox a = MakeBox(Eigen::Vector3d(-1.0, 0.3, 0.5), Eigen::Vector3d(0.8, 0.4, 1.0));
  a.yaw_rad = 0.6;
  boxes.push_back(a);
  OrientedBox b = MakeBox(Eigen::Vector3d(1.2, -0.5, 0.1), Eigen::Vector3d(0.3, 1.1, 0.2));
  b.yaw_rad = -1.1;
  boxes.push_back(b);
  // A table top above the band: must not count.
  boxes.push_back(MakeBox(Eigen::Vector3d(0.0, 1.5, 0.8), Eigen::Vector3d(1.0, 1.0, 0.05)));
  return boxes;
}

double ExactDistance(const std::vector<OrientedBox>& boxes, const HeightBand& band,
                     const Eigen::Vector2d& p_W) {
  double d = std::numeric_limits<double>::infinity();
  for (const OrientedBox& box : boxes) {
    const double bottom = box.center_W_m.z() - 0.5 * box.size_m.z();
    const double top = box.center_W_m.z() + 0.5 * box.size_m.z();
    if (bottom < band.z_max_m && top > band.z_min_m) d = std::min(d, SignedDistanceToFootprint(box, p_W));
  }
  return d;
}

// The old build, kept as the reference: every box lowers every cell within cap_m of its
// footprint's bounds (one loop over boxes, one over their cells).
std::vector<float> BruteForceValues(const GridGeometry2& g, const std::vector<OrientedBox>& boxes,
                                    const HeightBand& band, double cap_m) {
  std::vector<float> values(g.NumCells(), static_cast<float>(cap_m));
  for (const OrientedBox& box : boxes) {
    const double bottom = box.center_W_m.z() - 0.5 * box.size_m.z();
    const double top = box.center_W_m.z() + 0.5 * box.size_m.z();
    if (!(bottom < band.z_max_m && top > band.z_min_m)) continue;
    const double c = std::cos(box.yaw_rad), s = std::sin(box.yaw_rad);
    const double hx = 0.5 * box.size_m.x(), hy = 0.5 * box.size_m.y();
    for (int iy = 0; iy < g.dims.y(); ++iy) {
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const Eigen::Vector2d p = g.CellCenter(ix, iy);
        const double dx = p.x() - box.center_W_m.x(), dy = p.y() - box.center_W_m.y();
        const double qx = std::abs(c * dx + s * dy) - hx;
        const double qy = std::abs(-s * dx + c * dy) - hy;
        const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
        const double d = std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
        float& v = values[g.Index(ix, iy)];
        v = std::min(v, static_cast<float>(d));
      }
    }
  }
  return values;
}

// The bucketed, block-wise build gives the very values of the brute-force build (bit for
// bit), on random scenes from sparse to dense clutter, small and large caps, boxes crossing
// the grid's edge and boxes out of the band.
TEST(FootprintDistanceFieldTest, EqualsTheBruteForceBuildOnRandomScenes) {
  Rng rng(11);
  for (int trial = 0; trial < 12; ++trial) {
    const int count = trial < 4 ? 1 + trial : (trial < 8 ? 60 : 600);
    const double resolution_m = trial % 2 == 0 ? 0.05 : 0.037;
    const double cap_m = trial % 3 == 0 ? 0.3 : 1.0;
    std::vector<OrientedBox> boxes;
    for (int i = 0; i < count; ++i) {
      const double size = trial >= 8 ? 0.06 : 0.8;
      OrientedBox box = MakeBox(
          Eigen::Vector3d(rng.Uniform(-3.5, 3.5), rng.Uniform(-3.5, 3.5), rng.Uniform(0.0, 1.0)),
          Eigen::Vector3d(rng.Uniform(0.01, size), rng.Uniform(0.01, size), rng.Uniform(0.05, 0.6)));
      box.yaw_rad = rng.Uniform(-3.2, 3.2);
      boxes.push_back(box);
    }
    const GridGeometry2 grid = Grid(resolution_m);
    const HeightBand band{0.0, 0.4};
    FootprintDistanceFieldSummary summary;
    const SignedDistanceField2 field =
        BuildFootprintDistanceField(grid, boxes, band, cap_m, &summary);
    const std::vector<float> expected = BruteForceValues(grid, boxes, band, cap_m);
    ASSERT_EQ(field.values().size(), expected.size());
    int differing = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) differing += field.values()[i] != expected[i];
    EXPECT_EQ(differing, 0) << "trial " << trial << ": " << count << " boxes";
    EXPECT_FALSE(summary.stopped);
  }
}

// A stop ends the build early and leaves the field conservative (unfilled cells occupied).
TEST(FootprintDistanceFieldTest, AStoppedBuildSaysSoAndIsConservative) {
  std::stop_source stop;
  stop.request_stop();
  FootprintDistanceFieldSummary summary;
  const SignedDistanceField2 field = BuildFootprintDistanceField(
      Grid(0.05), Boxes(), HeightBand{0.0, 0.5}, 0.7, &summary, stop.get_token());
  EXPECT_TRUE(summary.stopped);
  for (float v : field.values()) ASSERT_EQ(v, -0.7f);
}

TEST(FootprintDistanceFieldTest, CellValuesAreTheCappedExactDistances) {
  const GridGeometry2 grid = Grid(0.05);
  const HeightBand band{0.0, 0.5};
  const std::vector<OrientedBox> boxes = Boxes();
  FootprintDistanceFieldSummary summary;
  const SignedDistanceField2 field = BuildFootprintDistanceField(grid, boxes, band, 0.7, &summary);
  EXPECT_EQ(summary.num_boxes_in_band, 2);
  EXPECT_GT(summary.num_distance_evaluations, 0);
  EXPECT_NEAR(field.exactness_margin_m(), 0.05 / std::sqrt(2.0), 1e-12);
  for (int iy = 0; iy < grid.dims.y(); ++iy) {
    for (int ix = 0; ix < grid.dims.x(); ++ix) {
      const double expected = std::min(0.7, ExactDistance(boxes, band, grid.CellCenter(ix, iy)));
      ASSERT_NEAR(field.CellValue(ix, iy), expected, 1e-5) << "cell " << ix << ", " << iy;
    }
  }
}

// The promise the planner relies on: Distance(p) never exceeds the exact distance by more than
// exactness_margin_m() (below the cap), and the bound is nearly attained (not loose).
TEST(FootprintDistanceFieldTest, InterpolantExceedsTheExactDistanceByAtMostTheMargin) {
  const GridGeometry2 grid = Grid(0.05);
  const HeightBand band{0.0, 0.5};
  const std::vector<OrientedBox> boxes = Boxes();
  const double cap_m = 0.7;
  const SignedDistanceField2 field = BuildFootprintDistanceField(grid, boxes, band, cap_m);
  Rng rng(7);
  double worst_excess = -1.0;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector2d p(rng.Uniform(-2.9, 2.9), rng.Uniform(-2.9, 2.9));
    const double exact = ExactDistance(boxes, band, p);
    if (exact > cap_m - 0.1) continue;
    worst_excess = std::max(worst_excess, field.Distance(p) - exact);
  }
  EXPECT_LE(worst_excess, field.exactness_margin_m() + 1e-6);
  EXPECT_GT(worst_excess, 0.25 * field.exactness_margin_m());
  // An EDT field of the same band needs twice the margin.
  OccupancyGrid2 occupancy(grid);
  for (const OrientedBox& box : boxes) occupancy.AddBoxInBand(box, band);
  EXPECT_NEAR(SignedDistanceField2::Build(occupancy).exactness_margin_m(), std::sqrt(2.0) * 0.05,
              1e-12);
}

TEST(FootprintDistanceFieldTest, EmptyBandGivesTheCapEverywhere) {
  const SignedDistanceField2 field =
      BuildFootprintDistanceField(Grid(0.1), Boxes(), HeightBand{1.0, 1.5}, 0.9);
  for (float v : field.values()) ASSERT_EQ(v, 0.9f);
}

TEST(FootprintDistanceFieldTest, BadInputIsRejectedWithAReason) {
  std::vector<OrientedBox> boxes = Boxes();
  EXPECT_THROW(BuildFootprintDistanceField(Grid(0.1), boxes, HeightBand{0.0, 0.5}, 0.0),
               std::invalid_argument);
  boxes[1].size_m.x() = std::nan("");
  try {
    BuildFootprintDistanceField(Grid(0.1), boxes, HeightBand{0.0, 0.5}, 1.0);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("box 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay
