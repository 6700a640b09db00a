#include "core/optimization/trajectory_objective.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <stop_token>
#include <string>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "core/optimization/warm_start.h"
#include "tests/core/optimization/optimization_test_world.h"
#include "tests/core/robot/allocation_counter.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::MakeWorld;
using testing::OptimizationWorld;
using testing::ReadyJoints;

PenaltyMask Only(PenaltyTerm term) {
  PenaltyMask mask = NoPenalties();
  mask[static_cast<int>(term)] = true;
  return mask;
}

ObjectiveTerms NoTerms() {
  ObjectiveTerms terms;
  terms.jerk = terms.time = terms.end_effector = terms.path_fit = false;
  terms.penalties = NoPenalties();
  return terms;
}

// A drive of about 4 m past a ground box and under a floating one, with limits and margins
// chosen so that every penalty term is active somewhere along the warm start (the gradient
// checks are then not vacuous): low rate limits, wide clearance and self/chassis margins.
class TrajectoryObjectiveTest : public ::testing::Test {
 protected:
  static constexpr int kPanels = 12;

  TrajectoryObjectiveTest()
      : world_(MakeWorld({MakeBox({2.0, 0.95, 0.3}, {0.4, 0.4, 0.6}),
                          MakeBox({2.5, -0.3, 1.3}, {0.4, 0.4, 0.3})})) {
    start_ = MakeState(0.0, 0.0, 0.3, ReadyJoints());
    Eigen::VectorXd q_goal = ReadyJoints();
    q_goal << 0.8, 1.9, -0.5, -2.0, 0.4, 1.4, 0.3;
    goal_state_ = MakeState(4.0, 0.4, 1.2, q_goal);
    X_WE_goal_ = world_->kinematics->EndEffectorPose(goal_state_);
    X_WE_goal_.translation() += Eigen::Vector3d(0.05, -0.03, 0.02);  // EE residual != 0
    options_.panels_per_piece = kPanels;
    options_.penalties.arm_field_margin_m = 0.6;
    options_.penalties.base_field_margin_m = 0.3;
    options_.penalties.self_margin_m = 0.15;
    options_.penalties.chassis_margin_m = 0.4;
    options_.penalties.joint_position_margin_rad = 0.5;
    // The warm start is timed with the robot's limits; the objective gets far lower ones.
    WarmStartOptions warm_options;
    warm_options.piece_duration_s = 6.0;  // few pieces: fewer parameters to difference
    warm_ = MakeWarmStart(testing::StraightPath(start_, goal_state_), start_, BaseLimits(),
                          world_->model.joint_limits, kPanels, warm_options);
    limits_.v_max_mps = 0.3;
    limits_.a_max_mps2 = 0.1;
    limits_.omega_max_radps = 0.3;
    limits_.beta_max_radps2 = 0.1;
    world_->model.joint_limits.qd_max_radps.setConstant(0.1);
    world_->model.joint_limits.qdd_max_radps2.setConstant(0.05);
    objective_ = std::make_unique<TrajectoryObjective>(
        *world_->kinematics, world_->base_field(), world_->arm_field(), limits_, start_,
        X_WE_goal_, warm_.num_pieces, options_);
    objective_->set_path_reference(warm_.reference);
    Vector6d lambda;
    lambda << 3.0, -2.0, 1.0, 0.5, -0.4, 0.2;
    objective_->set_multiplier(lambda, 50.0);
    x_ = objective_->Pack(warm_.durations_s, warm_.waypoints, warm_.end);
    // Move the path off its reference so the path fit is not at its minimum.
    for (int i = 0; i < x_.size(); ++i) x_(i) += 0.03 * std::sin(1.7 * i);
  }

  double Cost(const Eigen::VectorXd& x) {
    double cost = 0.0;
    EXPECT_TRUE(objective_->Evaluate(x.data(), &cost, nullptr));
    return cost;
  }

