#include "core/optimization/lbfgs_solve.h"

#include <chrono>
#include <stdexcept>
#include <stop_token>

#include <gtest/gtest.h>

#include "core/optimization/warm_start.h"
#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using Clock = std::chrono::steady_clock;
using testing::MakeState;
using testing::ReadyJoints;

// Stage 2's objective for a 4 m drive in free space, from its warm start.
class LbfgsSolveTest : public ::testing::Test {
 protected:
  LbfgsSolveTest() : world_(testing::MakeWorld({})) {
    const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
    const WholeBodyState goal = MakeState(4.0, 1.0, 0.5, ReadyJoints());
    const WarmStart warm =
        MakeWarmStart(testing::StraightPath(start, goal), start, BaseLimits(),
                      world_->model.joint_limits, 12);
    objective_ = std::make_unique<TrajectoryObjective>(
        *world_->kinematics, world_->base_field(), world_->arm_field(), BaseLimits(), start,
        world_->kinematics->EndEffectorPose(goal), warm.num_pieces);
    objective_->set_multiplier(Vector6d::Zero(), 1e4);
    x0_ = objective_->Pack(warm.durations_s, warm.waypoints, warm.end);
  }

  double Cost(const Eigen::VectorXd& x) {
    double cost = 0.0;
    EXPECT_TRUE(objective_->Evaluate(x.data(), &cost, nullptr));
    return cost;
  }

  static Clock::time_point Later() { return Clock::now() + std::chrono::seconds(30); }

  std::unique_ptr<testing::OptimizationWorld> world_;
  std::unique_ptr<TrajectoryObjective> objective_;
  Eigen::VectorXd x0_;
};

TEST_F(LbfgsSolveTest, ConvergesAndLowersTheCost) {
  Eigen::VectorXd x = x0_;
  const double before = Cost(x0_);
  const LbfgsResult result = SolveWithLbfgs(objective_.get(), &x, LbfgsOptions(), Later(), {});
  EXPECT_EQ(result.stop, LbfgsStop::kConverged) << result.message;
  EXPECT_GT(result.iterations, 3);
  EXPECT_GE(result.evaluations, result.iterations);
  EXPECT_NEAR(result.initial_cost, before, 1e-9 * before);
  EXPECT_LT(result.final_cost, 0.5 * before);
  // x holds the solution Ceres reports.
  EXPECT_NEAR(Cost(x), result.final_cost, 1e-9 * result.final_cost);
}

// The relative-decrease stop: with a huge delta it fires as soon as `past` iterations exist.
TEST_F(LbfgsSolveTest, RelativeDecreaseStopLooksBackPastIterations) {
  LbfgsOptions options;
  options.relative_decrease_delta = 1e30;
  options.relative_decrease_past = 3;
  Eigen::VectorXd x = x0_;
  const LbfgsResult result = SolveWithLbfgs(objective_.get(), &x, options, Later(), {});
  EXPECT_EQ(result.stop, LbfgsStop::kConverged);
  EXPECT_EQ(result.iterations, 3);
}

TEST_F(LbfgsSolveTest, IterationLimit) {
  LbfgsOptions options;
  options.max_iterations = 5;
  options.relative_decrease_delta = 0.0;
  Eigen::VectorXd x = x0_;
  const LbfgsResult result = SolveWithLbfgs(objective_.get(), &x, options, Later(), {});
  EXPECT_EQ(result.stop, LbfgsStop::kMaxIterations) << result.message;
  EXPECT_EQ(result.iterations, 5);
  EXPECT_LT(Cost(x), Cost(x0_));  // progress is kept
}

TEST_F(LbfgsSolveTest, StopTokenAndDeadline) {
  std::stop_source source;
  source.request_stop();
  objective_->set_stop_token(source.get_token());
  Eigen::VectorXd x = x0_;
  EXPECT_EQ(SolveWithLbfgs(objective_.get(), &x, LbfgsOptions(), Later(), source.get_token()).stop,
            LbfgsStop::kCancelled);
  EXPECT_EQ(x, x0_);
  objective_->set_stop_token({});
  EXPECT_EQ(SolveWithLbfgs(objective_.get(), &x, LbfgsOptions(), Clock::now(), {}).stop,
            LbfgsStop::kTimeLimit);
}

TEST_F(LbfgsSolveTest, RejectsBadOptionsAndSizes) {
  Eigen::VectorXd x = x0_;
  LbfgsOptions options;
  options.curvature = 1e-5;  // must exceed sufficient_decrease
  EXPECT_THROW(SolveWithLbfgs(objective_.get(), &x, options, Later(), {}), std::invalid_argument);
  Eigen::VectorXd wrong(3);
  EXPECT_THROW(SolveWithLbfgs(objective_.get(), &wrong, LbfgsOptions(), Later(), {}),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
