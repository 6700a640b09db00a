#include "core/map/signed_distance_window.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/common/random.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

// A random binary grid: blobs (small boxes) plus salt.
std::vector<std::uint8_t> RandomCells(const Eigen::Vector3i& dims, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(dims.prod()), 0);
  auto index = [&](int x, int y, int z) { return (std::int64_t{z} * dims.y() + y) * dims.x() + x; };
  for (int b = 0; b < 6; ++b) {
    const Eigen::Vector3i lo(rng.UniformInt(0, dims.x() - 1), rng.UniformInt(0, dims.y() - 1),
                             rng.UniformInt(0, dims.z() - 1));
    const Eigen::Vector3i hi =
        (lo + Eigen::Vector3i(rng.UniformInt(1, 6), rng.UniformInt(1, 6), rng.UniformInt(1, 5)))
            .cwiseMin(dims);
    for (int z = lo.z(); z < hi.z(); ++z)
      for (int y = lo.y(); y < hi.y(); ++y)
        for (int x = lo.x(); x < hi.x(); ++x) cells[index(x, y, z)] = 1;
  }
  for (int s = 0; s < 20; ++s) {
    cells[index(rng.UniformInt(0, dims.x() - 1), rng.UniformInt(0, dims.y() - 1),
                rng.UniformInt(0, dims.z() - 1))] = 1;
  }
  return cells;
}

// The signed, capped values by brute force: for each cell the squared distance to every cell
// of the other phase (and, inside, to the virtual free cells beyond the grid), then the
// documented formula (SignedDistanceFieldOptions) in the same float arithmetic.
std::vector<float> BruteForce(const std::vector<std::uint8_t>& cells, const Eigen::Vector3i& dims,
                              double res, double cap, double inset) {
  std::vector<float> values(cells.size());
  auto index = [&](int x, int y, int z) { return (std::int64_t{z} * dims.y() + y) * dims.x() + x; };
  const float r = static_cast<float>(res), c = static_cast<float>(cap);
  for (int z = 0; z < dims.z(); ++z)
    for (int y = 0; y < dims.y(); ++y)
      for (int x = 0; x < dims.x(); ++x) {
        const bool occupied = cells[index(x, y, z)] != 0;
        std::int64_t best = std::numeric_limits<std::int64_t>::max();
        for (int z2 = 0; z2 < dims.z(); ++z2)
          for (int y2 = 0; y2 < dims.y(); ++y2)
            for (int x2 = 0; x2 < dims.x(); ++x2) {
              if ((cells[index(x2, y2, z2)] != 0) == occupied) continue;
              const std::int64_t d = std::int64_t{x - x2} * (x - x2) +
                                     std::int64_t{y - y2} * (y - y2) +
                                     std::int64_t{z - z2} * (z - z2);
              best = std::min(best, d);
            }
        float& v = values[index(x, y, z)];
        if (!occupied) {
          const float root = best == std::numeric_limits<std::int64_t>::max()
                                 ? std::numeric_limits<float>::infinity()
                                 : std::sqrt(static_cast<float>(best));
          v = std::min((root + (static_cast<float>(inset) - 0.5f)) * r, c);
        } else {
          const int border =
              std::min({x + 1, dims.x() - x, y + 1, dims.y() - y, z + 1, dims.z() - z});
          best = std::min<std::int64_t>(best, std::int64_t{border} * border);
          v = -std::min(
              (std::sqrt(static_cast<float>(best)) + (-0.5f - static_cast<float>(inset))) * r, c);
        }
      }
  return values;
}

int CountBitwiseDifferences(const std::vector<float>& a, const std::vector<float>& b) {
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0;
  return n;
}

TEST(SignedDistanceWindowTest, ReachCoversTheCapAndRejectsBadInput) {
  EXPECT_EQ(SignedDistanceReachCells(1.0, 0.05), 22);
  EXPECT_EQ(SignedDistanceReachCells(0.3, 0.1), 5);
  EXPECT_THROW(SignedDistanceReachCells(std::nan(""), 0.1), std::invalid_argument);
  EXPECT_THROW(SignedDistanceReachCells(1.0, 0.0), std::invalid_argument);
}

