// NmpcOptions::Check and TrackerLimits::Check name the bad field.

#include "core/control/nmpc_options.h"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/control/nmpc_solver.h"
#include "core/control/tracker_limits.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

void ExpectRejected(const std::function<void(NmpcOptions*)>& spoil, const std::string& field) {
  NmpcOptions options;
  spoil(&options);
  try {
    options.Check();
    ADD_FAILURE() << field << " accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(NmpcOptionsTest, DefaultsPass) { EXPECT_NO_THROW(NmpcOptions().Check()); }

TEST(NmpcOptionsTest, BadValuesAreRejectedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ExpectRejected([](NmpcOptions* o) { o->horizon_steps = 1; }, "horizon_steps");
  ExpectRejected([](NmpcOptions* o) { o->step_s = 0.0; }, "step_s");
  ExpectRejected([&](NmpcOptions* o) { o->step_s = nan; }, "step_s");
  ExpectRejected([](NmpcOptions* o) { o->control_period_s = 0.05; }, "control_period_s");
  ExpectRejected([](NmpcOptions* o) { o->latency_s = -0.01; }, "latency_s");
  ExpectRejected([](NmpcOptions* o) { o->time_budget_s = 0.0; }, "time_budget_s");
  ExpectRejected([](NmpcOptions* o) { o->max_iterations = 0; }, "max_iterations");
  ExpectRejected([](NmpcOptions* o) { o->position_weight = -1; }, "position_weight");
  ExpectRejected([](NmpcOptions* o) { o->yaw_weight = 0; }, "yaw_weight");
  ExpectRejected([](NmpcOptions* o) { o->joint_weight = 0; }, "joint_weight");
  ExpectRejected([](NmpcOptions* o) { o->terminal_weight_factor = 0.5; }, "terminal_weight_factor");
  ExpectRejected([](NmpcOptions* o) { o->v_weight = 0; }, "v_weight");
  ExpectRejected([](NmpcOptions* o) { o->omega_weight = 0; }, "omega_weight");
  ExpectRejected([](NmpcOptions* o) { o->qd_weight = 0; }, "qd_weight");
  ExpectRejected([](NmpcOptions* o) { o->a_weight = -1; }, "a_weight");
  ExpectRejected([](NmpcOptions* o) { o->beta_weight = -1; }, "beta_weight");
  ExpectRejected([](NmpcOptions* o) { o->qdd_weight = -1; }, "qdd_weight");
  ExpectRejected([](NmpcOptions* o) { o->limit_weight = 0; }, "limit_weight");
  ExpectRejected([](NmpcOptions* o) { o->stale_state_s = 0; }, "stale_state_s");
  ExpectRejected([](NmpcOptions* o) { o->end_settle_s = -1; }, "end_settle_s");
}

TEST(NmpcOptionsTest, SolverChecksOptionsAndLimits) {
  NmpcOptions options;
  options.step_s = -1.0;
  EXPECT_THROW(NmpcSolver(options, testing::TopayLimits()), std::invalid_argument);
  TrackerLimits limits = testing::TopayLimits();
  limits.base.a_max_mps2 = 0.0;
  try {
    NmpcSolver solver(NmpcOptions(), limits);
    ADD_FAILURE() << "a_max 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a_max_mps2"), std::string::npos);
  }
  limits = testing::TopayLimits();
  limits.qdd_max_radps2.resize(3);
  EXPECT_THROW(limits.Check(), std::invalid_argument);
  NmpcSolver solver(NmpcOptions(), testing::TopayLimits());
  EXPECT_THROW(solver.set_time_budget_s(0.0), std::invalid_argument);
}

TEST(NmpcOptionsTest, LimitsComeFromTheRobotModel) {
  RobotModel robot;
  robot.base_limits = BaseLimits{1.0, 0.8, 0.9, 1.0};
  robot.joint_limits.qd_max_radps = Eigen::VectorXd::Constant(7, 2.35);
  robot.joint_limits.qdd_max_radps2 = Eigen::VectorXd::Constant(7, 6.28);
  const TrackerLimits limits = MakeTrackerLimits(robot);
  EXPECT_EQ(limits.base.omega_max_radps, 0.9);
  EXPECT_EQ(limits.num_joints(), 7);
  EXPECT_TRUE(limits.coupled_v_omega);
}

}  // namespace
}  // namespace topay
