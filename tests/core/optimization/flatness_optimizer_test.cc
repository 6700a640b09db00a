// The REMANI-style flatness baseline: flat_yaw.h, FlatnessObjective, FlatnessTrajectory and
// FlatnessOptimizer (issue 4, item 7).
#include "core/optimization/flatness_optimizer.h"

#include <memory>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/optimization/back_end_factory.h"
#include "core/optimization/flat_yaw.h"
#include "core/optimization/flatness_objective.h"
#include "core/optimization/flatness_trajectory.h"
#include "core/optimization/trajectory_objective.h"
#include "core/optimization/trajectory_optimizer.h"
#include "core/validate/trajectory_validator.h"
#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::MakeWorld;
using testing::ReadyJoints;
using testing::StraightPath;

BaseLimits BenchmarkLimits() {
  BaseLimits limits;
  limits.omega_max_radps = 1.25;
  return limits;
}

// ---- flat_yaw.h ---------------------------------------------------------------------------

// A circle of radius r at angular rate w: v = r w, omega = w, a = beta = 0, yaw = w t + pi/2.
TEST(FlatYawTest, MatchesACircleAnalytically) {
  const double r = 1.5, w = 0.7, t = 0.4;
  const double c = std::cos(w * t), s = std::sin(w * t);
  const Eigen::Vector2d u(-r * w * s, r * w * c);
  const Eigen::Vector2d acc(-r * w * w * c, -r * w * w * s);
  const Eigen::Vector2d jerk(r * w * w * w * s, -r * w * w * w * c);
  const FlatYaw flat = ComputeFlatYaw(u, acc, jerk);
  EXPECT_NEAR(flat.v_mps, r * w, 1e-12);
  EXPECT_NEAR(flat.omega_radps, w, 1e-12);
  EXPECT_NEAR(flat.a_mps2, 0.0, 1e-12);
  EXPECT_NEAR(flat.beta_radps2, 0.0, 1e-12);
  EXPECT_NEAR(flat.yaw_rad, w * t + std::numbers::pi / 2, 1e-12);
}

// A speeding-up, turning motion: beta and a against numerical time derivatives of omega, v.
TEST(FlatYawTest, RatesAreTimeDerivatives) {
  // p(t) = (t + t^2, 0.3 t^2 + 0.2 t^3)
  const auto at = [](double t) {
    const Eigen::Vector2d u(1 + 2 * t, 0.6 * t + 0.6 * t * t);
    const Eigen::Vector2d w(2, 0.6 + 1.2 * t);
    const Eigen::Vector2d z(0, 1.2);
    return ComputeFlatYaw(u, w, z);
  };
  const double t = 0.7, h = 1e-5;
  const FlatYaw f = at(t);
  EXPECT_NEAR(f.a_mps2, (at(t + h).v_mps - at(t - h).v_mps) / (2 * h), 1e-7);
  EXPECT_NEAR(f.omega_radps, (at(t + h).yaw_rad - at(t - h).yaw_rad) / (2 * h), 1e-7);
  EXPECT_NEAR(f.beta_radps2, (at(t + h).omega_radps - at(t - h).omega_radps) / (2 * h), 1e-7);
}

TEST(FlatYawTest, GradientMatchesCentralDifferences) {
  Eigen::Matrix<double, 6, 1> p;
  p << 0.4, -0.3, 0.9, 0.5, -1.1, 0.7;  // u, w, z
  FlatYaw g;
  g.yaw_rad = 0.3;
  g.v_mps = -1.2;
  g.a_mps2 = 0.8;
  g.omega_radps = 1.7;
  g.beta_radps2 = -0.6;
  const auto f = [&](const Eigen::Matrix<double, 6, 1>& q) {
    const FlatYaw y = ComputeFlatYaw(q.segment<2>(0), q.segment<2>(2), q.segment<2>(4));
    return g.yaw_rad * y.yaw_rad + g.v_mps * y.v_mps + g.a_mps2 * y.a_mps2 +
           g.omega_radps * y.omega_radps + g.beta_radps2 * y.beta_radps2;
  };
  Eigen::Vector2d du = Eigen::Vector2d::Zero(), dw = Eigen::Vector2d::Zero(),
                  dz = Eigen::Vector2d::Zero();
  AddFlatYawGradient(p.segment<2>(0), p.segment<2>(2), p.segment<2>(4), g, &du, &dw, &dz);
  Eigen::Matrix<double, 6, 1> analytic;
  analytic << du, dw, dz;
  for (int i = 0; i < 6; ++i) {
    const double h = 1e-6;
    Eigen::Matrix<double, 6, 1> plus = p, minus = p;
    plus(i) += h;
    minus(i) -= h;
    const double numeric = (f(plus) - f(minus)) / (2 * h);
    EXPECT_NEAR(analytic(i), numeric, 1e-7 * std::max(1.0, std::abs(numeric))) << "entry " << i;
  }
}

