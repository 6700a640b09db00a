// BackgroundPlacement: the attempt's result is PlaceRouteBox's on the same inputs (and the
// generator comes back where the direct call leaves it), one attempt at a time, a result taken
// once, bad options rethrown where the result is taken, and a running attempt waited for on
// destruction.

#include "procs/director/background_placement.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "core/io/robot_loader.h"

namespace topay::director {
namespace {

class BackgroundPlacementTest : public testing::Test {
 protected:
  BackgroundPlacementTest() {
    room_.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 1.6));
    for (int i = 0; i <= 400; ++i) route_.path_W_m.emplace_back(-4.0 + 0.02 * i, 0.0);  // 8 m along x
    route_.robot_index = 0;
    route_.p_WR_m = route_.path_W_m.front();
  }
  // One attempt from a generator of seed 1, waited for.
  void StartAndWait(BackgroundPlacement* placement, const RouteBoxOptions& options) {
    placement->Start(PlacementTag{}, route_, room_, kinematics_, options, Rng(1));
    placement->Wait();
  }
  RobotModel model_ = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                     std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  Scene room_;
  RouteQuery route_;
};

TEST_F(BackgroundPlacementTest, TheResultAndTheDrawsAreThoseOfTheDirectCall) {
  BackgroundPlacement placement;
  EXPECT_FALSE(placement.busy());
  EXPECT_FALSE(placement.TakeIfDone()) << "nothing started";
  const RouteBoxOptions options;
  placement.Start(PlacementTag{7, 2}, route_, room_, kinematics_, options, Rng(5));
  EXPECT_TRUE(placement.busy());
  placement.Wait();
  const std::optional<PlacementResult> result = placement.TakeIfDone();
  ASSERT_TRUE(result);
  EXPECT_FALSE(placement.busy());
  EXPECT_FALSE(placement.TakeIfDone()) << "taken once";
  EXPECT_EQ(result->tag.trajectory_id, 7);
  EXPECT_EQ(result->tag.event_index, 2u);
  Rng direct_rng(5);
  const std::optional<RouteBox> direct = PlaceRouteBox(route_, room_, kinematics_, options, &direct_rng);
  ASSERT_TRUE(direct);
  ASSERT_TRUE(result->box);
  EXPECT_EQ(result->box->path_index, direct->path_index);
  EXPECT_EQ(result->box->box.size_m, direct->box.size_m);
  Rng after = result->rng;
  EXPECT_EQ(after.Uniform(0.0, 1.0), direct_rng.Uniform(0.0, 1.0)) << "the generator comes back advanced";
}

TEST_F(BackgroundPlacementTest, OneAttemptAtATime) {
  BackgroundPlacement placement;
  placement.Start(PlacementTag{}, route_, room_, kinematics_, RouteBoxOptions{}, Rng(1));
  EXPECT_THROW(placement.Start(PlacementTag{}, route_, room_, kinematics_, RouteBoxOptions{}, Rng(1)),
               std::logic_error);
  placement.Wait();
  EXPECT_THROW(placement.Start(PlacementTag{}, route_, room_, kinematics_, RouteBoxOptions{}, Rng(1)),
               std::logic_error)
      << "a finished result not taken yet";
  ASSERT_TRUE(placement.TakeIfDone());
  StartAndWait(&placement, RouteBoxOptions{});
  EXPECT_TRUE(placement.TakeIfDone());
}

TEST_F(BackgroundPlacementTest, EveryDrawRejectedIsAResultWithoutABox) {
  RouteBoxOptions options;
  options.min_robot_distance_m = 50.0;
  BackgroundPlacement placement;
  StartAndWait(&placement, options);
  const std::optional<PlacementResult> result = placement.TakeIfDone();
  ASSERT_TRUE(result);
  EXPECT_FALSE(result->box);
}

TEST_F(BackgroundPlacementTest, BadOptionsAreRethrownWhereTheResultIsTaken) {
  RouteBoxOptions options;
  options.tries = 0;
  BackgroundPlacement placement;
  StartAndWait(&placement, options);
  EXPECT_THROW(placement.TakeIfDone(), std::invalid_argument);
  EXPECT_FALSE(placement.busy());
}

TEST_F(BackgroundPlacementTest, DestructionWaitsForARunningAttempt) {
  // The attempt reads the kinematics: they must outlive it, and the destructor waits.
  auto placement = std::make_unique<BackgroundPlacement>();
  placement->Start(PlacementTag{}, route_, room_, kinematics_, RouteBoxOptions{}, Rng(1));
  placement.reset();
  SUCCEED() << "no use after free under ASan / TSan";
}

}  // namespace
}  // namespace topay::director
