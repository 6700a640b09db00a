#include "core/map/signed_distance_field2.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/common/make_box.h"
#include "tests/core/map/random_room.h"

namespace topay {
namespace {

const HeightBand kBaseBand{0.0, 0.155};

OccupancyGrid2 BaseOccupancy(const Scene& scene, double resolution_m) {
  const Eigen::AlignedBox3d& b = scene.bounds_W_m;
  OccupancyGrid2 grid(GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(b.min().head<2>(), b.max().head<2>()), resolution_m));
  for (const OrientedBox& box : scene.boxes) grid.AddBoxInBand(box, kBaseBand);
  return grid;
}

std::vector<OrientedBox> BoxesInBand(const Scene& scene) {
  std::vector<OrientedBox> in_band;
  for (const OrientedBox& box : scene.boxes) {
    const double half = 0.5 * box.size_m.z();
    if (box.center_W_m.z() - half < kBaseBand.z_max_m && box.center_W_m.z() + half > 0.0) {
      in_band.push_back(box);
    }
  }
  return in_band;
}

TEST(SignedDistanceField2Test, StripAlignedWithCellFacesIsExact) {
  // Cells with 3 <= iy < 17 occupied: the strip's lower face is the plane y = -0.7.
  OccupancyGrid2 grid(GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 1)), 0.1));
  for (int iy = 3; iy < 17; ++iy)
    for (int ix = 0; ix < 20; ++ix) grid.SetOccupied(ix, iy, true);
  for (double inset : {0.0, 0.5}) {
    SignedDistanceFieldOptions options;
    options.zero_level_inset_cells = inset;
    const SignedDistanceField2 field = SignedDistanceField2::Build(grid, options);
    Rng rng(2);
    for (int i = 0; i < 300; ++i) {
      const Eigen::Vector2d p(rng.Uniform(-0.35, 0.35), rng.Uniform(-0.95, -0.35));
      Eigen::Vector2d gradient;
      EXPECT_NEAR(field.DistanceAndGradient(p, &gradient), -0.7 - p.y() + inset * 0.1, 1e-6);
      EXPECT_TRUE(gradient.isApprox(-Eigen::Vector2d::UnitY(), 1e-6)) << gradient.transpose();
    }
  }
}

// The base field against exact 2D distances to the footprints of the boxes in the band, on
// 10,000 random points of a 20 x 20 m room: within one cell.
TEST(SignedDistanceField2Test, WithinOneCellOfExactFootprintDistance) {
  const Scene scene = testing::RandomDisjointRoom(42, 20.0, 160, 0.15);
  const std::vector<OrientedBox> in_band = BoxesInBand(scene);
  ASSERT_GT(in_band.size(), 40u);
  ASSERT_LT(in_band.size(), scene.boxes.size());  // floating boxes and slabs are left out
  for (double res : {0.1, 0.05}) {
    const SignedDistanceField2 field = SignedDistanceField2::Build(BaseOccupancy(scene, res));
    Rng rng(3);
    std::vector<double> errors;
    for (int i = 0; i < 10000; ++i) {
      const Eigen::Vector2d p(rng.Uniform(-10, 10), rng.Uniform(-10, 10));
      errors.push_back(std::abs(field.Distance(p) - testing::ExactSignedDistance2d(in_band, p)));
    }
    std::sort(errors.begin(), errors.end());
    std::cout << "2D resolution " << res << " m: max " << errors.back() << " m, median "
              << errors[errors.size() / 2] << " m\n";
    EXPECT_LE(errors.back(), res);
  }
}

TEST(SignedDistanceField2Test, GradientMatchesFiniteDifferencesInsideAndOutside) {
  const Scene scene = testing::RandomDisjointRoom(6, 6.0, 30, 0.15);
  const SignedDistanceField2 field = SignedDistanceField2::Build(BaseOccupancy(scene, 0.1));
  const GridGeometry2& g = field.geometry();
  Rng rng(8);
  int checked = 0;
  while (checked < 2000) {
    const Eigen::Vector2d p(rng.Uniform(-3.5, 3.5), rng.Uniform(-3.5, 3.5));
    const Eigen::Vector2d u = (p - g.origin_W_m) / g.resolution_m - Eigen::Vector2d::Constant(0.5);
    const Eigen::Vector2d fraction = u - u.array().floor().matrix();
    if ((fraction.array() < 0.01).any() || (fraction.array() > 0.99).any()) continue;
    Eigen::Vector2d gradient;
    field.DistanceAndGradient(p, &gradient);
    const double h = 1e-6;
    for (int a = 0; a < 2; ++a) {
      const Eigen::Vector2d step = h * Eigen::Vector2d::Unit(a);
      const double numeric = (field.Distance(p + step) - field.Distance(p - step)) / (2 * h);
      ASSERT_NEAR(gradient(a), numeric, 1e-6) << p.transpose() << " axis " << a;
    }
    ++checked;
  }
}

