#include "core/map/voxel_map_fields.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/random.h"
#include "core/map/scene_distance_fields.h"
#include "sim/scenes/benchmark_scene.h"
#include "tests/common/make_box.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

// A small map with both bands and small caps, so that windows are real parts of the grid.
VoxelMapFieldsOptions SmallOptions() {
  VoxelMapFieldsOptions options;
  options.bounds_W_m =
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.0, -0.8, 0.0), Eigen::Vector3d(1.4, 1.0, 0.8));
  options.resolution_m = 0.05;
  options.field_3d_cap_m = 0.3;
  options.base_resolution_m = 0.02;
  options.base_cap_m = 0.25;
  options.base_band = HeightBand{0.0, 0.155};
  options.base_upper_band = HeightBand{0.0, 0.45};
  options.base_upper_band_offset_m = 0.2;
  options.initial_state = VoxelState::kFree;
  return options;
}

int BitwiseDifferences(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return -1;
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0;
  return n;
}

double MaxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(double{a[i]} - b[i]));
  return m;
}

// The incremental fields against a full rebuild of a copy on the same voxels: bitwise equal,
// also the primary band (max difference exactly 0).
void ExpectEqualsFullRebuild(const VoxelMapFields& map, const std::string& where) {
  VoxelMapFields rebuilt = map;
  rebuilt.RebuildAll();
  EXPECT_EQ(BitwiseDifferences(map.field_3d().values(), rebuilt.field_3d().values()), 0) << where;
  EXPECT_EQ(MaxDifference(map.field_3d().values(), rebuilt.field_3d().values()), 0.0) << where;
  EXPECT_EQ(BitwiseDifferences(map.base_field_2d().values(), rebuilt.base_field_2d().values()), 0)
      << where;
  ASSERT_EQ(map.base_field_2d().primary_band() != nullptr,
            rebuilt.base_field_2d().primary_band() != nullptr);
  if (map.base_field_2d().primary_band()) {
    EXPECT_EQ(BitwiseDifferences(map.base_field_2d().primary_band()->values(),
                                 rebuilt.base_field_2d().primary_band()->values()),
              0)
        << where;
  }
}

// The changes setting every voxel of `box` (AddBox's rasterisation) to `state`.
std::vector<VoxelChange> BoxChanges(const GridGeometry3& g, const OrientedBox& box,
                                    VoxelState state) {
  OccupancyGrid3 grid(g);
  grid.AddBox(box);
  std::vector<VoxelChange> changes;
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix)
        if (grid.IsOccupied(ix, iy, iz)) changes.push_back({{ix, iy, iz}, state});
  return changes;
}

