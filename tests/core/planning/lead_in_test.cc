#include "core/planning/lead_in.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/common/angles.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "tests/common/arm_state.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

class LeadInTest : public ::testing::Test {
 protected:
  LeadInTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")) {}

  MovingState Moving(double v, double omega) const {
    MovingState start;
    start.state = BentArmState(0.0, 0.0, 0.4);
    start.rates = WholeBodyRates::Zero(7);
    start.rates.v_mps = v;
    start.rates.omega_radps = omega;
    return start;
  }

  RobotModel model_;
  BaseLimits limits_;  // a_max 0.8 m/s^2
};

TEST_F(LeadInTest, SlowStartHasNone) {
  const LeadIn lead_in = MakeLeadIn(Moving(0.04, 0.5), limits_, model_.joint_limits);
  EXPECT_TRUE(lead_in.empty());
  ASSERT_EQ(lead_in.states.size(), 1u);
  EXPECT_EQ(lead_in.states[0].x_m, 0.0);
  EXPECT_EQ(lead_in.distance_m, 0.0);
}

// Forward at 1 m/s on a left arc of curvature 0.5 / m: v^2 / 2a + 0.1 = 0.725 m of that arc,
// every state on the circle, its heading the arc's tangent, spaced <= 0.02 m.
TEST_F(LeadInTest, FollowsTheCurrentArcOverTheBrakingDistance) {
  const MovingState start = Moving(1.0, 0.5);
  const LeadIn lead_in = MakeLeadIn(start, limits_, model_.joint_limits);
  ASSERT_FALSE(lead_in.empty());
  EXPECT_NEAR(lead_in.distance_m, 1.0 / 1.6 + 0.1, 1e-12);
  const double radius = 2.0, yaw0 = 0.4;
  const Eigen::Vector2d centre(-radius * std::sin(yaw0), radius * std::cos(yaw0));
  double travelled = 0.0;
  for (std::size_t k = 1; k < lead_in.states.size(); ++k) {
    const WholeBodyState& a = lead_in.states[k - 1];
    const WholeBodyState& b = lead_in.states[k];
    const double step = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
    EXPECT_LE(step, 0.02 + 1e-12);
    travelled += step;
    EXPECT_NEAR(std::hypot(b.x_m - centre.x(), b.y_m - centre.y()), radius, 1e-9);
    // Forward: the step points along the heading.
    EXPECT_GT((b.x_m - a.x_m) * std::cos(b.yaw_rad) + (b.y_m - a.y_m) * std::sin(b.yaw_rad), 0.0);
    EXPECT_GT(lead_in.times_s[k], lead_in.times_s[k - 1]);
  }
  EXPECT_NEAR(travelled, lead_in.distance_m, 1e-4);  // chords of an arc
  EXPECT_NEAR(WrapAngle(lead_in.end().yaw_rad - (yaw0 + 0.5 * lead_in.distance_m)), 0.0, 1e-9);
  // Braking at a_max takes v / a = 1.25 s to the stop at 0.625 m.
  EXPECT_GT(lead_in.times_s.back(), 1.25);
}

TEST_F(LeadInTest, BackwardsMotionLeadsBackwards) {
  const LeadIn lead_in = MakeLeadIn(Moving(-0.6, 0.0), limits_, model_.joint_limits);
  ASSERT_FALSE(lead_in.empty());
  const WholeBodyState& end = lead_in.end();
  // Straight back along the heading 0.4 rad: 0.36 / 1.6 + 0.1 = 0.325 m.
  EXPECT_NEAR(end.x_m, -0.325 * std::cos(0.4), 1e-9);
  EXPECT_NEAR(end.y_m, -0.325 * std::sin(0.4), 1e-9);
  EXPECT_NEAR(end.yaw_rad, 0.4, 1e-12);
}

TEST_F(LeadInTest, JointsMoveTowardsTheirBrakingPositionsWithinLimits) {
  MovingState start = Moving(0.5, 0.0);
  start.rates.qd_radps(1) = 0.4;
  start.rates.qd_radps(3) = -0.2;
  const LeadIn lead_in = MakeLeadIn(start, limits_, model_.joint_limits);
  const Eigen::VectorXd& q0 = start.state.q_rad;
  const Eigen::VectorXd& q_end = lead_in.end().q_rad;
  const Eigen::VectorXd& qdd = model_.joint_limits.qdd_max_radps2;
  EXPECT_NEAR(q_end(1), std::min(q0(1) + 0.16 / (2.0 * qdd(1)), model_.joint_limits.q_max_rad(1)),
              1e-12);
  EXPECT_NEAR(q_end(3), std::max(q0(3) - 0.04 / (2.0 * qdd(3)), model_.joint_limits.q_min_rad(3)),
              1e-12);
  EXPECT_EQ(q_end(0), q0(0));
}

TEST_F(LeadInTest, ACollidingLeadInIsReportedAndAClearOnePasses) {
  const Kinematics kinematics(model_);
  Scene scene;
  scene.kind = "lead-in test";
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6));
  // A wall whose face is 0.9 m ahead along +x.
  scene.boxes.push_back(MakeBox(Eigen::Vector3d(1.0, 0.0, 0.75),
                                Eigen::Vector3d(0.2, 3.0, 1.5)));
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics));
  const WholeBodyValidity validity(kinematics, fields.base_field_2d, fields.field_3d);
  const SceneClearanceChecker exact(kinematics, scene);
  MovingState start = Moving(1.0, 0.0);
  start.state.yaw_rad = 0.0;
  bool used_exact = true;
  // Forward: 0.725 m towards the wall face at 0.9 m, with the base's 0.4 m radius.
  const LeadIn towards = MakeLeadIn(start, limits_, model_.joint_limits);
  const std::string reason = CheckLeadIn(towards, validity, &exact, 0.0, 0.0, &used_exact);
  EXPECT_NE(reason.find("moving start: the lead-in"), std::string::npos) << reason;
  // Backwards, away from it: clear.
  start.rates.v_mps = -1.0;
  const LeadIn away = MakeLeadIn(start, limits_, model_.joint_limits);
  EXPECT_EQ(CheckLeadIn(away, validity, &exact, 0.0, 0.0, &used_exact), "");
  EXPECT_FALSE(used_exact);
}

TEST_F(LeadInTest, RejectsBadInput) {
  LeadInOptions options;
  options.step_m = 0.0;
  EXPECT_THROW(MakeLeadIn(Moving(1.0, 0.0), limits_, model_.joint_limits, options),
               std::invalid_argument);
  MovingState start = Moving(1.0, 0.0);
  start.rates.qd_radps.resize(2);
  EXPECT_THROW(MakeLeadIn(start, limits_, model_.joint_limits), std::invalid_argument);
  start = Moving(std::nan(""), 0.0);
  EXPECT_THROW(MakeLeadIn(start, limits_, model_.joint_limits), std::invalid_argument);
}

}  // namespace
}  // namespace topay
