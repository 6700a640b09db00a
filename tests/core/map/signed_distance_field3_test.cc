#include "core/map/signed_distance_field3.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/map/random_room.h"

namespace topay {
namespace {

const Eigen::AlignedBox3d kUnitBounds(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1));

OccupancyGrid3 RoomOccupancy(const Scene& scene, double resolution_m) {
  OccupancyGrid3 grid(GridGeometry3::FromBounds(scene.bounds_W_m, resolution_m));
  for (const OrientedBox& box : scene.boxes) grid.AddBox(box);
  return grid;
}

// Fractional part of the continuous cell-centre index of p on each axis.
Eigen::Vector3d CellFraction(const GridGeometry3& g, const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d u = (p_W - g.origin_W_m) / g.resolution_m - Eigen::Vector3d::Constant(0.5);
  return u - u.array().floor().matrix();
}

TEST(SignedDistanceField3Test, SlabAlignedWithCellFacesIsExactForBothZeroLevels) {
  // Cells with 3 <= ix < 17 occupied over all y, z: a slab whose left face is the plane
  // x = -1 + 0.3 = -0.7. Near that face, away from the grid's other faces, the cell values are
  // exact distances to the plane shifted by the zero-level inset, and so is the interpolant.
  const double res = 0.1;
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 2));
  OccupancyGrid3 grid(GridGeometry3::FromBounds(bounds, res));
  for (int iz = 0; iz < 20; ++iz)
    for (int iy = 0; iy < 20; ++iy)
      for (int ix = 3; ix < 17; ++ix) grid.SetOccupied(ix, iy, iz, true);
  for (double inset : {0.0, 0.25, 0.5}) {
    SignedDistanceFieldOptions options;
    options.zero_level_inset_cells = inset;
    const SignedDistanceField3 field = SignedDistanceField3::Build(grid, options);
    for (int ix = 0; ix <= 6; ++ix) {
      const double expected = (-0.7 - (-1 + (ix + 0.5) * res)) + inset * res;
      EXPECT_NEAR(field.CellValue(ix, 10, 10), expected, 1e-6) << ix << " inset " << inset;
    }
    Rng rng(1);
    for (int i = 0; i < 300; ++i) {
      const Eigen::Vector3d p(rng.Uniform(-0.95, -0.35), rng.Uniform(-0.35, 0.35),
                              rng.Uniform(0.65, 1.35));
      Eigen::Vector3d gradient;
      EXPECT_NEAR(field.DistanceAndGradient(p, &gradient), -0.7 - p.x() + inset * res, 1e-6);
      EXPECT_TRUE(gradient.isApprox(-Eigen::Vector3d::UnitX(), 1e-6)) << gradient.transpose();
    }
  }
  SignedDistanceFieldOptions bad;
  bad.zero_level_inset_cells = 0.7;
  EXPECT_THROW(SignedDistanceField3::Build(grid, bad), std::invalid_argument);
  bad.zero_level_inset_cells = std::nan("");
  EXPECT_THROW(SignedDistanceField3::Build(grid, bad), std::invalid_argument);
}

TEST(SignedDistanceField3Test, InterpolationReproducesCellValuesAndSigns) {
  const Scene scene = testing::RandomDisjointRoom(5, 6.0, 30, 0.15);
  const OccupancyGrid3 grid = RoomOccupancy(scene, 0.1);
  SignedDistanceFieldOptions faces;
  faces.zero_level_inset_cells = 0.0;  // value < 0 exactly on occupied cells
  const SignedDistanceField3 field = SignedDistanceField3::Build(grid, faces);
  const GridGeometry3& g = field.geometry();
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const float value = field.CellValue(ix, iy, iz);
        ASSERT_EQ(value < 0.0f, grid.IsOccupied(ix, iy, iz));
        ASSERT_GE(std::abs(value), 0.5 * g.resolution_m - 1e-6);
        ASSERT_NEAR(field.Distance(g.CellCenter(ix, iy, iz)), value, 1e-6);
      }
}

struct ErrorStats {
  double max = 0.0;
  double median = 0.0;
  double p99 = 0.0;
};

