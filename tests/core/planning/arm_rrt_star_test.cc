#include "core/planning/arm_rrt_star.h"

#include <gtest/gtest.h>

#include "tests/core/planning/stop_latency.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <stop_token>
#include <thread>

#include "tests/common/make_box.h"
#include "tests/core/planning/rrt_test_world.h"

namespace topay {
namespace {

using testing::RrtTestWorld;

/// A straight corridor along x (walls at y = +-1.1 m) with a slab spanning it at
/// x in [2.5, 3.5] whose underside is at `slab_bottom_m`: the base passes under it, the
/// upright arm (1.2 m tall) does not, so the arm must fold on the way.
Scene CorridorWithSlab(double slab_bottom_m) {
  Scene scene;
  scene.bounds_W_m =
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.5, -1.5, 0.0), Eigen::Vector3d(7.5, 1.5, 1.6));
  scene.kind = "corridor with a low slab";
  scene.boxes.push_back(MakeBox({3.0, 1.15, 0.5}, {9.0, 0.1, 1.0}));
  scene.boxes.push_back(MakeBox({3.0, -1.15, 0.5}, {9.0, 0.1, 1.0}));
  scene.boxes.push_back(MakeBox({3.0, 0.0, slab_bottom_m + 0.025}, {1.0, 2.2, 0.05}));
  return scene;
}

struct Corridor {
  explicit Corridor(double slab_bottom_m, double delta_l_m = 1.414)
      : world(CorridorWithSlab(slab_bottom_m)),
        validity(world.kinematics, world.fields.base_field_2d, world.fields.field_3d) {
    DiscreteSE2Options options;
    options.delta_l_m = delta_l_m;
    base = DiscreteSE2({{0.0, 0.0}, {6.0, 0.0}}, 0.0, 0.0, world.model.base_limits, options);
    q_start = Eigen::VectorXd::Zero(world.model.num_joints());
    q_goal = q_start;
    q_goal(0) = 1.0;  // upright, turned about joint 1
  }
  RrtTestWorld world;
  WholeBodyValidity validity;
  DiscreteSE2Path base;
  Eigen::VectorXd q_start, q_goal;
};

ArmRrtStarOptions CappedOptions(std::int64_t iterations, std::uint64_t seed = 3) {
  ArmRrtStarOptions options;
  options.time_budget_s = 60.0;  // never reached: the iteration cap ends the run
  options.max_iterations = iterations;
  options.seed = seed;
  return options;
}

void ExpectLayeredAndExactlyValid(const Corridor& c, const ArmRrtStarResult& result) {
  ASSERT_TRUE(result.success()) << result.message;
  const WholeBodyPath& path = result.path;
  ASSERT_EQ(path.states.size(), c.base.layers.size());
  ASSERT_EQ(path.times_s.size(), path.states.size());
  EXPECT_EQ(path.states.front().q_rad, c.q_start);
  EXPECT_EQ(path.states.back().q_rad, c.q_goal);
  double cost = 0.0;
  for (std::size_t k = 0; k < path.states.size(); ++k) {
    // State k sits on layer k: consecutive states differ by exactly one layer.
    const Se2Layer& layer = c.base.layers[k];
    EXPECT_EQ(path.states[k].x_m, layer.x_m);
    EXPECT_EQ(path.states[k].y_m, layer.y_m);
    EXPECT_EQ(path.states[k].yaw_rad, layer.yaw_rad);
    EXPECT_EQ(path.times_s[k], layer.time_s);
    if (k == 0) continue;
    const Eigen::VectorXd dq = path.states[k].q_rad - path.states[k - 1].q_rad;
    cost += dq.norm();
    // Joint motion feasible within the base step's time.
    const Eigen::VectorXd bound = c.world.model.joint_limits.qd_max_radps * layer.step_time_s;
    EXPECT_TRUE((dq.cwiseAbs().array() <= bound.array() * (1.0 + 1e-9)).all()) << "edge " << k;
  }
  EXPECT_NEAR(path.cost, cost, 1e-9);
  EXPECT_NEAR(result.stats.final_cost, cost, 1e-9);
  EXPECT_GE(cost, result.stats.cost_lower_bound - 1e-12);
  EXPECT_EQ(testing::ExactPathFailure(c.world, path.states), "");
}