TEST(VoxelMapFieldsTest, IncrementalEqualsFullRebuildOnRandomAddsAndClears) {
  VoxelMapFields map(SmallOptions());
  const GridGeometry3& g = map.geometry();
  Rng rng(17);
  for (int step = 0; step < 40; ++step) {
    std::vector<VoxelChange> changes;
    const int kind = static_cast<int>(rng.UniformInt(0, 3));
    if (kind == 0) {
      // A box appears or goes away (low boxes touch both bands, tall ones the 3D field only).
      const OrientedBox box =
          MakeBox({rng.Uniform(-1.1, 1.5), rng.Uniform(-0.9, 1.1), rng.Uniform(0.0, 0.8)},
                  {rng.Uniform(0.05, 0.5), rng.Uniform(0.05, 0.5), rng.Uniform(0.05, 0.5)},
                  rng.Uniform(-3.0, 3.0));
      changes =
          BoxChanges(g, box, rng.Uniform01() < 0.6 ? VoxelState::kOccupied : VoxelState::kFree);
    } else if (kind == 1) {
      // Scattered voxels set and cleared (noise), with duplicates.
      for (int i = 0; i < 60; ++i) {
        const Eigen::Vector3i v(rng.UniformInt(0, g.dims.x() - 1),
                                rng.UniformInt(0, g.dims.y() - 1),
                                rng.UniformInt(0, g.dims.z() - 1));
        changes.push_back({v, rng.Uniform01() < 0.5 ? VoxelState::kOccupied : VoxelState::kFree});
        if (i % 10 == 0) changes.push_back({v, VoxelState::kFree});
      }
    } else if (kind == 2) {
      // The grid's edges and corners, both bands' layers.
      for (int i = 0; i < 20; ++i) {
        Eigen::Vector3i v(rng.UniformInt(0, g.dims.x() - 1), rng.UniformInt(0, g.dims.y() - 1),
                          rng.UniformInt(0, 9));
        const int axis = static_cast<int>(rng.UniformInt(0, 2));
        v(axis) = rng.Uniform01() < 0.5 ? 0 : g.dims(axis) - 1;
        changes.push_back({v, rng.Uniform01() < 0.7 ? VoxelState::kOccupied : VoxelState::kFree});
      }
    } else {
      // Clear a random slab of what is there (obstacles moving away).
      const int x0 = static_cast<int>(rng.UniformInt(0, g.dims.x() - 8));
      const int y0 = static_cast<int>(rng.UniformInt(0, g.dims.y() - 8));
      for (int iz = 0; iz < g.dims.z(); ++iz)
        for (int iy = y0; iy < y0 + 8; ++iy)
          for (int ix = x0; ix < x0 + 8; ++ix) changes.push_back({{ix, iy, iz}, VoxelState::kFree});
    }
    const VoxelMapUpdateSummary summary = map.ApplyChanges(changes);
    EXPECT_EQ(summary.num_changes, static_cast<int>(changes.size()));
    ExpectEqualsFullRebuild(map, "step " + std::to_string(step) + " kind " + std::to_string(kind));
  }
  EXPECT_GT(map.occupancy_3d().CountOccupied(), 0);
}

// A snapshot's states set at once give the fields the same changes applied one by one give.
TEST(VoxelMapFieldsTest, ResetStatesEqualsTheSameChangesApplied) {
  for (const UnknownVoxelPolicy policy : {UnknownVoxelPolicy::kFree, UnknownVoxelPolicy::kOccupied}) {
    VoxelMapFieldsOptions options = SmallOptions();
    options.unknown = policy;
    VoxelMapFields applied(options), reset(options);
    const GridGeometry3& g = applied.geometry();
    Rng rng(5);
    std::vector<VoxelChange> changes =
        BoxChanges(g, MakeBox({0.2, 0.1, 0.3}, {0.6, 0.4, 0.5}, 0.4), VoxelState::kOccupied);
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector3i v(rng.UniformInt(0, g.dims.x() - 1), rng.UniformInt(0, g.dims.y() - 1),
                              rng.UniformInt(0, g.dims.z() - 1));
      changes.push_back({v, rng.Uniform01() < 0.5 ? VoxelState::kFree : VoxelState::kOccupied});
    }
    applied.ApplyChanges(changes);
    reset.ResetStates(applied.states());
    EXPECT_EQ(BitwiseDifferences(applied.field_3d().values(), reset.field_3d().values()), 0);
    EXPECT_EQ(BitwiseDifferences(applied.base_field_2d().values(), reset.base_field_2d().values()), 0);
    EXPECT_TRUE(std::equal(applied.states().begin(), applied.states().end(), reset.states().begin()));
  }
  VoxelMapFields map(SmallOptions());
  std::vector<std::uint8_t> bad(map.states().begin(), map.states().end());
  bad[3] = 7;
  EXPECT_THROW(map.ResetStates(bad), std::invalid_argument);
  bad.pop_back();
  EXPECT_THROW(map.ResetStates(bad), std::invalid_argument);
}

