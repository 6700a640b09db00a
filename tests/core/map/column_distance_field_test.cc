#include "core/map/column_distance_field.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/common/random.h"
#include "core/map/footprint_distance_field.h"
#include "tests/common/make_box.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

// Random columns: a few rectangles of columns plus single columns, edges included.
OccupancyGrid2 RandomColumns(const GridGeometry2& g, std::uint64_t seed) {
  OccupancyGrid2 columns(g);
  Rng rng(seed);
  for (int b = 0; b < 5; ++b) {
    const int x0 = rng.UniformInt(0, g.dims.x() - 1), y0 = rng.UniformInt(0, g.dims.y() - 1);
    const int x1 = std::min<int>(x0 + rng.UniformInt(1, 5), g.dims.x());
    const int y1 = std::min<int>(y0 + rng.UniformInt(1, 5), g.dims.y());
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) columns.SetOccupied(x, y, true);
  }
  for (int s = 0; s < 8; ++s) {
    columns.SetOccupied(rng.UniformInt(0, g.dims.x() - 1), rng.UniformInt(0, g.dims.y() - 1), true);
  }
  columns.SetOccupied(0, g.dims.y() - 1, true);
  return columns;
}

// Distance from u to the interval [lo, hi] (0 inside).
double IntervalDistance(double u, double lo, double hi) { return std::max({lo - u, u - hi, 0.0}); }

// The field by brute force: per field cell, every square of the other phase (and, for an
// occupied point, the outside of the grid), in double, then capped and signed.
std::vector<float> BruteForce(const OccupancyGrid2& columns, const GridGeometry2& fg, double cap) {
  const GridGeometry2& cg = columns.geometry();
  const double r = cg.resolution_m;
  std::vector<float> values(fg.NumCells());
  const double gx0 = cg.origin_W_m.x(), gx1 = gx0 + cg.dims.x() * r;
  const double gy0 = cg.origin_W_m.y(), gy1 = gy0 + cg.dims.y() * r;
  for (int fy = 0; fy < fg.dims.y(); ++fy) {
    for (int fx = 0; fx < fg.dims.x(); ++fx) {
      const Eigen::Vector2d p = fg.CellCenter(fx, fy);
      const Eigen::Vector2i c = cg.CellOf(p);
      const bool occupied = cg.Contains(p) && columns.IsOccupied(c.x(), c.y());
      double best = std::numeric_limits<double>::infinity();
      for (int cy = 0; cy < cg.dims.y(); ++cy) {
        for (int cx = 0; cx < cg.dims.x(); ++cx) {
          if (columns.IsOccupied(cx, cy) == occupied) continue;
          const double ex = IntervalDistance(p.x(), gx0 + cx * r, gx0 + (cx + 1) * r);
          const double ey = IntervalDistance(p.y(), gy0 + cy * r, gy0 + (cy + 1) * r);
          best = std::min(best, ex * ex + ey * ey);
        }
      }
      if (occupied) {
        const double e = std::min({p.x() - gx0, gx1 - p.x(), p.y() - gy0, gy1 - p.y()});
        best = std::min(best, e * e);
      }
      const double d = std::min(std::sqrt(best), cap);
      values[fg.Index(fx, fy)] = static_cast<float>(occupied ? -d : d);
    }
  }
  return values;
}

TEST(ColumnDistanceFieldTest, EqualsBruteForceOnFinerAndEqualGrids) {
  const GridGeometry2 columns_geometry{{-0.6, 0.2}, 0.05, {26, 21}};
  for (double field_res : {0.01, 0.05, 0.03}) {
    const GridGeometry2 fg = GridGeometry2::FromBounds(
        Eigen::AlignedBox2d(Eigen::Vector2d(-0.6, 0.2), Eigen::Vector2d(0.7, 1.25)), field_res);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const OccupancyGrid2 columns = RandomColumns(columns_geometry, seed);
      for (double cap : {0.2, 5.0}) {
        const SignedDistanceField2 field = BuildColumnDistanceField(columns, fg, cap);
        const std::vector<float> expected = BruteForce(columns, fg, cap);
        double max_difference = 0.0;
        for (std::size_t i = 0; i < expected.size(); ++i) {
          max_difference =
              std::max(max_difference, std::abs(double{field.values()[i]} - double{expected[i]}));
        }
        EXPECT_EQ(max_difference, 0.0) << "res " << field_res << " seed " << seed << " cap " << cap;
        EXPECT_DOUBLE_EQ(field.exactness_margin_m(), field_res / std::sqrt(2.0));
        EXPECT_DOUBLE_EQ(field.max_distance_m(), cap);
      }
    }
  }
}