TEST(SignedDistanceWindowTest, FullGridEqualsBruteForceAndTheUncappedBuild) {
  const Eigen::Vector3i dims(18, 15, 9);
  const double res = 0.1;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const std::vector<std::uint8_t> cells = RandomCells(dims, seed);
    for (double inset : {0.5, 0.0}) {
      SignedDistanceFieldOptions options;
      options.zero_level_inset_cells = inset;
      for (double cap : {0.35, 100.0}) {
        std::vector<float> values(cells.size(), 7.0f);
        SignedDistanceWindowWorkspace ws;
        RecomputeSignedDistanceWindow(cells.data(), dims, 3, res, cap, options,
                                      CellBox{Eigen::Vector3i::Zero(), dims}, &ws, values.data());
        EXPECT_EQ(CountBitwiseDifferences(values, BruteForce(cells, dims, res, cap, inset)), 0)
            << "seed " << seed << " cap " << cap;
        // The library's whole-grid build with the same cap.
        std::vector<float> reference;
        BuildSignedDistanceValues(cells.data(), dims, 3, res, cap, options, nullptr, &reference);
        EXPECT_EQ(CountBitwiseDifferences(values, reference), 0);
      }
    }
  }
}

TEST(SignedDistanceWindowTest, WindowsEqualTheFullBuildBitwise) {
  const Eigen::Vector3i dims(40, 33, 12);
  const double res = 0.05, cap = 0.3;
  const SignedDistanceFieldOptions options;
  Rng rng(7);
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const std::vector<std::uint8_t> cells = RandomCells(dims, seed);
    SignedDistanceWindowWorkspace ws;
    std::vector<float> full(cells.size());
    RecomputeSignedDistanceWindow(cells.data(), dims, 3, res, cap, options,
                                  CellBox{Eigen::Vector3i::Zero(), dims}, &ws, full.data());
    for (int trial = 0; trial < 10; ++trial) {
      // A random window (edges included); everything outside it must stay untouched.
      CellBox target;
      for (int a = 0; a < 3; ++a) {
        const int b = rng.UniformInt(0, dims(a) - 1);
        target.begin(a) = b;
        target.end(a) = rng.UniformInt(b + 1, dims(a));
      }
      std::vector<float> values(cells.size(), 42.0f);
      RecomputeSignedDistanceWindow(cells.data(), dims, 3, res, cap, options, target, &ws,
                                    values.data());
      int differences = 0, untouched = 0;
      for (int z = 0; z < dims.z(); ++z)
        for (int y = 0; y < dims.y(); ++y)
          for (int x = 0; x < dims.x(); ++x) {
            const std::int64_t i = (std::int64_t{z} * dims.y() + y) * dims.x() + x;
            if (target.Contains({x, y, z})) {
              differences += std::memcmp(&values[i], &full[i], sizeof(float)) != 0;
            } else {
              untouched += values[i] == 42.0f;
            }
          }
      EXPECT_EQ(differences, 0) << "seed " << seed << " trial " << trial;
      // A window whose source is the whole grid runs in place (all cells correct); otherwise
      // cells outside the target are not written.
      if (target.Dilated(Eigen::Vector3i::Constant(SignedDistanceReachCells(cap, res)), dims)
              .NumCells() < dims.prod()) {
        EXPECT_EQ(untouched, dims.prod() - target.NumCells());
      }
    }
  }
}

TEST(SignedDistanceWindowTest, RejectsATargetOutsideTheGrid) {
  const Eigen::Vector3i dims(8, 8, 4);
  std::vector<std::uint8_t> cells(dims.prod(), 0);
  std::vector<float> values(cells.size());
  SignedDistanceWindowWorkspace ws;
  EXPECT_THROW(RecomputeSignedDistanceWindow(cells.data(), dims, 3, 0.1, 0.5, {},
                                             CellBox{{0, 0, 0}, {9, 8, 4}}, &ws, values.data()),
               std::invalid_argument);
  EXPECT_THROW(RecomputeSignedDistanceWindow(cells.data(), dims, 3, 0.1, 0.5, {},
                                             CellBox{{2, 2, 2}, {2, 3, 3}}, &ws, values.data()),
               std::invalid_argument);
  SignedDistanceFieldOptions bad;
  bad.zero_level_inset_cells = std::nan("");
  EXPECT_THROW(RecomputeSignedDistanceWindow(cells.data(), dims, 3, 0.1, 0.5, bad,
                                             CellBox{{0, 0, 0}, dims}, &ws, values.data()),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