TEST(ArmRrtStarTest, FoldsTheArmUnderALowSlab) {
  const Corridor c(0.85);
  // The upright arm cannot pass: the straight joint-space path is blocked.
  WholeBodyValidityWorkspace workspace = c.validity.MakeWorkspace();
  ASSERT_FALSE(c.validity.IsValid(c.base.State(c.base.num_layers() / 2, c.q_start), &workspace));
  const ArmRrtStarResult result =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, CappedOptions(4000));
  ExpectLayeredAndExactlyValid(c, result);
  EXPECT_LE(result.stats.final_cost, result.stats.first_cost);
  EXPECT_GT(result.stats.iterations, 0);
  EXPECT_GT(result.stats.nodes_start_tree + result.stats.nodes_goal_tree, 2);
  EXPECT_TRUE(std::isfinite(result.stats.time_to_first_solution_s));
  std::cout << "corridor: " << c.base.num_layers() << " layers, " << result.stats.iterations
            << " iterations, nodes " << result.stats.nodes_start_tree << " + "
            << result.stats.nodes_goal_tree << ", first solution after "
            << result.stats.time_to_first_solution_s * 1e3 << " ms (cost "
            << result.stats.first_cost << "), final cost " << result.stats.final_cost << " (bound "
            << result.stats.cost_lower_bound << "), " << result.stats.elapsed_s * 1e3 << " ms\n";
  // Somewhere under the slab the arm is folded: its highest sphere is below the slab.
  bool folded = false;
  KinematicsCache cache = c.world.kinematics.MakeCache();
  for (const WholeBodyState& state : result.path.states) {
    c.world.kinematics.Update(state, &cache);
    double top = 0.0;
    for (std::size_t s = 0; s < cache.p_WS.size(); ++s) {
      top = std::max(top, cache.p_WS[s].z() + c.world.model.spheres[s].radius_m);
    }
    if (state.x_m > 2.0 && state.x_m < 4.0) folded = folded || top < 0.85;
  }
  EXPECT_TRUE(folded);
}

TEST(ArmRrtStarTest, FineLayersAndTurnsStayValid) {
  Corridor c(0.85, 0.5);
  c.base = DiscreteSE2({{0.0, 0.0}, {6.0, 0.0}}, 0.7, -0.5, c.world.model.base_limits,
                       DiscreteSE2Options{.delta_l_m = 0.5});
  const ArmRrtStarResult result =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, CappedOptions(6000, 9));
  ExpectLayeredAndExactlyValid(c, result);
}

TEST(ArmRrtStarTest, AnytimeImprovementDoesNotRaiseTheCost) {
  const Corridor c(1.5);  // slab 0.3 m above the upright arm: the straight line is free
  ArmRrtStarOptions options = CappedOptions(200);
  options.stop_at_first_solution = true;
  const ArmRrtStarResult first = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options);
  ExpectLayeredAndExactlyValid(c, first);
  options.stop_at_first_solution = false;
  const ArmRrtStarResult improved =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options);
  ExpectLayeredAndExactlyValid(c, improved);
  EXPECT_LE(improved.stats.final_cost, first.stats.final_cost + 1e-12);
  EXPECT_LE(improved.stats.final_cost, improved.stats.first_cost + 1e-12);
  // With a free straight line, the goal-biased steer finds the lower bound |q_g - q_s|.
  EXPECT_NEAR(improved.stats.final_cost, improved.stats.cost_lower_bound, 1e-9);
}