// ---- FlatnessObjective ----------------------------------------------------------------------

class FlatnessObjectiveTest : public ::testing::Test {
 protected:
  FlatnessObjectiveTest()
      : world_(MakeWorld({MakeBox({1.6, 0.75, 0.4}, {0.6, 0.6, 0.8})})),
        start_(MakeState(0.0, 0.0, 0.1, ReadyJoints())) {
    Eigen::VectorXd q_goal = ReadyJoints();
    q_goal(0) += 0.4;
    q_goal(3) += 0.2;
    goal_ = MakeState(3.0, 0.4, 0.2, q_goal);
    objective_ = std::make_unique<FlatnessObjective>(
        *world_->kinematics, world_->base_field(), world_->arm_field(), BenchmarkLimits(),
        start_, world_->kinematics->EndEffectorPose(goal_), 3);
    Vector6d lambda;
    lambda << 0.3, -0.2, 0.1, 0.05, -0.1, 0.2;
    objective_->set_multiplier(lambda, 50.0);
    const int N = 7;
    Eigen::MatrixXd waypoints(N + 2, 2);
    waypoints.col(0) << 1.0, 0.25, ReadyJoints() + Eigen::VectorXd::Constant(N, 0.1);
    waypoints.col(1) << 2.05, 0.3, ReadyJoints() + Eigen::VectorXd::Constant(N, 0.2);
    Eigen::VectorXd end(N + 3);
    end << 2.9, 0.45, 0.25, q_goal;
    x_ = objective_->Pack(Eigen::Vector3d(1.6, 1.3, 1.9), waypoints, end);
  }

  void ExpectGradientMatches(const FlatnessTerms& terms, const std::string& what) {
    objective_->set_terms(terms);
    Eigen::VectorXd gradient(objective_->num_parameters());
    double cost = 0.0;
    ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, gradient.data())) << what;
    ASSERT_GT(cost, 0.0) << what << " is zero at the test point: the check would be vacuous";
    const double scale = std::max(1.0, gradient.cwiseAbs().maxCoeff());
    constexpr double kStep = 1e-6;
    const double roundoff = 10.0 * 2.2e-16 * cost / kStep;
    const auto f = [&](const Eigen::VectorXd& x) {
      double c = 0.0;
      EXPECT_TRUE(objective_->Evaluate(x.data(), &c, nullptr));
      return c;
    };
    double worst = 0.0;
    for (int i = 0; i < objective_->num_parameters(); ++i) {
      const double numeric = testing::CentralDifference(f, x_, i, kStep);
      const double tolerance = 1e-7 * scale + 1e-6 * std::abs(numeric) + roundoff;
      worst = std::max(worst, std::abs(gradient(i) - numeric) / tolerance);
      EXPECT_NEAR(gradient(i), numeric, tolerance) << what << " parameter " << i;
    }
    std::printf("%-14s cost %.5g  |grad|max %.3g  worst error / tolerance %.3g\n", what.c_str(),
                cost, scale, worst);
  }

  std::unique_ptr<testing::OptimizationWorld> world_;
  WholeBodyState start_, goal_;
  std::unique_ptr<FlatnessObjective> objective_;
  Eigen::VectorXd x_;
};

TEST_F(FlatnessObjectiveTest, WholeObjectiveGradientMatchesCentralDifferences) {
  ExpectGradientMatches(FlatnessTerms(), "all terms");
  // Not vacuous: the flat-output terms are active at this point.
  const FlatnessBreakdown& b = objective_->breakdown();
  EXPECT_GT(b.end_effector, 0.0);
  EXPECT_GT(b.penalties[static_cast<int>(PenaltyTerm::kBaseObstacle)] +
                b.penalties[static_cast<int>(PenaltyTerm::kArmObstacle)],
            0.0);
}