TEST(ColumnDistanceFieldTest, WindowsEqualTheWholeFillBitwise) {
  const GridGeometry2 cg{{0.0, 0.0}, 0.05, {40, 30}};
  const GridGeometry2 fg = GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 1.5)), 0.01);
  const double cap = 0.25;
  Rng rng(3);
  ColumnDistanceWorkspace ws;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const OccupancyGrid2 columns = RandomColumns(cg, seed);
    const SignedDistanceField2 full = BuildColumnDistanceField(columns, fg, cap, &ws);
    for (int trial = 0; trial < 10; ++trial) {
      CellBox target{Eigen::Vector3i::Zero(), Eigen::Vector3i::Ones()};
      for (int a = 0; a < 2; ++a) {
        target.begin(a) = rng.UniformInt(0, fg.dims(a) - 1);
        target.end(a) = rng.UniformInt(target.begin(a) + 1, fg.dims(a));
      }
      std::vector<float> values(fg.NumCells(), 42.0f);
      FillColumnDistanceWindow(columns, fg, target, cap, &ws, values.data());
      int differences = 0, untouched = 0;
      for (int y = 0; y < fg.dims.y(); ++y)
        for (int x = 0; x < fg.dims.x(); ++x) {
          const std::int64_t i = fg.Index(x, y);
          if (target.Contains({x, y, 0})) {
            differences += std::memcmp(&values[i], &full.values()[i], sizeof(float)) != 0;
          } else {
            untouched += values[i] == 42.0f;
          }
        }
      EXPECT_EQ(differences, 0);
      EXPECT_EQ(untouched, fg.NumCells() - target.NumCells());
    }
  }
}

TEST(ColumnDistanceFieldTest, ExactnessMarginHoldsAtRandomPoints) {
  const GridGeometry2 cg{{0.0, 0.0}, 0.05, {30, 30}};
  const GridGeometry2 fg = GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1.5, 1.5)), 0.02);
  const OccupancyGrid2 columns = RandomColumns(cg, 5);
  const double cap = 0.5;
  const SignedDistanceField2 field = BuildColumnDistanceField(columns, fg, cap);
  Rng rng(11);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Eigen::Vector2d p(rng.Uniform(0.0, 1.5), rng.Uniform(0.0, 1.5));
    double exact = std::numeric_limits<double>::infinity();
    for (int cy = 0; cy < cg.dims.y(); ++cy)
      for (int cx = 0; cx < cg.dims.x(); ++cx) {
        if (!columns.IsOccupied(cx, cy)) continue;
        const double ex = IntervalDistance(p.x(), cx * 0.05, (cx + 1) * 0.05);
        const double ey = IntervalDistance(p.y(), cy * 0.05, (cy + 1) * 0.05);
        exact = std::min(exact, std::hypot(ex, ey));
      }
    // Wherever the field promises d (below the cap), the squares are at least d away.
    const double promised = field.Distance(p) - field.exactness_margin_m();
    if (promised > 0.0 && promised < cap - field.exactness_margin_m()) {
      ++checked;
      EXPECT_GE(exact, promised - 1e-9) << p.transpose();
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(ColumnDistanceFieldTest, WithinOneColumnDiagonalBelowTheExactFootprintField) {
  // Boxes rasterised into columns (AddFootprint: conservative) against their exact footprints.
  const GridGeometry2 cg{{-1.0, -1.0}, 0.05, {40, 40}};
  const GridGeometry2 fg = GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 1)), 0.01);
  const std::vector<OrientedBox> boxes = {MakeBox({0.2, 0.1, 0.05}, {0.3, 0.12, 0.1}, 0.4),
                                          MakeBox({-0.5, -0.4, 0.05}, {0.05, 0.05, 0.1}),
                                          MakeBox({-0.3, 0.6, 0.05}, {0.5, 0.2, 0.1}, -1.0)};
  OccupancyGrid2 columns(cg);
  for (const OrientedBox& box : boxes) columns.AddFootprint(box);
  const double cap = 1.0;
  const SignedDistanceField2 field = BuildColumnDistanceField(columns, fg, cap);
  const SignedDistanceField2 exact =
      BuildFootprintDistanceField(fg, boxes, HeightBand{0.0, 0.155}, cap);
  const double diagonal = std::sqrt(2.0) * cg.resolution_m;
  int free_cells = 0;
  for (std::int64_t i = 0; i < fg.NumCells(); ++i) {
    const double v = field.values()[i], b = exact.values()[i];
    EXPECT_LE(v, b + 1e-6);
    if (v > 0.0) {
      ++free_cells;
      EXPECT_GE(v, b - diagonal - 1e-6);
    }
  }
  EXPECT_GT(free_cells, fg.NumCells() / 2);
}

TEST(ColumnDistanceFieldTest, NoColumnsGivesTheCapAndBadInputThrows) {
  const GridGeometry2 cg{{0.0, 0.0}, 0.1, {5, 5}};
  const OccupancyGrid2 columns(cg);
  const SignedDistanceField2 field = BuildColumnDistanceField(columns, cg, 0.3);
  for (float v : field.values()) EXPECT_EQ(v, 0.3f);
  std::vector<float> values(25);
  ColumnDistanceWorkspace ws;
  EXPECT_THROW(
      FillColumnDistanceWindow(columns, cg, CellBox{{0, 0, 0}, {6, 5, 1}}, 0.3, &ws, values.data()),
      std::invalid_argument);
  EXPECT_THROW(FillColumnDistanceWindow(columns, cg, CellBox{{0, 0, 0}, {5, 5, 1}}, std::nan(""),
                                        &ws, values.data()),
               std::invalid_argument);
  EXPECT_THROW(BuildColumnDistanceField(columns, cg, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace topay