TEST(VoxelMapFieldsTest, UpdatesOnlyWindowsNearTheChange) {
  VoxelMapFieldsOptions options = SmallOptions();
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -3, 0), Eigen::Vector3d(3, 3, 1.0));
  VoxelMapFields map(options);
  const std::vector<VoxelChange> changes =
      BoxChanges(map.geometry(), MakeBox({1.0, -1.0, 0.1}, {0.2, 0.2, 0.2}), VoxelState::kOccupied);
  const VoxelMapUpdateSummary summary = map.ApplyChanges(changes);
  EXPECT_EQ(summary.num_voxels_changed, static_cast<int>(changes.size()));
  EXPECT_EQ(summary.num_voxels_changed_3d, static_cast<int>(changes.size()));
  EXPECT_GT(summary.num_columns_changed, 0);
  EXPECT_EQ(summary.num_windows_3d, 1);
  EXPECT_GT(summary.num_cells_3d, 0);
  EXPECT_LT(summary.num_cells_3d, map.geometry().NumCells() / 5);
  EXPECT_LT(summary.num_cells_2d, 2 * map.base_geometry().NumCells() / 5);
  ExpectEqualsFullRebuild(map, "one box");
  // Far away the field still reads the cap; next to the box it is small.
  EXPECT_FLOAT_EQ(static_cast<float>(map.field_3d().Distance(Eigen::Vector3d(-2, 2, 0.5))),
                  static_cast<float>(options.field_3d_cap_m));
  // 0.05 m from the box's face (y = -0.9): the 3D zero level on the boundary voxels' centres
  // (half a voxel inside), the 2D field exact to the columns.
  EXPECT_NEAR(map.field_3d().Distance(Eigen::Vector3d(1.0, -0.85, 0.1)), 0.075, 0.03);
  EXPECT_NEAR(map.base_field_2d().Distance(Eigen::Vector2d(1.0, -0.85)), 0.05, 0.015);
  // The same changes again change nothing.
  const VoxelMapUpdateSummary again = map.ApplyChanges(changes);
  EXPECT_EQ(again.num_voxels_changed, 0);
  EXPECT_EQ(again.num_cells_3d, 0);
  EXPECT_EQ(again.num_cells_2d, 0);
}

TEST(VoxelMapFieldsTest, BandsAndPrimaryBand) {
  VoxelMapFields map(SmallOptions());
  const GridGeometry3& g = map.geometry();
  // A slab in the upper band only (z 0.3-0.4): lowers the 2D field by the offset's measure,
  // but the primary band (base band alone) does not see it.
  map.ApplyChanges(
      BoxChanges(g, MakeBox({0.0, 0.0, 0.35}, {0.3, 0.3, 0.1}), VoxelState::kOccupied));
  const SignedDistanceField2& field = map.base_field_2d();
  ASSERT_NE(field.primary_band(), nullptr);
  ASSERT_TRUE(field.offset_band().has_value());
  EXPECT_DOUBLE_EQ(field.offset_band()->offset_m, 0.2);
  const Eigen::Vector2d above(0.0, 0.0);
  EXPECT_NEAR(field.Distance(above), -0.15 + 0.2, 0.03);
  EXPECT_FLOAT_EQ(static_cast<float>(field.primary_band()->Distance(above)), 0.25f);
  // A post in the base band: both see it.
  map.ApplyChanges(BoxChanges(g, MakeBox({0.8, 0.5, 0.1}, {0.1, 0.1, 0.2}), VoxelState::kOccupied));
  EXPECT_LT(field.Distance(Eigen::Vector2d(0.8, 0.5)), 0.0);
  EXPECT_LT(field.primary_band()->Distance(Eigen::Vector2d(0.8, 0.5)), 0.0);
  ExpectEqualsFullRebuild(map, "bands");
  // A copy taken before an update keeps its values (copy on write of the primary band).
  const SignedDistanceField2 before = map.base_field_2d();
  map.ApplyChanges(BoxChanges(g, MakeBox({0.8, 0.5, 0.1}, {0.1, 0.1, 0.2}), VoxelState::kFree));
  EXPECT_LT(before.primary_band()->Distance(Eigen::Vector2d(0.8, 0.5)), 0.0);
  EXPECT_GT(map.base_field_2d().primary_band()->Distance(Eigen::Vector2d(0.8, 0.5)), 0.2);
  EXPECT_LT(before.Distance(Eigen::Vector2d(0.8, 0.5)), 0.0);
  ExpectEqualsFullRebuild(map, "cleared post");
}