  // The analytic gradient of the current terms against central differences of the cost in
  // every parameter. Central differences have truncation error O(h^2) and round-off about
  // eps |f| / h; the tolerance is relative to the gradient's own scale.
  void ExpectGradientMatches(const ObjectiveTerms& terms, const std::string& what) {
    objective_->set_terms(terms);
    Eigen::VectorXd gradient(objective_->num_parameters());
    double cost = 0.0;
    ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, gradient.data())) << what;
    ASSERT_GT(cost, 0.0) << what << " is zero at the test point: the check would be vacuous";
    const double scale = std::max(1.0, gradient.cwiseAbs().maxCoeff());
    constexpr double kStep = 1e-6;
    const double roundoff = 10.0 * 2.2e-16 * cost / kStep;
    int failures = 0;
    double worst = 0.0;  // largest error / tolerance
    for (int i = 0; i < x_.size(); ++i) {
      const double numeric = testing::CentralDifference(
          [&](const Eigen::VectorXd& x) { return Cost(x); }, x_, i, kStep);
      const double tolerance = 1e-7 * scale + 1e-6 * std::abs(numeric) + roundoff;
      worst = std::max(worst, std::abs(gradient(i) - numeric) / tolerance);
      if (std::abs(gradient(i) - numeric) > tolerance && ++failures <= 5) {
        ADD_FAILURE() << what << ": parameter " << i << " analytic " << gradient(i)
                      << " numeric " << numeric << " tolerance " << tolerance;
      }
    }
    EXPECT_EQ(failures, 0) << what;
    RecordProperty("cost_" + what, std::to_string(cost));
    RecordProperty("worst_error_over_tolerance_" + what, std::to_string(worst));
    std::printf("%-20s cost %.4g  |grad|max %.3g  worst error / tolerance %.3g\n", what.c_str(),
                cost, scale, worst);
  }

  std::unique_ptr<OptimizationWorld> world_;
  BaseLimits limits_;
  WholeBodyState start_, goal_state_;
  Eigen::Isometry3d X_WE_goal_;
  TrajectoryObjectiveOptions options_;
  WarmStart warm_;
  std::unique_ptr<TrajectoryObjective> objective_;
  Eigen::VectorXd x_;
};

TEST_F(TrajectoryObjectiveTest, JerkEnergyGradient) {
  ObjectiveTerms terms = NoTerms();
  terms.jerk = true;
  ExpectGradientMatches(terms, "jerk");
}

TEST_F(TrajectoryObjectiveTest, TimeGradient) {
  ObjectiveTerms terms = NoTerms();
  terms.time = true;
  ExpectGradientMatches(terms, "time");
}

TEST_F(TrajectoryObjectiveTest, EndEffectorAugmentedLagrangianGradient) {
  ObjectiveTerms terms = NoTerms();
  terms.end_effector = true;
  ExpectGradientMatches(terms, "end effector");
}

TEST_F(TrajectoryObjectiveTest, PathFitGradient) {
  ObjectiveTerms terms = NoTerms();
  terms.path_fit = true;
  ExpectGradientMatches(terms, "path fit");
}

TEST_F(TrajectoryObjectiveTest, EveryPenaltyTermGradient) {
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    ObjectiveTerms terms = NoTerms();
    terms.penalties = Only(static_cast<PenaltyTerm>(t));
    ExpectGradientMatches(terms, std::string(ToString(static_cast<PenaltyTerm>(t))));
  }
}

TEST_F(TrajectoryObjectiveTest, WholeObjectiveGradient) {
  ObjectiveTerms terms;  // stage 2: everything but the path fit
  ExpectGradientMatches(terms, "stage 2 objective");
  terms.path_fit = true;
  ExpectGradientMatches(terms, "everything");
}