TEST_F(FlatnessObjectiveTest, BaseRatePenaltiesAloneGradientMatches) {
  FlatnessTerms terms;
  terms.jerk = terms.time = terms.end_effector = terms.min_speed = false;
  terms.penalties = NoPenalties();
  for (PenaltyTerm t : {PenaltyTerm::kVelocityOmega, PenaltyTerm::kAcceleration,
                        PenaltyTerm::kYawAcceleration}) {
    terms.penalties[static_cast<int>(t)] = true;
  }
  // Tighten the base limits so that these terms are active.
  BaseLimits tight;
  tight.v_max_mps = 0.5;
  tight.a_max_mps2 = 0.3;
  tight.omega_max_radps = 0.1;
  tight.beta_max_radps2 = 0.1;
  objective_ = std::make_unique<FlatnessObjective>(
      *world_->kinematics, world_->base_field(), world_->arm_field(), tight, start_,
      world_->kinematics->EndEffectorPose(goal_), 3);
  ExpectGradientMatches(terms, "base rates");
  EXPECT_GT(objective_->breakdown().penalties[static_cast<int>(PenaltyTerm::kYawAcceleration)],
            0.0);
}

TEST_F(FlatnessObjectiveTest, MinimumSpeedTermAloneGradientMatches) {
  FlatnessTerms terms;
  terms.jerk = terms.time = terms.end_effector = false;
  terms.penalties = NoPenalties();
  // A nearly stalled middle: waypoints close together, long pieces.
  const int N = 7;
  Eigen::MatrixXd waypoints(N + 2, 2);
  waypoints.col(0) << 0.5, 0.05, ReadyJoints();
  waypoints.col(1) << 0.52, 0.06, ReadyJoints();
  Eigen::VectorXd end(N + 3);
  end << 1.0, 0.1, 0.1, ReadyJoints();
  x_ = objective_->Pack(Eigen::Vector3d(2.0, 3.0, 2.0), waypoints, end);
  ExpectGradientMatches(terms, "min speed");
  EXPECT_GT(objective_->breakdown().min_speed, 0.0);
}

TEST_F(FlatnessObjectiveTest, SamplesAreDenserInTheStopPieces) {
  EXPECT_EQ(objective_->panels(0), 32);
  EXPECT_EQ(objective_->panels(1), 16);
  EXPECT_EQ(objective_->panels(2), 32);
}

TEST_F(FlatnessObjectiveTest, TrajectoryStartsAtTheStartAndEndsAtRestAlongPsiF) {
  double cost = 0.0;
  ASSERT_TRUE(objective_->Evaluate(x_.data(), &cost, nullptr));
  FlatnessTrajectory trajectory(objective_->TrajectoryData());
  TrajectorySample sample = MakeTrajectorySample(7);
  trajectory.Evaluate(0.0, &sample);
  EXPECT_NEAR(sample.state.x_m, start_.x_m, 1e-12);
  EXPECT_NEAR(sample.state.yaw_rad, start_.yaw_rad, 1e-12);
  EXPECT_NEAR(sample.v_mps, 0.0, 1e-12);
  // Just after the start the heading tends to the start yaw (the rest remedy).
  trajectory.Evaluate(1e-4, &sample);
  EXPECT_NEAR(sample.state.yaw_rad, start_.yaw_rad, 1e-3);
  const double T = trajectory.duration_s();
  EXPECT_NEAR(T, 1.6 + 1.3 + 1.9, 1e-9);
  trajectory.Evaluate(T, &sample);
  EXPECT_NEAR(sample.state.x_m, 2.9, 1e-9);
  EXPECT_NEAR(sample.state.yaw_rad, 0.25, 1e-12);
  EXPECT_NEAR(sample.v_mps, 0.0, 1e-12);
  trajectory.Evaluate(T - 1e-4, &sample);
  EXPECT_NEAR(sample.state.yaw_rad, 0.25, 1e-3);
}

// ---- FlatnessOptimizer ----------------------------------------------------------------------

class FlatnessOptimizerTest : public ::testing::Test {
 protected:
  FlatnessOptimizerTest()
      : world_(MakeWorld({MakeBox({2.5, 1.2, 0.4}, {0.6, 0.6, 0.8}),
                          MakeBox({-2.5, 3.0, 1.0}, {0.5, 0.5, 0.4})})),
        optimizer_(*world_->kinematics, world_->base_field(), world_->arm_field()) {}

  TrajectoryProblem Problem(const WholeBodyState& start, const WholeBodyState& goal) const {
    TrajectoryProblem problem;
    problem.start = start;
    problem.X_WE_goal = world_->kinematics->EndEffectorPose(goal);
    problem.base_limits = BenchmarkLimits();
    return problem;
  }

