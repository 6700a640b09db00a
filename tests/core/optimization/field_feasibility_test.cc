#include "core/optimization/field_feasibility.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/optimization/optimization_test_world.h"

namespace topay {
namespace {

using testing::MakeState;
using testing::ReadyJoints;

// A quintic rest-to-rest drive of 3 m along x in 4 s (s(t) = 3 (10 u^3 - 15 u^4 + 6 u^5),
// u = t / 4: v peaks at 45 / 32 = 1.406 m/s at u = 1/2, a at 1.083 m/s^2 at
// u = (3 - sqrt 3) / 6), one piece, arm still.
ArcYawTrajectory Drive(double y_m) {
  ArcYawTrajectory trajectory(7, 1, ArcYawTrajectory::Options());
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(9, 3), tail = Eigen::MatrixXd::Zero(9, 3);
  head.col(0).tail(7) = ReadyJoints();
  tail.col(0).tail(7) = ReadyJoints();
  tail(0, 0) = 3.0;
  trajectory.Update(Eigen::Vector2d(0.0, y_m), head, tail, Eigen::MatrixXd(9, 0),
                    Eigen::VectorXd::Constant(1, 4.0));
  return trajectory;
}

class FieldFeasibilityTest : public ::testing::Test {
 protected:
  FieldFeasibilityTest()
      : world_(testing::MakeWorld({MakeBox({1.5, 1.2, 0.5}, {1.0, 0.6, 1.0})})) {}
  FieldFeasibilityReport Check(const ArcYawTrajectory& trajectory, const BaseLimits& limits) {
    return CheckFeasibilityOnFields(trajectory, *world_->kinematics, world_->base_field(),
                                    world_->arm_field(), limits);
  }
  std::unique_ptr<testing::OptimizationWorld> world_;
};

TEST_F(FieldFeasibilityTest, FeasibleDrive) {
  BaseLimits limits;
  limits.v_max_mps = 1.5;
  limits.a_max_mps2 = 1.5;
  const FieldFeasibilityReport report = Check(Drive(-1.5), limits);
  EXPECT_TRUE(report.feasible) << report.first_violation;
  EXPECT_EQ(report.num_samples, 401);  // 0, 0.01, ..., 4.00
  EXPECT_NEAR(report.max_rate_ratio, 1.40625 / 1.5, 1e-6);  // v, sampled at its peak t = 2 s
  EXPECT_GT(report.min_base_clearance_m, 0.5);
  EXPECT_TRUE(DescribeViolations(report).empty());
}

TEST_F(FieldFeasibilityTest, ReportsRateViolationsWithTheWorstRate) {
  // v_max 1: the coupled v-omega ratio (omega = 0) is v / v_max = 1.406, above a's 1.35.
  const FieldFeasibilityReport report = Check(Drive(-1.5), BaseLimits());
  EXPECT_FALSE(report.feasible);
  EXPECT_EQ(report.worst_rate, "v-omega");
  EXPECT_NEAR(report.max_rate_ratio, 1.40625, 1e-6);
  EXPECT_NE(DescribeViolations(report).find("v-omega at 1.406"), std::string::npos)
      << DescribeViolations(report);
}

TEST_F(FieldFeasibilityTest, ReportsClearanceViolations) {
  BaseLimits limits;
  limits.v_max_mps = 1.5;
  limits.a_max_mps2 = 1.5;
  // Passing 0.2 m from the box's face (y = 0.9): the base cylinder (0.4 m) hits it.
  const FieldFeasibilityReport report = Check(Drive(0.7), limits);
  EXPECT_FALSE(report.feasible);
  EXPECT_LT(report.min_base_clearance_m, -0.1);
  EXPECT_NE(report.first_violation.find("base clearance"), std::string::npos)
      << report.first_violation;
  EXPECT_NE(DescribeViolations(report).find("base clearance short by"), std::string::npos);
}

TEST_F(FieldFeasibilityTest, RejectsBadOptions) {
  FieldFeasibilityOptions options;
  options.sample_period_s = 0.0;
  EXPECT_THROW(CheckFeasibilityOnFields(Drive(0.0), *world_->kinematics, world_->base_field(),
                                        world_->arm_field(), BaseLimits(), options),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