// A moving start (issue 18): the head's velocity and acceleration columns are the start's
// rates; every term's gradient still matches central differences, and the trajectory
// starts with those rates.
TEST_F(TrajectoryObjectiveTest, MovingHeadGradientAndInitialRates) {
  WholeBodyRates rates;
  rates.v_mps = 0.25;
  rates.omega_radps = -0.2;
  rates.a_mps2 = 0.08;
  rates.beta_radps2 = 0.05;
  rates.qd_radps = Eigen::VectorXd::LinSpaced(7, -0.08, 0.08);
  rates.qdd_radps2 = Eigen::VectorXd::LinSpaced(7, 0.04, -0.04);
  double rest_cost = 0.0;
  objective_->set_terms(ObjectiveTerms());
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &rest_cost, nullptr));
  objective_->set_start_rates(rates);
  EXPECT_DOUBLE_EQ(objective_->head()(0, 1), 0.25);
  EXPECT_DOUBLE_EQ(objective_->head()(1, 2), 0.05);
  double moving_cost = 0.0;
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &moving_cost, nullptr));
  EXPECT_NE(moving_cost, rest_cost);  // the head enters the trajectory
  TrajectorySample sample = objective_->trajectory().MakePoint();
  objective_->trajectory().Evaluate(0.0, &sample);
  EXPECT_NEAR(sample.v_mps, rates.v_mps, 1e-9);
  EXPECT_NEAR(sample.omega_radps, rates.omega_radps, 1e-9);
  EXPECT_NEAR(sample.a_mps2, rates.a_mps2, 1e-9);
  EXPECT_NEAR(sample.beta_radps2, rates.beta_radps2, 1e-9);
  EXPECT_LT((sample.qd_radps - rates.qd_radps).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((sample.qdd_radps2 - rates.qdd_radps2).cwiseAbs().maxCoeff(), 1e-9);
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    ObjectiveTerms terms = NoTerms();
    terms.penalties = Only(static_cast<PenaltyTerm>(t));
    ExpectGradientMatches(terms, "moving " + std::string(ToString(static_cast<PenaltyTerm>(t))));
  }
  ObjectiveTerms terms;
  terms.path_fit = true;
  ExpectGradientMatches(terms, "moving everything");
  // Rates of the wrong joint count or not finite are refused.
  WholeBodyRates bad = rates;
  bad.qd_radps.resize(3);
  EXPECT_THROW(objective_->set_start_rates(bad), std::invalid_argument);
  bad = rates;
  bad.a_mps2 = std::nan("");
  EXPECT_THROW(objective_->set_start_rates(bad), std::invalid_argument);
}

TEST_F(TrajectoryObjectiveTest, PenaltyScalesMultiplyTheirTermsOnly) {
  double cost = 0.0;
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, nullptr));
  const ObjectiveBreakdown before = objective_->breakdown();
  PenaltyValues scales = OnesPenaltyValues();
  scales[static_cast<int>(PenaltyTerm::kArmObstacle)] = 10.0;
  objective_->set_penalty_scales(scales);
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, nullptr));
  const ObjectiveBreakdown& after = objective_->breakdown();
  EXPECT_EQ(after.jerk, before.jerk);
  EXPECT_EQ(after.end_effector, before.end_effector);
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    EXPECT_NEAR(after.penalties[t], scales[t] * before.penalties[t], 1e-9 * after.penalties[t])
        << ToString(static_cast<PenaltyTerm>(t));
  }
  scales[0] = 0.0;
  EXPECT_THROW(objective_->set_penalty_scales(scales), std::invalid_argument);
}

TEST_F(TrajectoryObjectiveTest, BreakdownSumsToTheCost) {
  ObjectiveTerms terms;
  terms.path_fit = true;
  objective_->set_terms(terms);
  double cost = 0.0;
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, nullptr));
  const ObjectiveBreakdown& b = objective_->breakdown();
  double sum = b.jerk + b.time + b.end_effector + b.path_fit;
  for (double p : b.penalties) sum += p;
  EXPECT_NEAR(sum, cost, 1e-12 * cost);
  EXPECT_NEAR(b.time, 50.0 * objective_->durations_s().sum(), 1e-9);
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    EXPECT_GT(b.penalties[t], 0.0) << ToString(static_cast<PenaltyTerm>(t));
  }
}