  std::unique_ptr<testing::OptimizationWorld> world_;
  FlatnessOptimizer optimizer_;
};

TEST_F(FlatnessOptimizerTest, StraightDriveSucceedsAndPassesTheValidator) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  Eigen::VectorXd q_goal = ReadyJoints();
  q_goal(0) = 0.3;
  q_goal(5) = 1.1;
  const WholeBodyState goal = MakeState(4.0, 0.0, 0.0, q_goal);
  const TrajectoryProblem problem = Problem(start, goal);
  const BackEndSummary summary = optimizer_.Optimize(problem, StraightPath(start, goal));
  std::printf("straight drive\n%s", summary.Report().c_str());
  ASSERT_EQ(summary.status, BackEndStatus::kSuccess) << summary.Report();
  const TrajectoryValidator validator(*world_->kinematics, world_->scene, problem.base_limits);
  const ValidationReport report =
      validator.Validate(summary.Sampled(), problem.start, problem.X_WE_goal);
  EXPECT_TRUE(report.ok) << report.Report();
}

// Allowed to fail (yaw is undefined where the base only turns): only a clean return.
TEST_F(FlatnessOptimizerTest, TurnInPlaceReturnsCleanlyWithAReason) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(0.0, 0.0, std::numbers::pi, ReadyJoints());
  const TrajectoryProblem problem = Problem(start, goal);
  const BackEndSummary summary = optimizer_.Optimize(problem, StraightPath(start, goal));
  std::printf("turn in place: %s\n%s", summary.success() ? "SUCCEEDED" : "failed",
              summary.Report().c_str());
  EXPECT_NE(summary.status, BackEndStatus::kInvalidInput) << summary.reason;
  EXPECT_NE(summary.status, BackEndStatus::kCancelled);
  EXPECT_EQ(summary.success(), summary.reason.empty()) << summary.reason;
}

// Issue 18: the baseline plans from rest only; a moving start is refused with the reason.
TEST_F(FlatnessOptimizerTest, AMovingStartIsRefusedWithAReason) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(2.0, 0.0, 0.0, ReadyJoints());
  TrajectoryProblem problem = Problem(start, goal);
  problem.start_rates.v_mps = 0.5;
  const BackEndSummary summary = optimizer_.Optimize(problem, StraightPath(start, goal));
  EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
  EXPECT_EQ(summary.reason.rfind("moving start:", 0), 0u) << summary.reason;
}

TEST_F(FlatnessOptimizerTest, BadInputFailsCleanlyWithAReason) {
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(2.0, 0.0, 0.0, ReadyJoints());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  {
    TrajectoryProblem problem = Problem(start, goal);
    problem.start.x_m = nan;
    const auto summary = optimizer_.Optimize(problem, StraightPath(start, goal));
    EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
    EXPECT_NE(summary.reason.find("start state is not finite"), std::string::npos);
    EXPECT_THROW(summary.Sampled(), std::invalid_argument);
  }
  {
    TrajectoryProblem problem = Problem(start, goal);
    problem.start.q_rad.resize(3);
    const auto summary = optimizer_.Optimize(problem, StraightPath(start, goal));
    EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
    EXPECT_NE(summary.reason.find("joints"), std::string::npos) << summary.reason;
  }
  {
    TrajectoryProblem problem = Problem(start, goal);
    problem.X_WE_goal.translation().x() = nan;
    const auto summary = optimizer_.Optimize(problem, StraightPath(start, goal));
    EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
    EXPECT_NE(summary.reason.find("X_WE_goal"), std::string::npos) << summary.reason;
  }
  {
    TrajectoryProblem problem = Problem(start, goal);
    problem.base_limits.v_max_mps = -1.0;
    const auto summary = optimizer_.Optimize(problem, StraightPath(start, goal));
    EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
    EXPECT_NE(summary.reason.find("base limits"), std::string::npos) << summary.reason;
  }
  {
    const auto summary = optimizer_.Optimize(Problem(start, goal), WholeBodyPath{});
    EXPECT_EQ(summary.status, BackEndStatus::kInvalidInput);
    EXPECT_NE(summary.reason.find("initial path"), std::string::npos) << summary.reason;
  }
  FlatnessOptimizerOptions options;
  options.objective.panels_per_piece = 0;
  EXPECT_THROW(FlatnessObjective(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                 BenchmarkLimits(), start, Eigen::Isometry3d::Identity(), 3,
                                 options.objective),
               std::invalid_argument);
  options = FlatnessOptimizerOptions();
  options.alm.rho_initial = 0.0;
  EXPECT_THROW(FlatnessOptimizer(*world_->kinematics, world_->base_field(), world_->arm_field(),
                                 options),
               std::invalid_argument);
  FlatnessTrajectoryData data;  // empty
  EXPECT_THROW(FlatnessTrajectory{data}, std::invalid_argument);
  EXPECT_THROW(SampleFlatness(data), std::invalid_argument);
}


