#include "core/planning/parallel_acquisition.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <limits>

#include "tests/common/make_box.h"
#include "tests/common/sanitizer_build.h"
#include "tests/core/planning/rrt_test_world.h"

namespace topay {
namespace {

using testing::RrtTestWorld;
using Clock = std::chrono::steady_clock;

/// A corridor along x with a slab at x in [2.5, 3.5], 0.85 m high: the upright arm must fold
/// under it, so no path reaches the cost lower bound and the anytime search never ends early.
Scene SlabCorridor() {
  Scene scene;
  scene.bounds_W_m =
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.5, -1.5, 0.0), Eigen::Vector3d(7.5, 1.5, 1.6));
  scene.kind = "corridor with a low slab";
  scene.boxes.push_back(MakeBox({3.0, 1.15, 0.5}, {9.0, 0.1, 1.0}));
  scene.boxes.push_back(MakeBox({3.0, -1.15, 0.5}, {9.0, 0.1, 1.0}));
  scene.boxes.push_back(MakeBox({3.0, 0.0, 0.875}, {1.0, 2.2, 0.05}));
  return scene;
}

struct AcquisitionWorld {
  AcquisitionWorld()
      : world(SlabCorridor()),
        validity(world.kinematics, world.fields.base_field_2d, world.fields.field_3d) {
    q_start = Eigen::VectorXd::Zero(world.model.num_joints());
    q_goal = q_start;
    q_goal(0) = 1.0;
    for (int j = 0; j < 2; ++j) {
      ArmJob job;
      job.base_path.waypoints_W_m = {{0.0, 0.0}, {6.0, 0.0}};
      job.base_path.length_m = 6.0;
      job.base_path.homotopy_class = j;
      job.base_path_index = j;
      job.base_sequence =
          DiscreteSE2(job.base_path.waypoints_W_m, 0.0, 0.0, world.model.base_limits);
      job.seed = 11 + j;
      jobs.push_back(std::move(job));
    }
  }
  RrtTestWorld world;
  WholeBodyValidity validity;
  Eigen::VectorXd q_start, q_goal;
  std::vector<ArmJob> jobs;
};

// Anytime jobs (10 s budget, no reachable cost bound) run until the improvement window,
// which starts at the first solution of any job (not when a job returns), then all are
// cancelled and return their best paths.
TEST(ParallelAcquisitionTest, WindowStartsAtTheFirstSolutionOfAnyJob) {
  const AcquisitionWorld w;
  ParallelAcquisitionOptions options;
  options.rrt.time_budget_s = 10.0;
  ASSERT_FALSE(options.rrt.stop_at_first_solution);
  std::atomic<int> caller_calls{0};
  options.rrt.on_first_solution = [&caller_calls](double) { ++caller_calls; };
  // Long enough for the other job to find its first solution too (slower in sanitizer builds).
  options.improvement_window_s = 0.03 * testing::kBuildSlowdown;
  options.budget_s = std::numeric_limits<double>::infinity();
  options.num_workers = 2;
  const Clock::time_point t0 = Clock::now();
  const ParallelAcquisitionResult result =
      AcquireWholeBodyPaths(w.jobs, w.q_start, w.q_goal, w.validity, options, t0);
  const double window_ms = 1e3 * options.improvement_window_s;
  std::cout << "first solution at " << result.first_success_ms << " ms, stage " << result.wall_ms
            << " ms\n";
  ASSERT_TRUE(std::isfinite(result.first_success_ms));
  ASSERT_EQ(result.jobs.size(), 2u);
  ASSERT_EQ(result.paths.size(), 2u);
  EXPECT_EQ(caller_calls.load(), 2);  // the caller's callback is chained, once per job
  for (const ArmJobReport& job : result.jobs) {
    EXPECT_EQ(job.status, ArmRrtStarStatus::kSuccess) << job.message;
    EXPECT_TRUE(job.stats.cancelled);
    // Each job ran on past its first solution, until the window closed.
    EXPECT_GE(job.finished_at_ms, result.first_success_ms + window_ms - 1e-6);
    EXPECT_LE(job.stats.final_cost, job.stats.first_cost);
  }
  // stats.cancelled (asserted above) is set only by the stop token, never by the 10 s budget:
  // so the window ended the jobs.
  for (const FrontEndPath& path : result.paths) {
    EXPECT_EQ(testing::ExactPathFailure(w.world, path.path.states), "");
    EXPECT_EQ(path.path.homotopy_class, w.jobs[path.job].base_path.homotopy_class);
  }
}

TEST(ParallelAcquisitionTest, FirstSolutionExitStillWorks) {
  const AcquisitionWorld w;
  ParallelAcquisitionOptions options;
  options.rrt.stop_at_first_solution = true;
  options.rrt.time_budget_s = 10.0;
  options.improvement_window_s = std::numeric_limits<double>::infinity();
  options.budget_s = std::numeric_limits<double>::infinity();
  options.num_workers = 2;
  const Clock::time_point t0 = Clock::now();
  const ParallelAcquisitionResult result =
      AcquireWholeBodyPaths(w.jobs, w.q_start, w.q_goal, w.validity, options, t0);
  ASSERT_EQ(result.paths.size(), 2u);
  double earliest_finish_ms = std::numeric_limits<double>::infinity();
  for (const ArmJobReport& job : result.jobs) {
    EXPECT_EQ(job.status, ArmRrtStarStatus::kSuccess) << job.message;
    EXPECT_FALSE(job.stats.cancelled);
    EXPECT_EQ(job.stats.num_solutions, 1);
    earliest_finish_ms = std::min(earliest_finish_ms, job.finished_at_ms);
  }
  EXPECT_LE(result.first_success_ms, earliest_finish_ms);
}

}  // namespace
}  // namespace topay