TEST(VoxelMapFieldsTest, UnknownSpacePolicies) {
  for (UnknownVoxelPolicy policy : {UnknownVoxelPolicy::kFree, UnknownVoxelPolicy::kOccupied,
                                    UnknownVoxelPolicy::kOccupiedInBaseBands}) {
    VoxelMapFieldsOptions options = SmallOptions();
    options.unknown = policy;
    options.initial_state = VoxelState::kUnknown;
    VoxelMapFields map(options);
    const GridGeometry3& g = map.geometry();
    // Everything unknown.
    const std::int64_t expected_3d = policy == UnknownVoxelPolicy::kOccupied ? g.NumCells() : 0;
    EXPECT_EQ(map.occupancy_3d().CountOccupied(), expected_3d);
    const std::int64_t expected_2d =
        policy == UnknownVoxelPolicy::kFree ? 0 : map.base_columns().geometry().NumCells();
    EXPECT_EQ(map.base_columns().CountOccupied(), expected_2d);
    // Scan a region free: the fields open up there, equal to a full rebuild.
    std::vector<VoxelChange> seen;
    for (int iz = 0; iz < g.dims.z(); ++iz)
      for (int iy = 5; iy < 25; ++iy)
        for (int ix = 5; ix < 30; ++ix) seen.push_back({{ix, iy, iz}, VoxelState::kFree});
    map.ApplyChanges(seen);
    ExpectEqualsFullRebuild(map, "policy " + std::to_string(static_cast<int>(policy)));
    // 2.5 voxels (0.125 m) inside the seen region, in x.
    const Eigen::Vector3d p = g.CellCenter(7, 15, 8);
    const double d2 = map.base_field_2d().Distance(p.head<2>());
    if (policy == UnknownVoxelPolicy::kFree) {
      EXPECT_FLOAT_EQ(static_cast<float>(d2), 0.25f);  // the cap: nothing in the bands
    } else {
      EXPECT_NEAR(d2, 0.125, 0.015);  // the unknown columns block the base
    }
    // 3D: the nearest unknown voxel centre is 3 voxels away: (3 - 1/2 + 1/2) x 0.05 m.
    const double d3 = map.field_3d().Distance(p);
    if (policy == UnknownVoxelPolicy::kOccupied) {
      EXPECT_NEAR(d3, 0.15, 1e-6);
    } else {
      EXPECT_FLOAT_EQ(static_cast<float>(d3), 0.3f);
    }
  }
}

TEST(VoxelMapFieldsTest, BadInputGivesClearErrorsAndLeavesTheMapAsItWas) {
  VoxelMapFields map(SmallOptions());
  const std::vector<float> before = map.field_3d().values();
  const std::vector<VoxelChange> outside = {
      {{1, 1, 1}, VoxelState::kOccupied}, {{map.geometry().dims.x(), 0, 0}, VoxelState::kOccupied}};
  try {
    map.ApplyChanges(outside);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("change 1"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("outside the grid"), std::string::npos);
  }
  EXPECT_EQ(map.state(1, 1, 1), VoxelState::kFree);
  const std::vector<VoxelChange> negative = {{{0, -1, 0}, VoxelState::kOccupied}};
  EXPECT_THROW(map.ApplyChanges(negative), std::invalid_argument);
  const std::vector<VoxelChange> bad_state = {{{0, 0, 0}, static_cast<VoxelState>(7)}};
  EXPECT_THROW(map.ApplyChanges(bad_state), std::invalid_argument);
  EXPECT_EQ(BitwiseDifferences(before, map.field_3d().values()), 0);
  EXPECT_THROW(map.ChangeAt(Eigen::Vector3d(std::nan(""), 0, 0), VoxelState::kOccupied),
               std::invalid_argument);
  EXPECT_THROW(map.ChangeAt(Eigen::Vector3d(5, 0, 0.1), VoxelState::kOccupied),
               std::invalid_argument);
  const VoxelChange change =
      map.ChangeAt(Eigen::Vector3d(-0.97, -0.78, 0.01), VoxelState::kOccupied);
  EXPECT_EQ(change.voxel, Eigen::Vector3i(0, 0, 0));
  for (auto mutate : std::vector<void (*)(VoxelMapFieldsOptions*)>{
           [](VoxelMapFieldsOptions* o) { o->resolution_m = std::nan(""); },
           [](VoxelMapFieldsOptions* o) { o->field_3d_cap_m = 0.0; },
           [](VoxelMapFieldsOptions* o) { o->base_cap_m = -1.0; },
           [](VoxelMapFieldsOptions* o) { o->base_resolution_m = std::nan(""); },
           [](VoxelMapFieldsOptions* o) { o->base_upper_band_offset_m = std::nan(""); },
           [](VoxelMapFieldsOptions* o) {
             o->base_band = HeightBand{0.2, 0.1};
           },
           [](VoxelMapFieldsOptions* o) { o->tile_voxels = 0; },
           [](VoxelMapFieldsOptions* o) { o->bounds_W_m.max().x() = std::nan(""); }}) {
    VoxelMapFieldsOptions options = SmallOptions();
    mutate(&options);
    EXPECT_THROW(VoxelMapFields{options}, std::invalid_argument);
  }
  OccupancyGrid3 other(GridGeometry3{{0, 0, 0}, 0.05, {4, 4, 4}});
  EXPECT_THROW(map.ResetFrom(other), std::invalid_argument);
}