// With the default joint margin (0.01 rad) every warm-start joint value is inside the joint
// map's range: Pack and Unpack round-trip, and the trajectory ends at the free end, at rest.
TEST_F(TrajectoryObjectiveTest, PackUnpackRoundTripAndTrajectoryEndsAtTheFreeEnd) {
  TrajectoryObjective objective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                limits_, start_, X_WE_goal_, warm_.num_pieces);
  const Eigen::VectorXd x = objective.Pack(warm_.durations_s, warm_.waypoints, warm_.end);
  Eigen::VectorXd durations, end;
  Eigen::MatrixXd waypoints;
  objective.Unpack(x.data(), &durations, &waypoints, &end);
  EXPECT_TRUE(durations.isApprox(warm_.durations_s, 1e-12));
  EXPECT_TRUE(waypoints.isApprox(warm_.waypoints, 1e-9));
  EXPECT_TRUE(end.isApprox(warm_.end, 1e-9));
  double cost = 0.0;
  ASSERT_TRUE(objective.Evaluate(x.data(), &cost, nullptr));
  TrajectorySample point = objective.trajectory().MakePoint();
  objective.trajectory().Evaluate(objective.trajectory().duration_s(), &point);
  EXPECT_NEAR(point.s_m, warm_.end(0), 1e-9);
  EXPECT_NEAR(point.state.yaw_rad, warm_.end(1), 1e-9);
  EXPECT_LT((point.state.q_rad - warm_.end.tail(7)).norm(), 1e-9);
  EXPECT_NEAR(point.v_mps, 0.0, 1e-9);
  objective.trajectory().Evaluate(0.0, &point);
  EXPECT_NEAR(point.state.x_m, start_.x_m, 1e-12);
  EXPECT_NEAR(point.state.yaw_rad, start_.yaw_rad, 1e-12);
}

// The joint map's range is the limits less the joint margin: a value beyond it packs to the
// edge of that range (the fixture's margin is 0.5 rad; joint 2's limit 2.26 rad).
TEST_F(TrajectoryObjectiveTest, JointValuesStayInsideTheLimitsLessTheMargin) {
  Eigen::VectorXd end = warm_.end;
  end(2 + 1) = 2.2;
  const Eigen::VectorXd x = objective_->Pack(warm_.durations_s, warm_.waypoints, end);
  Eigen::VectorXd durations, unpacked_end;
  Eigen::MatrixXd waypoints;
  objective_->Unpack(x.data(), &durations, &waypoints, &unpacked_end);
  EXPECT_LT(unpacked_end(3), 2.26 - 0.5);
  EXPECT_NEAR(unpacked_end(3), 2.26 - 0.5, 1e-5);
  Eigen::VectorXd far = x;
  far(far.size() - 7 + 1) = 1e6;  // xi of joint 2 of the end
  objective_->Unpack(far.data(), &durations, &waypoints, &unpacked_end);
  EXPECT_LT(unpacked_end(3), 2.26 - 0.5);
}

