#include "core/optimization/trajectory_problem.h"

#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::MakeWorld;
using testing::ReadyJoints;

class TrajectoryProblemTest : public ::testing::Test {
 protected:
  TrajectoryProblemTest()
      : world_(MakeWorld({MakeBox({2.0, 0.0, 0.5}, {0.6, 0.6, 1.0})})),
        reach_(ComputeReachHeights(*world_->kinematics)) {
    problem_.start = MakeState(0.0, 0.0, 0.0, ReadyJoints());
    problem_.X_WE_goal =
        world_->kinematics->EndEffectorPose(MakeState(-1.0, 1.0, 0.3, ReadyJoints()));
  }
  std::string Check(const TrajectoryProblem& problem) const {
    return CheckTrajectoryProblem(problem, *world_->kinematics, world_->arm_field(), reach_);
  }

  std::unique_ptr<testing::OptimizationWorld> world_;
  ReachHeights reach_;
  TrajectoryProblem problem_;
};

TEST_F(TrajectoryProblemTest, ReachBracketsTheEndEffectorOfAnyState) {
  EXPECT_LT(reach_.min_z_m, reach_.max_z_m);
  const double z = problem_.X_WE_goal.translation().z();
  EXPECT_GE(z, reach_.min_z_m);
  EXPECT_LE(z, reach_.max_z_m);
}

TEST_F(TrajectoryProblemTest, AGoodProblemPassesAndEachDefectIsNamed) {
  EXPECT_EQ(Check(problem_), "");
  const auto expect = [&](TrajectoryProblem p, const std::string& part) {
    const std::string why = Check(p);
    EXPECT_NE(why.find(part), std::string::npos) << "'" << why << "' lacks '" << part << "'";
  };
  TrajectoryProblem p = problem_;
  p.start.q_rad.resize(3);
  expect(p, "start state has 3 joints");
  p = problem_;
  p.start.x_m = std::numeric_limits<double>::quiet_NaN();
  expect(p, "start state is not finite");
  p = problem_;
  p.start.q_rad(0) = 100.0;
  expect(p, "start joint 1");
  p = problem_;
  p.base_limits.beta_max_radps2 = 0.0;
  expect(p, "base limits");
  p = problem_;
  p.X_WE_goal.translation().y() = std::numeric_limits<double>::infinity();
  expect(p, "X_WE_goal is not finite");
  p = problem_;
  p.X_WE_goal.linear() *= 2.0;
  expect(p, "not orthonormal");
  p = problem_;
  p.X_WE_goal.translation().z() = reach_.max_z_m + 0.1;
  expect(p, "target out of reach");
  p = problem_;
  p.X_WE_goal.translation() = Eigen::Vector3d(2.0, 0.0, 0.5);  // the box's centre
  expect(p, "target inside an obstacle");
  // A moving start (issue 18): rates of the robot's joint count (or none) and finite.
  p = problem_;
  p.start_rates = WholeBodyRates::Zero(7);
  p.start_rates.v_mps = 0.8;
  EXPECT_EQ(Check(p), "");
  p.start_rates.qdd_radps2.resize(4);
  expect(p, "start rates have joint vectors");
  p = problem_;
  p.start_rates.omega_radps = std::numeric_limits<double>::quiet_NaN();
  expect(p, "start rates are not finite");
}

}  // namespace
}  // namespace topay
