// The trajectory being followed at a time: active from max(start, publication), newest in
// the log wins; switches are the activations that happen.

#include "tools/report/active_trajectory.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"
#include "tools/report/run_log.h"

namespace topay::report {
namespace {

LoggedTrajectory Logged(std::int64_t id, double published_s, double start_s) {
  std::string error;
  msgs::PolyTrajectory poly = *msgs::FromMessage(test::TrajectoryMessage(id, published_s, start_s), &error);
  return {poly, test::SmoothTrajectory()};
}

TEST(ActiveTrajectory, ActiveFromTheLaterOfStartAndPublicationNewestWins) {
  const std::vector<LoggedTrajectory> t = {Logged(1, 0.0, 1.0), Logged(2, 2.0, 1.5), Logged(3, 2.5, 4.0)};
  EXPECT_EQ(ActivationUtime(t[0]), test::At(1.0));
  EXPECT_EQ(ActivationUtime(t[1]), test::At(2.0));  // published after its start
  EXPECT_FALSE(ActiveTrajectoryAt(t, test::At(0.99)).has_value());
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(1.0)), 0u);
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(1.9)), 0u);
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(2.0)), 1u);
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(3.9)), 1u);  // 3 is pending until 4 s
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(4.0)), 2u);
  const std::vector<std::int64_t> switches = {test::At(1.0), test::At(2.0), test::At(4.0)};
  EXPECT_EQ(TrajectorySwitchUtimes(t), switches);
}

TEST(ActiveTrajectory, ASupersededPendingTrajectoryNeverSwitchesIn) {
  // 2 waits for 5 s but 3 (newer) is active from 3 s: 2 never becomes active.
  const std::vector<LoggedTrajectory> t = {Logged(1, 0.0, 0.0), Logged(2, 1.0, 5.0), Logged(3, 3.0, 3.0)};
  EXPECT_EQ(ActiveTrajectoryAt(t, test::At(6.0)), 2u);
  const std::vector<std::int64_t> switches = {test::At(0.0), test::At(3.0)};
  EXPECT_EQ(TrajectorySwitchUtimes(t), switches);
}

}  // namespace
}  // namespace topay::report
