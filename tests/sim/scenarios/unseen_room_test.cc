// The unseen Tables room is the room topay-sim makes for `--scene tables --seed N` with its
// keep-out radius around the start.

#include "sim/scenarios/unseen_room.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "sim/scenes/scene_json.h"
#include "sim/world/scene_source.h"

namespace topay {
namespace {

Scene SimulatorRoom(std::uint64_t seed, double keep_out_radius_m) {
  KeepOutRegions keep_out;
  VerticalCylinder start;
  start.radius_m = keep_out_radius_m;
  start.height_m = 3.0;
  keep_out.cylinders.push_back(start);
  return sim::LoadScene(*sim::ParseSceneArgument("tables", seed), keep_out);
}

TEST(UnseenTablesRoom, IsTheSimulatorsRoom) {
  for (const std::uint64_t seed : {1, 3}) {
    const GeneratedScene room = UnseenTablesRoom(seed, 1.2);
    EXPECT_EQ(SceneToJson(room.scene), SceneToJson(SimulatorRoom(seed, 1.2))) << "seed " << seed;
    EXPECT_EQ(room.roles.size(), room.scene.boxes.size());
  }
}

TEST(UnseenTablesRoom, NothingNearTheStart) {
  const GeneratedScene room = UnseenTablesRoom(2, 1.5);
  for (const OrientedBox& box : room.scene.boxes) {
    EXPECT_GE(SignedDistanceToFootprint(box, Eigen::Vector2d::Zero()), 1.5 - 1e-9);
  }
}

TEST(UnseenTablesRoom, BadRadiusThrows) {
  EXPECT_THROW(UnseenTablesRoom(1, -1.0), std::invalid_argument);
  EXPECT_THROW(UnseenTablesRoom(1, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace topay