ErrorStats FieldErrorOnRandomPoints(const Scene& scene, const SignedDistanceField3& field,
                                    int num_points, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> errors;
  errors.reserve(num_points);
  const Eigen::AlignedBox3d& b = scene.bounds_W_m;
  for (int i = 0; i < num_points; ++i) {
    const Eigen::Vector3d p(rng.Uniform(b.min().x(), b.max().x()),
                            rng.Uniform(b.min().y(), b.max().y()),
                            rng.Uniform(b.min().z(), b.max().z()));
    errors.push_back(std::abs(field.Distance(p) - testing::ExactSignedDistance(scene.boxes, p)));
  }
  std::sort(errors.begin(), errors.end());
  return {errors.back(), errors[errors.size() / 2], errors[errors.size() * 99 / 100]};
}

// The correctness figure: against brute-force exact distances to the boxes on 10,000 random
// points of a 20 x 20 x 1.6 m room of ~160 random disjoint boxes, |error| <= one cell.
TEST(SignedDistanceField3Test, WithinOneCellOfExactDistanceOnRandomRoom) {
  const Scene scene = testing::RandomDisjointRoom(42, 20.0, 160, 0.15);
  ASSERT_GE(scene.boxes.size(), 4u + 150u);
  for (double res : {0.1, 0.05}) {
    const SignedDistanceField3 field = SignedDistanceField3::Build(RoomOccupancy(scene, res));
    const ErrorStats stats = FieldErrorOnRandomPoints(scene, field, 10000, 99);
    std::cout << "resolution " << res << " m: |sdf - exact| max " << stats.max << " m, p99 "
              << stats.p99 << " m, median " << stats.median << " m over 10000 points\n";
    RecordProperty(res == 0.1 ? "max_error_0_1" : "max_error_0_05", std::to_string(stats.max));
    EXPECT_LE(stats.max, res);
    EXPECT_LE(stats.median, 0.5 * res);
  }
}

TEST(SignedDistanceField3Test, GradientMatchesFiniteDifferencesOfTheInterpolant) {
  const Scene scene = testing::RandomDisjointRoom(8, 6.0, 30, 0.15);
  const SignedDistanceField3 field = SignedDistanceField3::Build(RoomOccupancy(scene, 0.1));
  const GridGeometry3& g = field.geometry();
  const Eigen::AlignedBox3d box = g.Bounds();
  Rng rng(4);
  int checked = 0;
  double largest_component = 0.0;
  while (checked < 2000) {
    // Points inside the grid and up to 0.5 m beyond it (the clamped, extended region).
    const Eigen::Vector3d p(rng.Uniform(box.min().x() - 0.5, box.max().x() + 0.5),
                            rng.Uniform(box.min().y() - 0.5, box.max().y() + 0.5),
                            rng.Uniform(box.min().z() - 0.5, box.max().z() + 0.5));
    const Eigen::Vector3d fraction = CellFraction(g, p);
    // The interpolant is smooth inside a cell of centres; stay away from its kinks.
    if ((fraction.array() < 0.01).any() || (fraction.array() > 0.99).any()) continue;
    Eigen::Vector3d gradient;
    const double distance = field.DistanceAndGradient(p, &gradient);
    ASSERT_DOUBLE_EQ(distance, field.Distance(p));
    const double h = 1e-6;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(a);
      const double numeric = (field.Distance(p + step) - field.Distance(p - step)) / (2 * h);
      ASSERT_NEAR(gradient(a), numeric, 1e-6) << "point " << p.transpose() << " axis " << a;
      largest_component = std::max(largest_component, std::abs(gradient(a)));
    }
    ++checked;
  }
  EXPECT_GT(largest_component, 0.5);  // the check saw real slopes, not a flat field
}