// ---- Behind the driver's interface ------------------------------------------------------------

TEST_F(FlatnessOptimizerTest, FactoryBuildsTheBaselineFromTheParameterisationOption) {
  TrajectoryOptimizerOptions options;
  options.parameterisation = TrajectoryParameterisation::kFlatness;
  const std::unique_ptr<TrajectoryBackEnd> back_end = MakeTrajectoryBackEnd(
      *world_->kinematics, world_->base_field(), world_->arm_field(), options);
  ASSERT_NE(dynamic_cast<const FlatnessOptimizer*>(back_end.get()), nullptr);
  EXPECT_EQ(back_end->parameterisation(), TrajectoryParameterisation::kFlatness);
  const TrajectoryBackEnd& driver = *back_end;
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(4.0, 0.0, 0.0, ReadyJoints());
  const TrajectoryProblem problem = Problem(start, goal);
  const BackEndSummary summary = driver.Optimize(problem, StraightPath(start, goal));
  std::printf("driver, flatness\n%s", summary.Report().c_str());
  ASSERT_EQ(summary.status, BackEndStatus::kSuccess) << summary.Report();
  EXPECT_EQ(summary.parameterisation, TrajectoryParameterisation::kFlatness);
  EXPECT_THROW(summary.MakeTrajectory(), std::invalid_argument);
  const TrajectoryValidator validator(*world_->kinematics, world_->scene, problem.base_limits);
  const ValidationReport report =
      validator.Validate(summary.Sampled(), problem.start, problem.X_WE_goal);
  EXPECT_TRUE(report.ok) << report.Report();
  EXPECT_NEAR(summary.Sampled().duration_s, summary.duration_s, 1e-12);
  // The shared input checks (reach) hold for either back end.
  TrajectoryProblem too_high = problem;
  too_high.X_WE_goal.translation().z() = 3.0;
  const BackEndSummary bad = driver.Optimize(too_high, StraightPath(start, goal));
  EXPECT_EQ(bad.status, BackEndStatus::kInvalidInput);
  EXPECT_THROW(bad.Sampled(), std::invalid_argument);
}

TEST_F(FlatnessOptimizerTest, DefaultBackEndIsArcLengthYawAndSampledAsSuch) {
  const std::unique_ptr<TrajectoryBackEnd> back_end = MakeTrajectoryBackEnd(
      *world_->kinematics, world_->base_field(), world_->arm_field(), {});
  ASSERT_NE(dynamic_cast<const TrajectoryOptimizer*>(back_end.get()), nullptr);
  EXPECT_EQ(back_end->parameterisation(), TrajectoryParameterisation::kArcLengthYaw);
  const TrajectoryBackEnd& driver = *back_end;
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(2.0, 0.0, 0.0, ReadyJoints());
  const TrajectoryProblem problem = Problem(start, goal);
  const BackEndSummary summary = driver.Optimize(problem, StraightPath(start, goal));
  ASSERT_EQ(summary.status, BackEndStatus::kSuccess) << summary.Report();
  EXPECT_EQ(summary.parameterisation, TrajectoryParameterisation::kArcLengthYaw);
  const SampledTrajectory sampled = summary.Sampled();
  EXPECT_NEAR(sampled.duration_s, summary.MakeTrajectory().duration_s(), 1e-12);
  const TrajectoryValidator validator(*world_->kinematics, world_->scene, problem.base_limits);
  const ValidationReport report = validator.Validate(sampled, problem.start, problem.X_WE_goal);
  EXPECT_TRUE(report.ok) << report.Report();
}

