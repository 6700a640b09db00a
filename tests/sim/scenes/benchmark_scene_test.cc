#include "sim/scenes/benchmark_scene.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/geometry/primitive_box_distance.h"
#include "sim/scenes/scene_json.h"

namespace topay {
namespace {

int Count(const GeneratedScene& scene, BoxRole role) {
  return static_cast<int>(std::count(scene.roles.begin(), scene.roles.end(), role));
}

bool OnMicroGrid(double value) { return std::abs(value * 1e6 - std::round(value * 1e6)) < 1e-6; }

double Bottom(const OrientedBox& box) { return box.center_W_m.z() - 0.5 * box.size_m.z(); }

void ExpectInsideRoom(const GeneratedScene& generated) {
  const RoomOptions room;
  const double inner = 0.5 * room.size_x_m - room.wall_thickness_m;
  for (std::size_t i = 0; i < generated.scene.boxes.size(); ++i) {
    const Eigen::AlignedBox3d bounds = generated.scene.boxes[i].WorldBounds();
    EXPECT_TRUE(generated.scene.bounds_W_m.contains(bounds)) << "box " << i;
    if (generated.roles[i] == BoxRole::kWall) continue;
    EXPECT_GE(bounds.min().x(), -inner) << "box " << i;
    EXPECT_GE(bounds.min().y(), -inner) << "box " << i;
    EXPECT_LE(bounds.max().x(), inner) << "box " << i;
    EXPECT_LE(bounds.max().y(), inner) << "box " << i;
  }
}

void ExpectGroundedBoxesInRange(const GeneratedScene& generated) {
  for (std::size_t i = 0; i < generated.scene.boxes.size(); ++i) {
    if (generated.roles[i] != BoxRole::kGroundedBox) continue;
    const OrientedBox& box = generated.scene.boxes[i];
    EXPECT_NEAR(Bottom(box), 0.0, 1e-6);
    EXPECT_GE(box.size_m.x(), 0.2 - 1e-6);
    EXPECT_LE(box.size_m.x(), 0.8 + 1e-6);
    EXPECT_GE(box.size_m.y(), 0.2 - 1e-6);
    EXPECT_LE(box.size_m.y(), 0.8 + 1e-6);
    EXPECT_GE(box.size_m.z(), 0.4 - 1e-6);
    EXPECT_LE(box.size_m.z(), 1.5 + 1e-6);
  }
}

TEST(BenchmarkSceneTest, CuboidsCountsAndSizes) {
  const GeneratedScene generated = GenerateCuboidsScene(42);
  const Scene& scene = generated.scene;
  ASSERT_EQ(generated.roles.size(), scene.boxes.size());
  EXPECT_EQ(scene.kind, "cuboids");
  EXPECT_EQ(scene.seed, 42u);
  EXPECT_EQ(scene.boxes.size(), 4u + 80u + 80u);
  EXPECT_EQ(Count(generated, BoxRole::kWall), 4);
  EXPECT_EQ(Count(generated, BoxRole::kGroundedBox), 80);
  EXPECT_EQ(Count(generated, BoxRole::kFloatingCube), 80);
  ExpectGroundedBoxesInRange(generated);
  double min_yaw = 10.0, max_yaw = -10.0;
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const OrientedBox& box = scene.boxes[i];
    if (generated.roles[i] == BoxRole::kFloatingCube) {
      EXPECT_EQ(box.size_m.x(), box.size_m.y());
      EXPECT_EQ(box.size_m.x(), box.size_m.z());
      EXPECT_GE(box.size_m.x(), 0.3 - 1e-6);
      EXPECT_LE(box.size_m.x(), 0.6 + 1e-6);
      EXPECT_GE(Bottom(box), 0.4 - 1e-6);
      EXPECT_LE(Bottom(box), 0.8 + 1e-6);
    }
    if (generated.roles[i] == BoxRole::kWall) {
      EXPECT_NEAR(box.size_m.z(), 1.0, 1e-12);
      EXPECT_NEAR(box.size_m.maxCoeff(), 20.0, 0.21);
    } else {
      min_yaw = std::min(min_yaw, box.yaw_rad);
      max_yaw = std::max(max_yaw, box.yaw_rad);
    }
    EXPECT_GE(box.yaw_rad, -M_PI);
    EXPECT_LE(box.yaw_rad, M_PI);
  }
  EXPECT_LT(min_yaw, -2.5);  // yaw spread over [-pi, pi)
  EXPECT_GT(max_yaw, 2.5);
  ExpectInsideRoom(generated);
  EXPECT_TRUE(scene.bounds_W_m.isApprox(
      Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6))));
}

