#include "core/map/occupancy_map.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "tests/core/robot/allocation_counter.h"

namespace topay {
namespace {

// A 2 x 2 x 1 m map of 0.1 m voxels (20 x 20 x 10) at the world origin.
OccupancyMapOptions SmallOptions() {
  OccupancyMapOptions options;
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 2, 1));
  options.resolution_m = 0.1;
  return options;
}

// World point at the centre of voxel (ix, iy, iz) of SmallOptions().
Eigen::Vector3f Centre(int ix, int iy, int iz) {
  return Eigen::Vector3f(0.1f * ix + 0.05f, 0.1f * iy + 0.05f, 0.1f * iz + 0.05f);
}
Eigen::Vector3d CentreD(int ix, int iy, int iz) { return Centre(ix, iy, iz).cast<double>(); }

ScanInsertSummary Insert(OccupancyMap* map, const Eigen::Vector3d& p_WS,
                         const std::vector<Eigen::Vector3f>& points,
                         std::vector<VoxelChange>* changes = nullptr) {
  return map->InsertScan(p_WS, points, changes);
}

void ExpectInvalid(void (*mutate)(OccupancyMapOptions*), const std::string& field) {
  OccupancyMapOptions options;
  mutate(&options);
  try {
    OccupancyMap map(options);
    ADD_FAILURE() << "accepted a bad " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(OccupancyMapTest, DefaultsAreTheRoomAtFiveCentimetres) {
  const OccupancyMap map;
  EXPECT_EQ(map.geometry().dims, Eigen::Vector3i(400, 400, 32));
  EXPECT_EQ(map.states().size(), 400u * 400u * 32u);
  const VoxelStateCounts counts = map.CountStates();
  EXPECT_EQ(counts.unknown, 400 * 400 * 32);
  EXPECT_EQ(counts.occupied + counts.free, 0);
  EXPECT_EQ(map.state(3, 4, 5), VoxelState::kUnknown);
  EXPECT_EQ(map.log_odds(3, 4, 5), 0.0f);
}

TEST(OccupancyMapTest, InvalidOptionsNameTheField) {
  ExpectInvalid([](OccupancyMapOptions* o) { o->bounds_W_m.max().z() = -1.0; }, "bounds_W_m");
  ExpectInvalid([](OccupancyMapOptions* o) { o->resolution_m = 0.0; }, "resolution_m");
  ExpectInvalid([](OccupancyMapOptions* o) { o->log_odds_hit = -0.1f; }, "log_odds_hit");
  ExpectInvalid([](OccupancyMapOptions* o) { o->log_odds_miss = 0.0f; }, "log_odds_miss");
  ExpectInvalid([](OccupancyMapOptions* o) { o->log_odds_min = 0.5f; }, "log_odds_min");
  ExpectInvalid([](OccupancyMapOptions* o) { o->log_odds_max = -0.5f; }, "log_odds_max");
  ExpectInvalid([](OccupancyMapOptions* o) { o->occupied_threshold_log_odds = NAN; },
                "occupied_threshold_log_odds");
  ExpectInvalid([](OccupancyMapOptions* o) { o->max_free_ray_length_m = -1.0; },
                "max_free_ray_length_m");
}

TEST(OccupancyMapTest, AReturnIsOccupiedAndItsRayFree) {
  OccupancyMap map(SmallOptions());
  const ScanInsertSummary s = Insert(&map, CentreD(1, 10, 5), {Centre(15, 10, 5)});
  EXPECT_EQ(s.num_points, 1);
  EXPECT_EQ(s.num_points_used, 1);
  EXPECT_EQ(s.num_voxels_hit, 1);
  EXPECT_EQ(s.num_voxels_missed, 14);  // voxels 1..14 of the row
  EXPECT_EQ(s.num_changes, 15);
  EXPECT_EQ(map.state(15, 10, 5), VoxelState::kOccupied);
  EXPECT_FLOAT_EQ(map.log_odds(15, 10, 5), 0.85f);
  for (int ix = 1; ix < 15; ++ix) {
    EXPECT_EQ(map.state(ix, 10, 5), VoxelState::kFree) << ix;
    EXPECT_FLOAT_EQ(map.log_odds(ix, 10, 5), -0.4f);
  }
  EXPECT_EQ(map.state(0, 10, 5), VoxelState::kUnknown);   // behind the sensor
  EXPECT_EQ(map.state(16, 10, 5), VoxelState::kUnknown);  // behind the return
  EXPECT_EQ(map.state(15, 11, 5), VoxelState::kUnknown);
  const VoxelStateCounts counts = map.CountStates();
  EXPECT_EQ(counts.occupied, 1);
  EXPECT_EQ(counts.free, 14);
}

// Scans through a voxel at the maximum clear it after exactly ceil((max - threshold) / -miss)
// scans; a voxel at the minimum becomes occupied after floor((threshold - min) / hit) + 1.
TEST(OccupancyMapTest, ClampingBoundsHowLongAVoxelRemembers) {
  const OccupancyMapOptions options = SmallOptions();
  OccupancyMap map(options);
  const Eigen::Vector3d sensor = CentreD(1, 10, 5);
  // A box face at voxel 10 of the row, seen for 20 scans: clamped at the maximum.
  for (int scan = 0; scan < 20; ++scan) Insert(&map, sensor, {Centre(10, 10, 5)});
  EXPECT_FLOAT_EQ(map.log_odds(10, 10, 5), options.log_odds_max);
  EXPECT_FLOAT_EQ(map.log_odds(5, 10, 5), options.log_odds_min);
  // The box is removed: the rays now return from voxel 18 behind it.
  const int scans_to_clear = static_cast<int>(
      std::ceil((options.log_odds_max - options.occupied_threshold_log_odds) /
                -options.log_odds_miss));
  ASSERT_EQ(scans_to_clear, 9);
  for (int scan = 1; scan <= scans_to_clear; ++scan) {
    std::vector<VoxelChange> changes;
    Insert(&map, sensor, {Centre(18, 10, 5)}, &changes);
    const bool cleared = scan == scans_to_clear;
    EXPECT_EQ(map.state(10, 10, 5), cleared ? VoxelState::kFree : VoxelState::kOccupied) << scan;
    // The change is reported in the scan it happens.
    bool reported = false;
    for (const VoxelChange& c : changes) {
      reported |= c.voxel == Eigen::Vector3i(10, 10, 5) && c.state == VoxelState::kFree;
    }
    EXPECT_EQ(reported, cleared) << scan;
  }
  // A box is added at voxel 5, seen free for 20 scans (at the minimum).
  const int scans_to_appear = static_cast<int>(std::floor(
                                  (options.occupied_threshold_log_odds - options.log_odds_min) /
                                  options.log_odds_hit)) + 1;
  ASSERT_EQ(scans_to_appear, 3);
  for (int scan = 1; scan <= scans_to_appear; ++scan) {
    Insert(&map, sensor, {Centre(5, 10, 5)});
    EXPECT_EQ(map.state(5, 10, 5),
              scan == scans_to_appear ? VoxelState::kOccupied : VoxelState::kFree) << scan;
  }
}

TEST(OccupancyMapTest, EachVoxelIsUpdatedOncePerScanAndAHitWins) {
  OccupancyMap map(SmallOptions());
  const Eigen::Vector3d sensor = CentreD(1, 10, 5);
  // Three returns on one line: the nearer ones' voxels lie on the farthest one's ray; two
  // returns in voxel 12; the rays share voxels 2..5.
  const std::vector<Eigen::Vector3f> points = {
      Centre(16, 10, 5), Centre(6, 10, 5), Centre(12, 10, 5),
      Centre(12, 10, 5) + Eigen::Vector3f(0.02f, 0.01f, -0.01f)};
  const ScanInsertSummary s = Insert(&map, sensor, points);
  EXPECT_EQ(s.num_voxels_hit, 3);
  EXPECT_FLOAT_EQ(map.log_odds(6, 10, 5), 0.85f);   // hit, not hit + miss
  EXPECT_FLOAT_EQ(map.log_odds(12, 10, 5), 0.85f);  // hit once for two returns
  EXPECT_FLOAT_EQ(map.log_odds(16, 10, 5), 0.85f);
  for (int ix = 1; ix < 16; ++ix) {
    if (ix == 6 || ix == 12) continue;
    EXPECT_FLOAT_EQ(map.log_odds(ix, 10, 5), -0.4f) << ix;  // missed once for up to 4 rays
  }
  EXPECT_EQ(s.num_voxels_missed, 13);
  EXPECT_GT(s.num_ray_steps, s.num_voxels_missed + s.num_voxels_hit);
}

TEST(OccupancyMapTest, ChangesAreExactlyTheStateDiff) {
  OccupancyMap map(SmallOptions());
  Rng rng(11);
  std::vector<VoxelChange> changes;
  int total_changes = 0;
  for (int scan = 0; scan < 40; ++scan) {
    const std::vector<std::uint8_t> before(map.states().begin(), map.states().end());
    // A sensor inside or outside the map, returns scattered in and around it.
    const Eigen::Vector3d sensor(rng.Uniform(-0.5, 2.5), rng.Uniform(-0.5, 2.5),
                                 rng.Uniform(0.0, 1.0));
    std::vector<Eigen::Vector3f> points;
    for (int k = 0; k < 300; ++k) {
      points.emplace_back(rng.Uniform(-0.3, 2.3), rng.Uniform(-0.3, 2.3), rng.Uniform(-0.2, 1.2));
    }
    changes.clear();
    changes.push_back({{0, 0, 0}, VoxelState::kUnknown});  // InsertScan appends
    const ScanInsertSummary s = Insert(&map, sensor, points, &changes);
    ASSERT_EQ(static_cast<int>(changes.size()), s.num_changes + 1);
    std::map<std::tuple<int, int, int>, VoxelState> listed;
    for (std::size_t c = 1; c < changes.size(); ++c) {
      const Eigen::Vector3i& v = changes[c].voxel;
      ASSERT_TRUE(listed.emplace(std::make_tuple(v.x(), v.y(), v.z()), changes[c].state).second)
          << "listed twice";
    }
    const GridGeometry3& g = map.geometry();
    int diff = 0;
    for (int iz = 0; iz < g.dims.z(); ++iz)
      for (int iy = 0; iy < g.dims.y(); ++iy)
        for (int ix = 0; ix < g.dims.x(); ++ix) {
          const std::int64_t i = g.Index(ix, iy, iz);
          if (before[i] == map.states()[i]) continue;
          ++diff;
          const auto it = listed.find({ix, iy, iz});
          ASSERT_NE(it, listed.end()) << "unlisted change";
          EXPECT_EQ(it->second, map.state(ix, iy, iz));
        }
    EXPECT_EQ(diff, s.num_changes);
    total_changes += diff;
  }
  EXPECT_GT(total_changes, 1000);
}

TEST(OccupancyMapTest, ReturnsOutsideTheBoundsClearOnlyTheirRaysInsidePart) {
  OccupancyMap map(SmallOptions());
  // Sensor outside on the -x side, return outside on the +x side: the whole row is free.
  const Eigen::Vector3d sensor(-0.5, 1.05, 0.55);
  const ScanInsertSummary s = Insert(&map, sensor, {Eigen::Vector3f(2.5f, 1.05f, 0.55f)});
  EXPECT_EQ(s.num_points_outside, 1);
  EXPECT_EQ(s.num_voxels_hit, 0);
  EXPECT_EQ(s.num_voxels_missed, 20);
  for (int ix = 0; ix < 20; ++ix) EXPECT_EQ(map.state(ix, 10, 5), VoxelState::kFree);
  // A return above the map (z > 1): no hit anywhere, its ray clears up to the top.
  Insert(&map, CentreD(10, 3, 2), {Eigen::Vector3f(1.05f, 0.35f, 1.6f)});
  for (int iz = 2; iz < 10; ++iz) EXPECT_EQ(map.state(10, 3, iz), VoxelState::kFree) << iz;
  EXPECT_EQ(map.CountStates().occupied, 0);
}

TEST(OccupancyMapTest, ReturnsBeyondTheClearingDistanceClearUpToItAndHitWithinTheHitRange) {
  OccupancyMapOptions options = SmallOptions();
  options.max_free_ray_length_m = 0.8;
  options.max_hit_range_m = 1.5;
  OccupancyMap map(options);
  const Eigen::Vector3d sensor(0.05, 1.05, 0.55);
  // One return at 1.9 m (beyond the hit range), one at 1.2 m (within it) in another row.
  const ScanInsertSummary s = Insert(&map, sensor, {Eigen::Vector3f(1.95f, 1.05f, 0.55f),
                                                    Eigen::Vector3f(1.25f, 1.05f, 0.65f)});
  EXPECT_EQ(s.num_points_beyond_range, 1);
  EXPECT_EQ(s.num_voxels_hit, 1);
  EXPECT_EQ(map.state(12, 10, 6), VoxelState::kOccupied);
  // Cleared from x 0.05 to 0.85: voxels 0..8; beyond, unknown.
  for (int ix = 0; ix < 20; ++ix) {
    EXPECT_EQ(map.state(ix, 10, 5), ix <= 8 ? VoxelState::kFree : VoxelState::kUnknown) << ix;
  }
}

TEST(OccupancyMapTest, NonFinitePointsAreSkippedAndCounted) {
  OccupancyMap map(SmallOptions());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const ScanInsertSummary s =
      Insert(&map, CentreD(1, 1, 1),
             {Eigen::Vector3f(nan, 0.5f, 0.5f), Centre(5, 1, 1), Eigen::Vector3f(0.5f, inf, 0.5f),
              Eigen::Vector3f(0.5f, 0.5f, -inf)});
  EXPECT_EQ(s.num_points, 4);
  EXPECT_EQ(s.num_points_skipped, 3);
  EXPECT_EQ(s.num_points_used, 1);
  EXPECT_EQ(s.num_voxels_hit, 1);
  EXPECT_EQ(map.state(5, 1, 1), VoxelState::kOccupied);
  // A NaN sensor origin throws and leaves the map unchanged.
  const std::vector<std::uint8_t> before(map.states().begin(), map.states().end());
  EXPECT_THROW(Insert(&map, Eigen::Vector3d(0.5, std::nan(""), 0.5), {Centre(9, 9, 1)}),
               std::invalid_argument);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), map.states().begin()));
}