// Box-built options with an exact 3D field (margin sqrt(3) / 2 x the cell size) give this map,
// whose 3D field is an EDT one (sqrt(3) x it), an upper band raised by the difference; the
// rest is copied.
TEST(VoxelMapFieldsTest, OptionsFromAnExactArmFieldRaiseTheUpperBandByTheMarginsDifference) {
  SceneDistanceFieldsOptions box_options;
  box_options.resolution_m = 0.05;
  box_options.base_resolution_m = 0.01;
  box_options.base_exact_cap_m = 1.0;
  box_options.base_upper_band = HeightBand{0.0, 0.535};
  box_options.base_upper_band_offset_m = 0.2;
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 1));
  const VoxelMapFieldsOptions edt = VoxelMapFieldsOptionsFrom(box_options, bounds);
  ASSERT_TRUE(edt.base_upper_band.has_value());
  EXPECT_DOUBLE_EQ(edt.base_upper_band->z_max_m, 0.535);
  box_options.arm_exact_cap_m = 1.0;
  const VoxelMapFieldsOptions exact = VoxelMapFieldsOptionsFrom(box_options, bounds);
  ASSERT_TRUE(exact.base_upper_band.has_value());
  EXPECT_NEAR(exact.base_upper_band->z_max_m, 0.535 + 0.5 * std::sqrt(3.0) * 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(exact.base_upper_band->z_min_m, 0.0);
  EXPECT_DOUBLE_EQ(exact.base_upper_band_offset_m, 0.2);
  EXPECT_DOUBLE_EQ(exact.base_resolution_m, 0.01);
}

