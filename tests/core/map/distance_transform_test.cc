#include "core/map/distance_transform.h"

#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(SquaredDistance1dTest, MatchesBruteForceOnRandomFunctions) {
  Rng rng(11);
  for (int trial = 0; trial < 500; ++trial) {
    const int n = static_cast<int>(rng.UniformInt(1, 60));
    // Small and large values (up to the 2^24 the fields use), a third of them "no site".
    const std::int64_t largest = trial % 2 == 0 ? 400 : (1 << 24);
    std::vector<std::int32_t> f(n);
    for (std::int32_t& value : f) {
      value = rng.Uniform01() < 0.33 ? kNoSite
                                     : static_cast<std::int32_t>(rng.UniformInt(0, largest));
    }
    std::vector<std::int32_t> d(n), sites(n);
    std::vector<std::int64_t> numerators(n), denominators(n);
    SquaredDistance1d(f.data(), n, d.data(), sites.data(), numerators.data(),
                      denominators.data());
    for (int q = 0; q < n; ++q) {
      std::int64_t expected = kNoSite;
      for (int p = 0; p < n; ++p) {
        if (f[p] != kNoSite) expected = std::min<std::int64_t>(expected, (q - p) * (q - p) + f[p]);
      }
      ASSERT_EQ(d[q], expected) << "trial " << trial << " q " << q;
    }
  }
}

TEST(SquaredDistance1dTest, NoSiteGivesNoSite) {
  const std::vector<std::int32_t> f(7, kNoSite);
  std::vector<std::int32_t> d(7, 0), sites(7);
  std::vector<std::int64_t> numerators(7), denominators(7);
  SquaredDistance1d(f.data(), 7, d.data(), sites.data(), numerators.data(), denominators.data());
  for (std::int32_t value : d) EXPECT_EQ(value, kNoSite);
}

// Brute force: squared distance between cell centres to the nearest cell of the other phase,
// in cell units.
std::vector<float> BruteForceEdt(const std::vector<std::uint8_t>& cells,
                                 const Eigen::Vector3i& dims) {
  std::vector<float> out(cells.size(), kInf);
  auto index = [&](int x, int y, int z) { return (z * dims.y() + y) * dims.x() + x; };
  for (int z = 0; z < dims.z(); ++z)
    for (int y = 0; y < dims.y(); ++y)
      for (int x = 0; x < dims.x(); ++x)
        for (int sz = 0; sz < dims.z(); ++sz)
          for (int sy = 0; sy < dims.y(); ++sy)
            for (int sx = 0; sx < dims.x(); ++sx) {
              if (cells[index(sx, sy, sz)] == cells[index(x, y, z)]) continue;
              const int dx = x - sx, dy = y - sy, dz = z - sz;
              float& best = out[index(x, y, z)];
              best = std::min(best, static_cast<float>(dx * dx + dy * dy + dz * dz));
            }
  return out;
}

TEST(SquaredDistanceToOtherPhaseTest, EqualsBruteForceOnSmallRandomGrids) {
  Rng rng(2024);
  EdtWorkspace workspace;  // reused across grids of different sizes on purpose
  const double densities[] = {0.0, 0.02, 0.1, 0.4, 0.8, 1.0};
  int checked_finite = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Sizes include 1-wide axes and more than one block of 16 lanes in x.
    const Eigen::Vector3i dims(static_cast<int>(rng.UniformInt(1, 37)),
                               static_cast<int>(rng.UniformInt(1, 12)),
                               static_cast<int>(rng.UniformInt(1, 9)));
    const double density = densities[trial % 6];
    std::vector<std::uint8_t> cells(dims.prod());
    for (auto& cell : cells) cell = rng.Uniform01() < density ? 1 : 0;
    std::vector<float> out(cells.size(), -1.0f);
    SquaredDistanceToOtherPhase(cells.data(), dims, out.data(), &workspace);
    const std::vector<float> expected = BruteForceEdt(cells, dims);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      ASSERT_EQ(out[i], expected[i]) << "trial " << trial << " dims " << dims.transpose()
                                     << " cell " << i;
      checked_finite += expected[i] != kInf && expected[i] > 1.0f;
    }
  }
  EXPECT_GT(checked_finite, 10000);  // the comparison covered plenty of non-trivial cells
}

TEST(SquaredDistanceToOtherPhaseTest, SingleOccupiedCellGivesSquaredNormEverywhere) {
  const Eigen::Vector3i dims(40, 30, 20);
  std::vector<std::uint8_t> cells(dims.prod(), 0);
  const Eigen::Vector3i site(3, 25, 11);
  cells[(site.z() * dims.y() + site.y()) * dims.x() + site.x()] = 1;
  std::vector<float> out(cells.size());
  EdtWorkspace workspace;
  SquaredDistanceToOtherPhase(cells.data(), dims, out.data(), &workspace);
  for (int z = 0; z < dims.z(); ++z)
    for (int y = 0; y < dims.y(); ++y)
      for (int x = 0; x < dims.x(); ++x) {
        const Eigen::Vector3i cell(x, y, z);
        // The occupied cell's nearest free cell is a face neighbour.
        const float expected = cell == site ? 1.0f : static_cast<float>((cell - site).squaredNorm());
        ASSERT_EQ(out[(z * dims.y() + y) * dims.x() + x], expected);
      }
}

}  // namespace
}  // namespace topay