// The pieces' chunks (sample_chunks) only change who computes what: 1, 2 or 3 chunks, run on
// one or two threads, give the same cost and gradient up to the summation order.
TEST_F(TrajectoryObjectiveTest, ChunkedSamplingEqualsSerialSampling) {
  ASSERT_GE(warm_.num_pieces, 3) << "the test needs a chunk of more than one piece";
  ObjectiveTerms terms;
  terms.path_fit = true;
  const auto evaluate = [&](int chunks, int threads, Eigen::VectorXd* gradient) {
    TrajectoryObjectiveOptions options = options_;
    options.sample_chunks = chunks;
    TrajectoryObjective objective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                  limits_, start_, X_WE_goal_, warm_.num_pieces, options);
    objective.set_path_reference(warm_.reference);
    Vector6d lambda;
    lambda << 3.0, -2.0, 1.0, 0.5, -0.4, 0.2;
    objective.set_multiplier(lambda, 50.0);
    objective.set_terms(terms);
    gradient->resize(objective.num_parameters());
    double cost = 0.0;
    tbb::task_arena arena(threads);
    bool ok = false;
    arena.execute([&] { ok = objective.Evaluate(x_.data(), &cost, gradient->data()); });
    EXPECT_TRUE(ok);
    return cost;
  };
  Eigen::VectorXd serial_gradient, gradient;
  const double serial = evaluate(1, 1, &serial_gradient);
  ASSERT_GT(serial, 0.0);
  const double scale = serial_gradient.cwiseAbs().maxCoeff();
  for (const auto& [chunks, threads] : {std::pair{2, 1}, std::pair{2, 2}, std::pair{3, 2}}) {
    const double cost = evaluate(chunks, threads, &gradient);
    EXPECT_NEAR(cost, serial, 1e-12 * serial) << chunks << " chunks, " << threads << " threads";
    EXPECT_LE((gradient - serial_gradient).cwiseAbs().maxCoeff(), 1e-11 * scale)
        << chunks << " chunks, " << threads << " threads";
  }
  // Two runs with the same chunks agree exactly, whatever the threads.
  Eigen::VectorXd again;
  EXPECT_EQ(evaluate(3, 1, &gradient), evaluate(3, 2, &again));
  EXPECT_EQ(gradient, again);
}

TEST_F(TrajectoryObjectiveTest, EvaluateDoesNotAllocate) {
  ObjectiveTerms terms;
  terms.path_fit = true;
  objective_->set_terms(terms);
  Eigen::VectorXd gradient(objective_->num_parameters());
  double cost = 0.0;
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, gradient.data()));
  testing::AllocationCounter counter;
  objective_->Evaluate(x_.data(), &cost, gradient.data());
  objective_->Evaluate(x_.data(), &cost, nullptr);
  EXPECT_EQ(counter.count(), 0);
}

TEST_F(TrajectoryObjectiveTest, FailsCleanlyOnNonFiniteOrExtremeParameters) {
  Eigen::VectorXd gradient(objective_->num_parameters());
  double cost = 0.0;
  Eigen::VectorXd bad = x_;
  bad(3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(objective_->Evaluate(bad.data(), &cost, gradient.data()));
  bad = x_;
  bad(0) = -1e9;  // a duration of ~1e-18 s: either a clean failure or finite values
  if (objective_->Evaluate(bad.data(), &cost, gradient.data())) {
    EXPECT_TRUE(std::isfinite(cost));
    EXPECT_TRUE(gradient.allFinite());
  }
  EXPECT_TRUE(objective_->Evaluate(x_.data(), &cost, gradient.data()));  // still usable
}

TEST_F(TrajectoryObjectiveTest, StopRequestFailsTheEvaluation) {
  std::stop_source source;
  objective_->set_stop_token(source.get_token());
  double cost = 0.0;
  EXPECT_TRUE(objective_->Evaluate(x_.data(), &cost, nullptr));
  EXPECT_FALSE(objective_->stopped());
  source.request_stop();
  EXPECT_FALSE(objective_->Evaluate(x_.data(), &cost, nullptr));
  EXPECT_TRUE(objective_->stopped());
}

TEST_F(TrajectoryObjectiveTest, RejectsBadConstructionArguments) {
  WholeBodyState short_start = start_;
  short_start.q_rad.resize(3);
  EXPECT_THROW(TrajectoryObjective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                   limits_, short_start, X_WE_goal_, 3, options_),
               std::invalid_argument);
  EXPECT_THROW(TrajectoryObjective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                   limits_, start_, X_WE_goal_, 0, options_),
               std::invalid_argument);
  TrajectoryObjectiveOptions no_chunks = options_;
  no_chunks.sample_chunks = 0;
  EXPECT_THROW(TrajectoryObjective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                   limits_, start_, X_WE_goal_, 3, no_chunks),
               std::invalid_argument);
  PathReference wrong = warm_.reference;
  wrong.yaw_rad.resize(2);
  EXPECT_THROW(objective_->set_path_reference(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace topay