// A Tables benchmark room rasterised into voxels (OccupancyGrid3::AddBox) against the fields
// BuildSceneDistanceFields builds from its boxes at the planner's settings.
TEST(VoxelMapFieldsTest, TablesSceneAgreesWithTheBoxFieldsWithinTheMargins) {
  const Scene scene = GenerateTablesScene(4).scene;
  SceneDistanceFieldsOptions box_options;
  box_options.resolution_m = 0.05;
  box_options.base_resolution_m = 0.02;
  box_options.base_exact_cap_m = 1.0;
  box_options.base_band = HeightBand{0.0, 0.155};
  box_options.base_upper_band = HeightBand{0.0, 0.62};
  box_options.base_upper_band_offset_m = 0.2;
  const VoxelMapFieldsOptions options = VoxelMapFieldsOptionsFrom(box_options, scene.bounds_W_m);
  VoxelMapFields map(options);
  OccupancyGrid3 voxels(map.geometry());
  for (const OrientedBox& box : scene.boxes) voxels.AddBox(box);
  map.ResetFrom(voxels);
  const SceneDistanceFields boxes = BuildSceneDistanceFields(scene, box_options);

  // 3D: the same voxels, so the same values, clamped at the cap (bitwise).
  const double cap3 = options.field_3d_cap_m;
  ASSERT_EQ(boxes.field_3d.values().size(), map.field_3d().values().size());
  int differences_3d = 0;
  for (std::size_t i = 0; i < boxes.field_3d.values().size(); ++i) {
    const float expected =
        std::clamp(boxes.field_3d.values()[i], static_cast<float>(-cap3), static_cast<float>(cap3));
    differences_3d += map.field_3d().values()[i] != expected;
  }
  EXPECT_EQ(differences_3d, 0);
  EXPECT_DOUBLE_EQ(map.field_3d().exactness_margin_m(), boxes.field_3d.exactness_margin_m());

  // 2D: never above the exact footprint field; where free, at most one column diagonal below
  // the exact field of the bands widened to whole voxel layers.
  const GridGeometry3& g = map.geometry();
  auto widened = [&g](const HeightBand& band) {
    const CellRange layers =
        CellsOverlapping(band.z_min_m, band.z_max_m, g.origin_W_m.z(), g.resolution_m, g.dims.z());
    return HeightBand{g.origin_W_m.z() + layers.begin * g.resolution_m,
                      g.origin_W_m.z() + layers.end * g.resolution_m};
  };
  SceneDistanceFieldsOptions widened_options = box_options;
  widened_options.base_band = widened(box_options.base_band);
  widened_options.base_upper_band = widened(*box_options.base_upper_band);
  const SceneDistanceFields widened_boxes = BuildSceneDistanceFields(scene, widened_options);
  const double diagonal = std::sqrt(2.0) * g.resolution_m;
  const double offset = options.base_upper_band_offset_m;
  const SignedDistanceField2& v = map.base_field_2d();
  ASSERT_EQ(v.values().size(), boxes.base_field_2d.values().size());
  ASSERT_NE(v.primary_band(), nullptr);
  int above = 0, too_low = 0, primary_above = 0, primary_too_low = 0, free_cells = 0;
  for (std::size_t i = 0; i < v.values().size(); ++i) {
    const double lowered = v.values()[i], primary = v.primary_band()->values()[i];
    const double b_primary =
        std::max<double>(boxes.base_field_2d.primary_band()->values()[i], -1.0);
    const double b_lowered = std::max<double>(boxes.base_field_2d.values()[i], -1.0);
    above += lowered > b_lowered + 1e-6;
    primary_above += primary > b_primary + 1e-6;
    if (primary > 0.0) {
      primary_too_low +=
          primary < widened_boxes.base_field_2d.primary_band()->values()[i] - diagonal - 1e-6;
    }
    if (lowered > offset) {
      ++free_cells;
      too_low += lowered < widened_boxes.base_field_2d.values()[i] - diagonal - 1e-6;
    }
  }
  EXPECT_EQ(above, 0);
  EXPECT_EQ(primary_above, 0);
  EXPECT_EQ(too_low, 0);
  EXPECT_EQ(primary_too_low, 0);
  EXPECT_GT(free_cells, static_cast<int>(v.values().size() / 4));
  EXPECT_DOUBLE_EQ(v.exactness_margin_m(), boxes.base_field_2d.exactness_margin_m());

  // An update on the room (a box appears beside a table, then goes) equals a full rebuild.
  const OrientedBox appearing = MakeBox({1.0, 1.0, 0.3}, {0.5, 0.4, 0.6}, 0.3);
  map.ApplyChanges(BoxChanges(g, appearing, VoxelState::kOccupied));
  ExpectEqualsFullRebuild(map, "box appears in Tables");
  map.ApplyChanges(BoxChanges(g, appearing, VoxelState::kFree));
  ExpectEqualsFullRebuild(map, "box goes in Tables");
}

}  // namespace
}  // namespace topay