TEST(OccupancyMapTest, SeedingAndResetReportTheirChanges) {
  OccupancyMap map(SmallOptions());
  std::vector<VoxelChange> changes;
  map.SetVoxel({3, 4, 5}, 10.0f, &changes);  // clamped to the maximum
  map.SetVoxel({3, 4, 6}, -1.0f, &changes);
  map.SetVoxel({3, 4, 6}, -1.5f, &changes);  // still free: no change
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_EQ(changes[0].voxel, Eigen::Vector3i(3, 4, 5));
  EXPECT_EQ(changes[0].state, VoxelState::kOccupied);
  EXPECT_EQ(changes[1].state, VoxelState::kFree);
  EXPECT_FLOAT_EQ(map.log_odds(3, 4, 5), 3.5f);
  EXPECT_FLOAT_EQ(map.log_odds(3, 4, 6), -1.5f);
  EXPECT_THROW(map.SetVoxel({20, 0, 0}, 1.0f, nullptr), std::invalid_argument);
  EXPECT_THROW(map.SetVoxel({0, -1, 0}, 1.0f, nullptr), std::invalid_argument);
  EXPECT_THROW(map.SetVoxel({0, 0, 0}, std::nanf(""), nullptr), std::invalid_argument);
  // A seeded voxel then takes scans as any other: 9 misses clear the clamped one.
  for (int scan = 0; scan < 9; ++scan) Insert(&map, CentreD(0, 4, 5), {Centre(8, 4, 5)});
  EXPECT_EQ(map.state(3, 4, 5), VoxelState::kFree);
  changes.clear();
  const VoxelStateCounts counts = map.CountStates();
  map.Reset(&changes);
  EXPECT_EQ(static_cast<std::int64_t>(changes.size()), counts.occupied + counts.free);
  for (const VoxelChange& c : changes) EXPECT_EQ(c.state, VoxelState::kUnknown);
  EXPECT_EQ(map.CountStates().unknown, 20 * 20 * 10);
  EXPECT_EQ(map.log_odds(3, 4, 5), 0.0f);
}

