#include "core/optimization/piece_sampler.h"

#include <stop_token>

#include <gtest/gtest.h>

#include "core/optimization/trajectory_objective.h"
#include "core/optimization/warm_start.h"
#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::MakeWorld;
using testing::ReadyJoints;

// A drive past a ground box with a wide arm margin, so that the arm and base penalties are
// active; the trajectory comes from a TrajectoryObjective evaluated at the warm start.
class PieceSamplerTest : public ::testing::Test {
 protected:
  static constexpr int kPanels = 12;

  PieceSamplerTest() : world_(MakeWorld({MakeBox({2.0, 0.9, 0.3}, {0.4, 0.4, 0.6})})) {
    const WholeBodyState start = MakeState(0.0, 0.0, 0.3, ReadyJoints());
    Eigen::VectorXd q_goal = ReadyJoints();
    q_goal(0) = 1.0;
    const WholeBodyState goal = MakeState(5.0, 0.3, 1.0, q_goal);
    WarmStartOptions warm_options;
    warm_options.piece_duration_s = 3.0;
    warm_ = MakeWarmStart(testing::StraightPath(start, goal), start, BaseLimits(),
                          world_->model.joint_limits, kPanels, warm_options);
    penalty_options_.arm_field_margin_m = 0.6;
    penalty_options_.base_field_margin_m = 0.3;
    TrajectoryObjectiveOptions options;
    options.panels_per_piece = kPanels;
    options.penalties = penalty_options_;
    objective_ = std::make_unique<TrajectoryObjective>(
        *world_->kinematics, world_->base_field(), world_->arm_field(), BaseLimits(), start,
        world_->kinematics->EndEffectorPose(goal), warm_.num_pieces, options);
    const Eigen::VectorXd x = objective_->Pack(warm_.durations_s, warm_.waypoints, warm_.end);
    double cost = 0.0;
    EXPECT_TRUE(objective_->Evaluate(x.data(), &cost, nullptr));
    num_pieces_ = warm_.num_pieces;
    dC_dc_.setZero(6 * num_pieces_, world_->model.num_joints() + 2);
    dC_dT_.setZero(num_pieces_);
  }

  std::unique_ptr<PieceSampler> MakeSampler() const {
    return std::make_unique<PieceSampler>(*world_->kinematics, world_->base_field(),
                                          world_->arm_field(), BaseLimits(), penalty_options_,
                                          PathFitWeights(), num_pieces_, kPanels);
  }

  PieceSampleContext Context(bool with_fit) {
    PieceSampleContext context;
    context.trajectory = &objective_->trajectory();
    context.durations_s = &objective_->durations_s();
    context.reference = with_fit ? &warm_.reference : nullptr;
    context.penalties_on = true;
    context.with_gradient = true;
    context.dC_dc = &dC_dc_;
    context.dC_dT = &dC_dT_;
    return context;
  }

  std::unique_ptr<testing::OptimizationWorld> world_;
  SamplePenaltyOptions penalty_options_;
  WarmStart warm_;
  std::unique_ptr<TrajectoryObjective> objective_;
  int num_pieces_ = 0;
  Eigen::MatrixXd dC_dc_;
  Eigen::VectorXd dC_dT_;
};

// Two samplers on [0, m) and [m, M) add up to one sampler on [0, M): costs, path fit and
// the Simpson-position gradient (the boundary sample is shared), and the per-piece blocks.
TEST_F(PieceSamplerTest, SplitRangesAddUpToTheWholeRange) {
  ASSERT_GE(num_pieces_, 3);
  const auto whole = MakeSampler();
  ASSERT_TRUE(whole->Run(Context(true), 0, num_pieces_, {}));
  const Eigen::MatrixXd whole_dC_dc = dC_dc_;
  const Eigen::VectorXd whole_dC_dT = dC_dT_;
  double whole_penalty = 0.0;
  for (double cost : whole->penalty_costs()) whole_penalty += cost;
  ASSERT_GT(whole_penalty, 0.0) << "no penalty active: the test would be vacuous";
  ASSERT_GT(whole->path_fit(), 0.0);

  dC_dc_.setZero();
  dC_dT_.setZero();
  const int middle = num_pieces_ / 2;
  const auto first = MakeSampler(), second = MakeSampler();
  ASSERT_TRUE(first->Run(Context(true), 0, middle, {}));
  ASSERT_TRUE(second->Run(Context(true), middle, num_pieces_, {}));
  double split_penalty = 0.0;
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    split_penalty += first->penalty_costs()[t] + second->penalty_costs()[t];
  }
  EXPECT_NEAR(split_penalty, whole_penalty, 1e-12 * whole_penalty);
  EXPECT_NEAR(first->path_fit() + second->path_fit(), whole->path_fit(), 1e-12 * whole->path_fit());
  const Eigen::Matrix2Xd split_dC_dp = first->dC_dp() + second->dC_dp();
  EXPECT_LE((split_dC_dp - whole->dC_dp()).cwiseAbs().maxCoeff(),
            1e-12 * whole->dC_dp().cwiseAbs().maxCoeff());
  // Piece j's blocks are written by piece j alone.
  EXPECT_LE((dC_dc_ - whole_dC_dc).cwiseAbs().maxCoeff(), 1e-12 * whole_dC_dc.cwiseAbs().maxCoeff());
  EXPECT_LE((dC_dT_ - whole_dC_dT).cwiseAbs().maxCoeff(), 1e-12 * whole_dC_dT.cwiseAbs().maxCoeff());
  // The first sampler leaves the second's samples alone, and vice versa.
  const int boundary = middle * kPanels;
  EXPECT_EQ(first->dC_dp().rightCols(first->dC_dp().cols() - boundary - 1).cwiseAbs().maxCoeff(),
            0.0);
  EXPECT_EQ(second->dC_dp().leftCols(boundary).cwiseAbs().maxCoeff(), 0.0);
}

TEST_F(PieceSamplerTest, RunStartsFromZeroEachTime) {
  const auto sampler = MakeSampler();
  ASSERT_TRUE(sampler->Run(Context(true), 0, num_pieces_, {}));
  const double fit = sampler->path_fit();
  const Eigen::Matrix2Xd dC_dp = sampler->dC_dp();
  ASSERT_TRUE(sampler->Run(Context(true), 0, num_pieces_, {}));
  EXPECT_EQ(sampler->path_fit(), fit);
  EXPECT_EQ(sampler->dC_dp(), dC_dp);
  ASSERT_TRUE(sampler->Run(Context(false), 0, num_pieces_, {}));
  EXPECT_EQ(sampler->path_fit(), 0.0);
}

TEST_F(PieceSamplerTest, StopRequestEndsTheRun) {
  const auto sampler = MakeSampler();
  std::stop_source source;
  source.request_stop();
  dC_dT_.setZero();
  EXPECT_FALSE(sampler->Run(Context(true), 0, num_pieces_, source.get_token()));
  EXPECT_EQ(dC_dT_.cwiseAbs().maxCoeff(), 0.0);  // no piece was sampled
}

}  // namespace
}  // namespace topay