TEST(BenchmarkSceneTest, TablesCountsAndStructure) {
  const GeneratedScene generated = GenerateTablesScene(43);
  const Scene& scene = generated.scene;
  EXPECT_EQ(scene.kind, "tables");
  // 40 groups of 1-4 tables: between 40 and 160 tables, and not all of one size.
  EXPECT_GE(generated.num_tables, 40);
  EXPECT_LE(generated.num_tables, 160);
  EXPECT_GT(generated.num_tables, 60);
  EXPECT_LT(generated.num_tables, 140);
  EXPECT_EQ(Count(generated, BoxRole::kTableTop), generated.num_tables);
  EXPECT_EQ(Count(generated, BoxRole::kTableLeg), 4 * generated.num_tables);
  EXPECT_EQ(Count(generated, BoxRole::kGroundedBox), 80);
  EXPECT_EQ(Count(generated, BoxRole::kWall), 4);
  EXPECT_EQ(scene.boxes.size(), 4u + 5u * generated.num_tables + 80u);
  ExpectGroundedBoxesInRange(generated);
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const OrientedBox& box = scene.boxes[i];
    if (generated.roles[i] == BoxRole::kTableTop) {
      EXPECT_NEAR(box.size_m.z(), 0.05, 1e-6);
      const double top = box.center_W_m.z() + 0.5 * box.size_m.z();
      EXPECT_GE(top, 0.5 - 1e-6);
      EXPECT_LE(top, 1.0 + 1e-6);
      EXPECT_GE(box.size_m.head<2>().minCoeff(), 0.75 - 1e-6);
      EXPECT_LE(box.size_m.head<2>().maxCoeff(), 1.25 + 1e-6);
      // Its four legs follow it, reach from the floor to its lower face, at its corners.
      for (std::size_t k = i + 1; k <= i + 4; ++k) {
        ASSERT_EQ(generated.roles[k], BoxRole::kTableLeg);
        const OrientedBox& leg = scene.boxes[k];
        EXPECT_NEAR(Bottom(leg), 0.0, 2e-6);
        EXPECT_NEAR(leg.center_W_m.z() + 0.5 * leg.size_m.z(), Bottom(box), 2e-6);
        EXPECT_NEAR(leg.size_m.x(), 0.05, 1e-6);
        const Eigen::Vector3d p_B = box.ToBoxFrame(leg.center_W_m);
        EXPECT_NEAR(std::abs(p_B.x()), 0.5 * box.size_m.x() - 0.025, 3e-6);
        EXPECT_NEAR(std::abs(p_B.y()), 0.5 * box.size_m.y() - 0.025, 3e-6);
      }
    }
  }
  ExpectInsideRoom(generated);
}

TEST(BenchmarkSceneTest, EveryNumberOnTheMicroGrid) {
  for (const SceneKind kind : {SceneKind::kCuboids, SceneKind::kTables}) {
    const GeneratedScene generated = GenerateBenchmarkScene(kind, 5);
    for (const OrientedBox& box : generated.scene.boxes) {
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(OnMicroGrid(box.center_W_m(i)));
        EXPECT_TRUE(OnMicroGrid(box.size_m(i)));
      }
      EXPECT_TRUE(OnMicroGrid(box.yaw_rad));
    }
  }
}

TEST(BenchmarkSceneTest, KeepOutRegionsAreRespected) {
  KeepOutRegions keep_out;
  keep_out.cylinders.push_back({Eigen::Vector2d(-3.0, 2.0), 1.8, 0.0, 1.6});
  keep_out.cylinders.push_back({Eigen::Vector2d(4.0, -4.0), 1.5, 0.0, 1.6});
  OrientedBox box;
  box.center_W_m = {3.0, 5.0, 0.8};
  box.size_m = {3.0, 2.0, 1.6};
  box.yaw_rad = 0.5;
  keep_out.boxes.push_back(box);
  for (const SceneKind kind : {SceneKind::kCuboids, SceneKind::kTables}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const GeneratedScene generated = GenerateBenchmarkScene(kind, seed, keep_out);
      const GeneratedScene unconstrained = GenerateBenchmarkScene(kind, seed);
      int inside_without = 0;
      for (std::size_t i = 4; i < generated.scene.boxes.size(); ++i) {
        EXPECT_TRUE(keep_out.Admits(generated.scene.boxes[i]));
      }
      for (std::size_t i = 4; i < unconstrained.scene.boxes.size(); ++i) {
        inside_without += !keep_out.Admits(unconstrained.scene.boxes[i]);
      }
      EXPECT_GT(inside_without, 0);  // the regions matter for this seed
      if (kind == SceneKind::kCuboids) {
        EXPECT_EQ(generated.scene.boxes.size(), 164u);
      }
    }
  }
}

TEST(BenchmarkSceneTest, SameSeedSameBytesDifferentSeedDifferentBytes) {
  for (const SceneKind kind : {SceneKind::kCuboids, SceneKind::kTables}) {
    const GeneratedScene a = GenerateBenchmarkScene(kind, 1234);
    const GeneratedScene b = GenerateBenchmarkScene(kind, 1234);
    const GeneratedScene c = GenerateBenchmarkScene(kind, 1235);
    EXPECT_EQ(SceneToJson(a.scene, &a.roles), SceneToJson(b.scene, &b.roles));
    EXPECT_NE(SceneToJson(a.scene, &a.roles), SceneToJson(c.scene, &c.roles));
  }
}

TEST(BenchmarkSceneTest, ImpossibleRequestsThrow) {
  KeepOutRegions everywhere;
  everywhere.cylinders.push_back({Eigen::Vector2d::Zero(), 20.0, 0.0, 2.0});
  EXPECT_THROW(GenerateCuboidsScene(1, everywhere), std::runtime_error);
  CuboidsOptions options;
  options.grounded.footprint_min_m = 0.9;  // min > max
  EXPECT_THROW(GenerateCuboidsScene(1, {}, options), std::invalid_argument);
  options = {};
  options.floating.count = -1;
  EXPECT_THROW(GenerateCuboidsScene(1, {}, options), std::invalid_argument);
  TablesOptions tables;
  tables.tables.leg_width_m = 0.5;
  EXPECT_THROW(GenerateTablesScene(1, {}, tables), std::invalid_argument);
  tables = {};
  tables.room.size_x_m = 0.1;
  EXPECT_THROW(GenerateTablesScene(1, {}, tables), std::invalid_argument);
}

}  // namespace
}  // namespace topay