TEST(OccupancyMapTest, MarksStayCorrectWhenTheirCounterWraps) {
  OccupancyMap map(SmallOptions());
  const Eigen::Vector3d sensor = CentreD(1, 10, 5);
  // 40,000 scans (past the 32,767 of the 16-bit mark counter) alternating hit and pass.
  for (int scan = 0; scan < 40000; ++scan) {
    Insert(&map, sensor, {scan % 2 == 0 ? Centre(8, 10, 5) : Centre(3, 10, 5)});
  }
  // Voxel 3: hit in odd scans, missed in even ones: +0.85 - 0.4 per pair, clamped at 3.5.
  EXPECT_FLOAT_EQ(map.log_odds(3, 10, 5), 3.5f);
  // Voxel 8: hit in even scans only (untouched in odd ones).
  EXPECT_FLOAT_EQ(map.log_odds(8, 10, 5), 3.5f);
  // One scan with two returns, voxel 3 and 8: 3 is hit (not missed by 8's ray) exactly once.
  map.SetVoxel({3, 10, 5}, 0.0f, nullptr);
  Insert(&map, sensor, {Centre(8, 10, 5), Centre(3, 10, 5)});
  EXPECT_FLOAT_EQ(map.log_odds(3, 10, 5), 0.85f);
  EXPECT_FLOAT_EQ(map.log_odds(5, 10, 5), -2.0f);
}

TEST(OccupancyMapTest, InsertingAScanAllocatesNothingAfterWarmUp) {
  OccupancyMap map(SmallOptions());
  Rng rng(2);
  std::vector<Eigen::Vector3f> points;
  for (int k = 0; k < 500; ++k) {
    points.emplace_back(rng.Uniform(-0.5, 2.5), rng.Uniform(-0.5, 2.5), rng.Uniform(-0.2, 1.2));
  }
  std::vector<VoxelChange> changes;
  changes.reserve(4000);  // every voxel at most once
  map.InsertScan(Eigen::Vector3d(1.0, 1.0, 0.5), points, &changes);
  changes.clear();
  const testing::AllocationCounter counter;
  const ScanInsertSummary s = map.InsertScan(Eigen::Vector3d(0.7, 1.2, 0.4), points, &changes);
  EXPECT_EQ(counter.count(), 0);
  EXPECT_GT(s.num_changes, 0);
}

}  // namespace
}  // namespace topay