TEST(SignedDistanceField2Test, OutsideEmptyAndNan) {
  const Scene scene = testing::RandomDisjointRoom(6, 6.0, 30, 0.15);
  const SignedDistanceField2 field = SignedDistanceField2::Build(BaseOccupancy(scene, 0.1));
  const GridGeometry2& g = field.geometry();
  const Eigen::Vector2d lo = g.CellCenter(0, 0);
  const Eigen::Vector2d hi = g.CellCenter(g.dims.x() - 1, g.dims.y() - 1);
  const Eigen::Vector2d p(hi.x() + 2.0, lo.y() - 1.0);
  EXPECT_NEAR(field.Distance(p), field.Distance(Eigen::Vector2d(hi.x(), lo.y())) + std::sqrt(5.0),
              1e-9);
  Eigen::Vector2d gradient;
  field.DistanceAndGradient(p, &gradient);
  EXPECT_TRUE(gradient.isApprox(Eigen::Vector2d(2, -1).normalized(), 1e-9));
  EXPECT_TRUE(std::isnan(field.Distance(Eigen::Vector2d(std::nan(""), 0))));

  const SignedDistanceField2 empty = SignedDistanceField2::Build(OccupancyGrid2(g));
  EXPECT_NEAR(empty.max_distance_m(), std::sqrt(2.0) * 6.0, 1e-9);
  EXPECT_NEAR(empty.DistanceAndGradient(Eigen::Vector2d(0.3, -1.2), &gradient),
              empty.max_distance_m(), 1e-6);
  EXPECT_TRUE(gradient.isZero(1e-12));
}

TEST(SignedDistanceField2Test, LowerToTakesTheCellwiseMinimumWithAnOffset) {
  const GridGeometry2 geometry =
      GridGeometry2::FromBounds(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 4)), 0.1);
  OccupancyGrid2 left(geometry), right(geometry);
  left.AddBoxInBand(MakeBox({0.5, 2.0, 0.05}, {0.4, 0.4, 0.1}), kBaseBand);
  right.AddBoxInBand(MakeBox({3.5, 2.0, 0.05}, {0.4, 0.4, 0.1}), kBaseBand);
  SignedDistanceField2 field = SignedDistanceField2::Build(left);
  const SignedDistanceField2 other = SignedDistanceField2::Build(right);
  const SignedDistanceField2 original = field;
  const double offset_m = 0.25;
  EXPECT_EQ(field.primary_band(), nullptr);
  field.LowerTo(other, offset_m);
  // The field as it was before is kept as its primary band, through further lowering.
  ASSERT_NE(field.primary_band(), nullptr);
  field.LowerTo(other, offset_m + 0.1);
  ASSERT_NE(field.primary_band(), nullptr);
  EXPECT_EQ(field.primary_band()->values(), original.values());
  for (int ix = 0; ix < geometry.dims.x(); ++ix) {
    for (int iy = 0; iy < geometry.dims.y(); ++iy) {
      const float expected = std::min(original.CellValue(ix, iy),
                                      static_cast<float>(other.CellValue(ix, iy) + offset_m));
      ASSERT_EQ(field.CellValue(ix, iy), expected) << ix << ", " << iy;
    }
  }
  // Near the right box the offset one wins: about 0.25 m at its face.
  EXPECT_NEAR(field.Distance(Eigen::Vector2d(3.3, 2.0)), offset_m, 0.1);
  // The interpolant never exceeds either field's.
  Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector2d p(rng.Uniform(0, 4), rng.Uniform(0, 4));
    EXPECT_LE(field.Distance(p), original.Distance(p) + 1e-6);
    EXPECT_LE(field.Distance(p), other.Distance(p) + offset_m + 1e-6);
  }
}

TEST(SignedDistanceField2Test, LowerToRejectsOtherGridsAndNanOffsets) {
  const auto box = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 2));
  SignedDistanceField2 field = SignedDistanceField2::Build(OccupancyGrid2(GridGeometry2::FromBounds(box, 0.1)));
  const SignedDistanceField2 coarser =
      SignedDistanceField2::Build(OccupancyGrid2(GridGeometry2::FromBounds(box, 0.2)));
  EXPECT_THROW(field.LowerTo(coarser, 0.0), std::invalid_argument);
  EXPECT_THROW(field.LowerTo(field, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace topay