TEST(ArmRrtStarTest, FirstSolutionCallbackFiresOnceOnTheSearchThread) {
  const Corridor c(0.85);
  ArmRrtStarOptions options = CappedOptions(3000, 5);
  int calls = 0;
  double reported_cost = std::numeric_limits<double>::quiet_NaN();
  std::thread::id caller_thread;
  options.on_first_solution = [&](double cost) {
    ++calls;
    reported_cost = cost;
    caller_thread = std::this_thread::get_id();
  };
  const ArmRrtStarResult result = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options);
  ExpectLayeredAndExactlyValid(c, result);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(caller_thread, std::this_thread::get_id());
  EXPECT_EQ(reported_cost, result.stats.first_cost);
  // The search went on improving after the call (anytime): never above the first cost.
  EXPECT_LE(result.stats.final_cost, reported_cost + 1e-12);

  // No solution exists under a 0.45 m slab: never called.
  const Corridor blocked(0.45);
  calls = 0;
  const ArmRrtStarResult none = PlanArmRrtStar(blocked.base, blocked.q_start, blocked.q_goal,
                                               blocked.validity, CappedOptions(300, 5));
  ArmRrtStarOptions counted = CappedOptions(300, 5);
  counted.on_first_solution = [&](double) { ++calls; };
  const ArmRrtStarResult none_counted = PlanArmRrtStar(blocked.base, blocked.q_start,
                                                       blocked.q_goal, blocked.validity, counted);
  EXPECT_EQ(none.status, ArmRrtStarStatus::kNoSolution);
  EXPECT_EQ(none_counted.status, ArmRrtStarStatus::kNoSolution);
  EXPECT_EQ(calls, 0);
}

TEST(ArmRrtStarTest, StopFromTheFirstSolutionCallbackReturnsThatSolution) {
  // The front end's use: a stop requested at the first solution ends the anytime search,
  // which still returns its (first) solution.
  const Corridor c(0.85);
  ArmRrtStarOptions options = CappedOptions(100000, 7);
  std::stop_source source;
  double reported_cost = std::numeric_limits<double>::quiet_NaN();
  options.on_first_solution = [&](double cost) {
    reported_cost = cost;
    source.request_stop();
  };
  const ArmRrtStarResult result =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options, source.get_token());
  ExpectLayeredAndExactlyValid(c, result);
  EXPECT_TRUE(result.stats.cancelled);
  EXPECT_EQ(result.stats.num_solutions, 1);
  EXPECT_NEAR(result.path.cost, reported_cost, 1e-9);
  EXPECT_LT(result.stats.iterations, options.max_iterations);
}

TEST(ArmRrtStarTest, DeterministicWithAnIterationCap) {
  const Corridor c(0.85);
  const ArmRrtStarResult a =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, CappedOptions(1500, 21));
  const ArmRrtStarResult b =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, CappedOptions(1500, 21));
  ASSERT_EQ(a.status, b.status);
  EXPECT_EQ(a.stats.iterations, b.stats.iterations);
  EXPECT_EQ(a.stats.nodes_start_tree, b.stats.nodes_start_tree);
  EXPECT_EQ(a.stats.nodes_goal_tree, b.stats.nodes_goal_tree);
  EXPECT_EQ(a.stats.final_cost, b.stats.final_cost);
  ASSERT_EQ(a.path.states.size(), b.path.states.size());
  for (std::size_t k = 0; k < a.path.states.size(); ++k) {
    EXPECT_EQ(a.path.states[k].q_rad, b.path.states[k].q_rad);
  }
}

TEST(ArmRrtStarTest, CancellationReturnsWithinMilliseconds) {
  const Corridor c(0.45);  // too low even for the folded arm: no solution exists
  ArmRrtStarOptions options;
  options.time_budget_s = 30.0;
  ArmRrtStarResult result;
  const testing::StopLatency latency = testing::MeasureStopLatency(50, [&](std::stop_token stop) {
    result = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options, stop);
  });
  EXPECT_EQ(result.status, ArmRrtStarStatus::kCancelled) << result.message;
  EXPECT_TRUE(result.stats.cancelled);
  EXPECT_GT(result.stats.iterations, 0);
  // One edge check at 1 cm / 0.01 rad is the longest uninterruptible step (well under 1 ms):
  // the bound is on the CPU time the search spends after the stop (all on this thread), which
  // a loaded machine does not inflate; the wall-clock latency is printed.
  EXPECT_LT(latency.cpu_ms, 20.0) << "CPU after the stop " << latency.cpu_ms << " ms";
  std::cout << "cancellation latency " << latency.wall_ms << " ms (" << latency.cpu_ms
            << " ms CPU) after " << result.stats.iterations << " iterations\n";

  std::stop_source already;
  already.request_stop();
  const ArmRrtStarResult at_once =
      PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, options, already.get_token());
  EXPECT_EQ(at_once.status, ArmRrtStarStatus::kCancelled);
  EXPECT_EQ(at_once.stats.iterations, 0);
}