// Figures for the report (printed, not asserted: no timing assertions in unit tests): a few
// tasks with both parameterisations, success by the validator, and wall time.
TEST_F(FlatnessOptimizerTest, ComparesBothParameterisationsOnIdenticalTasks) {
  TrajectoryOptimizerOptions flat_options;
  flat_options.parameterisation = TrajectoryParameterisation::kFlatness;
  const TrajectoryOptimizer arc(*world_->kinematics, world_->base_field(), world_->arm_field());
  const std::unique_ptr<TrajectoryBackEnd> flat_back_end = MakeTrajectoryBackEnd(
      *world_->kinematics, world_->base_field(), world_->arm_field(), flat_options);
  const TrajectoryBackEnd& flat = *flat_back_end;
  const TrajectoryValidator validator(*world_->kinematics, world_->scene, BenchmarkLimits());
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  Eigen::VectorXd q2 = ReadyJoints();
  q2(0) = 0.5;
  const WholeBodyState goals[] = {
      MakeState(4.0, 0.0, 0.0, ReadyJoints()), MakeState(3.0, 1.5, 0.6, q2),
      MakeState(5.0, -0.5, -0.3, q2), MakeState(1.0, 2.0, 1.2, ReadyJoints()),
      MakeState(0.0, 0.0, std::numbers::pi, ReadyJoints())};
  for (const WholeBodyState& goal : goals) {
    const TrajectoryProblem problem = Problem(start, goal);
    const WholeBodyPath path = StraightPath(start, goal);
    for (const TrajectoryBackEnd* driver : {static_cast<const TrajectoryBackEnd*>(&arc), &flat}) {
      const BackEndSummary summary = driver->Optimize(problem, path);
      ASSERT_NE(summary.status, BackEndStatus::kInvalidInput) << summary.reason;
      EXPECT_EQ(summary.success(), summary.reason.empty()) << summary.reason;
      const bool valid = summary.success() &&
                         validator.Validate(summary.Sampled(), problem.start, problem.X_WE_goal).ok;
      std::printf("goal (%.1f, %.1f, %.2f) %-9s: %-13s validated %d, %.2f ms, T %.2f s %s\n",
                  goal.x_m, goal.y_m, goal.yaw_rad, driver == &flat ? "flatness" : "arc-yaw",
                  std::string(ToString(summary.status)).c_str(), valid ? 1 : 0,
                  1e3 * summary.total_s, summary.duration_s, summary.reason.c_str());
    }
  }
}

// Per-evaluation cost with gradient at M = 10 (printed only).
TEST(FlatnessObjectiveTimingTest, PrintsPerEvaluationTimeForTenPieces) {
  const auto world = MakeWorld({MakeBox({2.5, 1.2, 0.4}, {0.6, 0.6, 0.8})});
  const WholeBodyState start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
  const WholeBodyState goal = MakeState(9.0, 0.5, 0.1, ReadyJoints());
  const Eigen::Isometry3d X_WE = world->kinematics->EndEffectorPose(goal);
  const int M = 10, N = 7;
  FlatnessObjective flat(*world->kinematics, world->base_field(), world->arm_field(),
                         BenchmarkLimits(), start, X_WE, M);
  TrajectoryObjective arc(*world->kinematics, world->base_field(), world->arm_field(),
                          BenchmarkLimits(), start, X_WE, M);
  Eigen::MatrixXd flat_waypoints(N + 2, M - 1), arc_waypoints(N + 2, M - 1);
  for (int i = 0; i + 1 < M; ++i) {
    flat_waypoints.col(i) << 0.9 * (i + 1), 0.05 * (i + 1), ReadyJoints();
    arc_waypoints.col(i) << 0.9 * (i + 1), 0.0, ReadyJoints();
  }
  Eigen::VectorXd flat_end(N + 3), arc_end(N + 2);
  flat_end << 9.0, 0.5, 0.1, ReadyJoints();
  arc_end << 9.0, 0.1, ReadyJoints();
  const Eigen::VectorXd durations = Eigen::VectorXd::Constant(M, 1.5);
  const Eigen::VectorXd x_flat = flat.Pack(durations, flat_waypoints, flat_end);
  const Eigen::VectorXd x_arc = arc.Pack(durations, arc_waypoints, arc_end);
  const auto time_us = [](auto& objective, const Eigen::VectorXd& x) {
    Eigen::VectorXd gradient(x.size());
    double cost = 0.0;
    constexpr int kRuns = 100;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < kRuns; ++r) ok = objective.Evaluate(x.data(), &cost, gradient.data()) && ok;
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(ok);
    return us / kRuns;
  };
  std::printf("per evaluation with gradient, M = 10: flatness %.1f us (%d + 2 x %d samples), "
              "arc length-yaw %.1f us (%d samples)\n",
              time_us(flat, x_flat), (M - 2) * 17, 33, time_us(arc, x_arc), M * 13);
}

}  // namespace
}  // namespace topay
