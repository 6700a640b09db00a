// The candidate base paths of a plan as a PLANNER_PATHS message (procs/planner/paths_message.h):
// every base path in order, and the one the chosen trajectory follows.

#include "procs/planner/paths_message.h"

#include <gtest/gtest.h>

#include "topay_msgs/checked_decode.h"

namespace topay::planner {
namespace {

WholeBodyPlanResult TwoPathsResult() {
  WholeBodyPlanResult r;
  BasePath left, right;
  left.waypoints_W_m = {{0, 0}, {1, 1}, {2, 0}};
  left.length_m = 2.83;
  right.waypoints_W_m = {{0, 0}, {2, 0}};
  right.length_m = 2.0;
  right.source = BasePathSource::kJumpPointSearch;
  r.front_end.base_paths = {left, right};
  FrontEndPath along_right;
  along_right.path.base_path_index = 1;
  r.front_end.paths = {along_right};
  r.candidates.resize(1);
  r.candidates[0].path_index = 0;
  return r;
}

TEST(PathsMessage, NamesTheBaseStandingStillAsSuch) {
  WholeBodyPlanResult r = TwoPathsResult();
  r.front_end.base_paths[0].source = BasePathSource::kStanding;
  const planner_paths_t msg = ToPathsMessage(r, 123, 11, 7);
  ASSERT_EQ(msg.num_paths, 2);
  EXPECT_EQ(msg.source[0], "standing");
  EXPECT_EQ(msg.source[1], "jps");
}

TEST(PathsMessage, CarriesEveryBasePathAndTheChosenOne) {
  WholeBodyPlanResult r = TwoPathsResult();
  r.chosen = 0;
  const planner_paths_t msg = ToPathsMessage(r, 123, 11, 7);
  EXPECT_EQ(msg.utime, 123);
  EXPECT_EQ(msg.goal_id, 11);
  EXPECT_EQ(msg.trajectory_id, 7);
  ASSERT_EQ(msg.num_paths, 2);
  EXPECT_EQ(msg.chosen, 1);
  EXPECT_EQ(msg.path_points, (std::vector<std::int32_t>{3, 2}));
  ASSERT_EQ(msg.num_points, 5);
  EXPECT_DOUBLE_EQ(msg.y_m[1], 1.0);  // path 0's second point
  EXPECT_DOUBLE_EQ(msg.x_m[4], 2.0);  // path 1's last point
  EXPECT_DOUBLE_EQ(msg.length_m[0], 2.83);
  EXPECT_EQ(msg.source[0], "topological_prm");
  EXPECT_EQ(msg.source[1], "jps");
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  std::string error;
  EXPECT_TRUE(CheckedDecode<planner_paths_t>(bytes.data(), bytes.size(), &error).has_value()) << error;
}

TEST(PathsMessage, ChoosesNoneWhenThePlanFailed) {
  const WholeBodyPlanResult r = TwoPathsResult();  // chosen = -1
  const planner_paths_t msg = ToPathsMessage(r, 1, 2, 0);
  EXPECT_EQ(msg.chosen, -1);
  EXPECT_EQ(msg.trajectory_id, 0);
  EXPECT_EQ(msg.num_paths, 2);
}

}  // namespace
}  // namespace topay::planner