TEST(ArmRrtStarTest, InvalidStartOrGoalGivesAnEmptyResultWithAReason) {
  const Corridor c(0.85);
  // Upright arm under the slab: move the start there by starting the base sequence at x = 3.
  const DiscreteSE2Path under =
      DiscreteSE2({{3.0, 0.0}, {6.0, 0.0}}, 0.0, 0.0, c.world.model.base_limits);
  ArmRrtStarResult result = PlanArmRrtStar(under, c.q_start, c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kStartInvalid);
  EXPECT_TRUE(result.path.states.empty());
  EXPECT_NE(result.message.find("arm collision"), std::string::npos) << result.message;

  const DiscreteSE2Path into =
      DiscreteSE2({{0.0, 0.0}, {3.0, 0.0}}, 0.0, 0.0, c.world.model.base_limits);
  result = PlanArmRrtStar(into, c.q_start, c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kGoalInvalid);
  EXPECT_TRUE(result.path.states.empty());

  Eigen::VectorXd beyond = c.q_start;
  beyond(3) = c.world.model.joint_limits.q_max_rad(3) + 0.1;
  result = PlanArmRrtStar(c.base, beyond, c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kStartInvalid);
  EXPECT_NE(result.message.find("joint limit"), std::string::npos) << result.message;

  Eigen::VectorXd nan = c.q_goal;
  nan(2) = std::numeric_limits<double>::quiet_NaN();
  result = PlanArmRrtStar(c.base, c.q_start, nan, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kGoalInvalid);

  result = PlanArmRrtStar(c.base, Eigen::VectorXd::Zero(3), c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kInvalidInput);
  result = PlanArmRrtStar(DiscreteSE2Path{}, c.q_start, c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kInvalidInput);
  ArmRrtStarOptions bad;
  bad.goal_bias = 1.5;
  result = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, bad);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kInvalidInput);
  bad = ArmRrtStarOptions{};
  bad.stow_bias = -0.1;
  result = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity, bad);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kInvalidInput);
  EXPECT_NE(result.message.find("stow_bias"), std::string::npos) << result.message;
}

TEST(ArmRrtStarTest, BaseThroughAWallIsRejected) {
  Corridor c(0.85);
  c.base = DiscreteSE2({{0.0, 0.0}, {0.0, 0.9}, {6.0, 0.9}, {6.0, 0.0}}, 0.0, 0.0,
                       c.world.model.base_limits);
  const ArmRrtStarResult result = PlanArmRrtStar(c.base, c.q_start, c.q_goal, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kBasePathInvalid);
  EXPECT_FALSE(result.message.empty());
}

TEST(ArmRrtStarTest, UnreachableJointsWithinTheBaseTimeFail) {
  const Corridor c(1.4);
  // 0.1 m in about 0.71 s (a triangle profile): 2.35 rad/s cannot turn joint 1 by 3 rad.
  const DiscreteSE2Path short_path =
      DiscreteSE2({{0.0, 0.0}, {0.1, 0.0}}, 0.0, 0.0, c.world.model.base_limits);
  Eigen::VectorXd far = c.q_start;
  far(0) = 3.0;
  const ArmRrtStarResult result = PlanArmRrtStar(short_path, c.q_start, far, c.validity);
  EXPECT_EQ(result.status, ArmRrtStarStatus::kNoSolution);
  EXPECT_NE(result.message.find("not reachable"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace topay