TEST(SignedDistanceField3Test, OutsideTheGridClampsAndAddsTheDistanceOutside) {
  const Scene scene = testing::RandomDisjointRoom(9, 6.0, 30, 0.15);
  const SignedDistanceField3 field = SignedDistanceField3::Build(RoomOccupancy(scene, 0.1));
  const GridGeometry3& g = field.geometry();
  // Box of cell centres.
  const Eigen::Vector3d lo = g.CellCenter(0, 0, 0);
  const Eigen::Vector3d hi = g.CellCenter(g.dims.x() - 1, g.dims.y() - 1, g.dims.z() - 1);
  Rng rng(10);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d p(rng.Uniform(lo.x() - 3, hi.x() + 3), rng.Uniform(lo.y() - 3, hi.y() + 3),
                            rng.Uniform(lo.z() - 3, hi.z() + 3));
    const Eigen::Vector3d c = p.cwiseMax(lo).cwiseMin(hi);
    Eigen::Vector3d gradient_p, gradient_c;
    const double at_p = field.DistanceAndGradient(p, &gradient_p);
    const double at_c = field.DistanceAndGradient(c, &gradient_c);
    ASSERT_NEAR(at_p, at_c + (p - c).norm(), 1e-9);
    if ((p - c).norm() > 1e-9) {
      Eigen::Vector3d expected = gradient_c;
      for (int a = 0; a < 3; ++a) {
        if (p(a) != c(a)) expected(a) = 0.0;
      }
      expected += (p - c).normalized();
      ASSERT_TRUE(gradient_p.isApprox(expected, 1e-9)) << gradient_p.transpose();
    }
  }
  // Continuous across the edge of the box of centres.
  const Eigen::Vector3d edge(hi.x(), 0.5 * (lo.y() + hi.y()), 0.5 * (lo.z() + hi.z()));
  const Eigen::Vector3d nudge(1e-9, 0, 0);
  EXPECT_NEAR(field.Distance(edge + nudge), field.Distance(edge - nudge), 1e-7);
  // Far away the field keeps growing.
  EXPECT_GT(field.Distance(Eigen::Vector3d(100, 0, 0.5)), 90.0);
}

TEST(SignedDistanceField3Test, EmptyGridIsLargeAndFiniteWithZeroGradient) {
  const OccupancyGrid3 grid(GridGeometry3::FromBounds(kUnitBounds, 0.1));
  const SignedDistanceField3 field = SignedDistanceField3::Build(grid);
  const double diagonal = std::sqrt(2.0 * 2.0 + 2.0 * 2.0 + 1.0);
  EXPECT_NEAR(field.max_distance_m(), diagonal, 1e-12);
  for (float value : field.values()) ASSERT_FLOAT_EQ(value, static_cast<float>(diagonal));
  Eigen::Vector3d gradient;
  const double distance = field.DistanceAndGradient(Eigen::Vector3d(0.13, -0.4, 0.77), &gradient);
  EXPECT_TRUE(std::isfinite(distance));
  EXPECT_NEAR(distance, diagonal, 1e-6);
  EXPECT_TRUE(gradient.isZero(1e-12));
}

TEST(SignedDistanceField3Test, FullGridIsDeepestInTheMiddleAndNanQueriesGiveNan) {
  // Every cell occupied: the only free space is beyond the grid, so the depth of a cell is its
  // distance to the grid's nearest face.
  OccupancyGrid3 grid(GridGeometry3::FromBounds(kUnitBounds, 0.1));  // 20 x 20 x 10 cells
  grid.AddBox(OrientedBox{Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d(3, 3, 3), 0.0});
  SignedDistanceFieldOptions faces;
  faces.zero_level_inset_cells = 0.0;
  const SignedDistanceField3 field = SignedDistanceField3::Build(grid, faces);
  EXPECT_NEAR(field.CellValue(0, 0, 0), -0.05, 1e-6);
  EXPECT_NEAR(field.CellValue(10, 10, 4), -0.45, 1e-6);  // 5 cells to the z faces
  EXPECT_NEAR(field.CellValue(10, 2, 4), -0.25, 1e-6);   // 3 cells to the y = -1 face
  Eigen::Vector3d gradient;
  EXPECT_TRUE(std::isnan(
      field.DistanceAndGradient(Eigen::Vector3d(std::nan(""), 0, 0.5), &gradient)));
  EXPECT_TRUE(std::isnan(field.Distance(Eigen::Vector3d(0, 0, std::nan("")))));
}

TEST(SignedDistanceField3Test, RebuildWithWorkspaceMatchesBuild) {
  const Scene scene = testing::RandomDisjointRoom(12, 6.0, 30, 0.15);
  const OccupancyGrid3 grid = RoomOccupancy(scene, 0.1);
  EdtWorkspace workspace;
  SignedDistanceField3 field =
      SignedDistanceField3::Build(OccupancyGrid3(GridGeometry3::FromBounds(kUnitBounds, 0.25)),
                                  {}, &workspace);
  field.Rebuild(grid, {}, &workspace);
  const SignedDistanceField3 fresh = SignedDistanceField3::Build(grid);
  EXPECT_EQ(field.geometry().dims, fresh.geometry().dims);
  EXPECT_EQ(field.values(), fresh.values());
}

}  // namespace
}  // namespace topay
