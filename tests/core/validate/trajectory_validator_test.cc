#include "core/validate/trajectory_validator.h"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/robot/self_collision.h"
#include "core/trajectory/arc_yaw_sampling.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/validate/rest_to_rest_motion.h"

namespace topay {
namespace {

using testing::FirstCrossing;
using testing::Ramp;
using testing::RampAcceleration;
using testing::RampRate;
using testing::RestToRest;

constexpr double kPeriod = 0.01;
const double kSqrt3 = std::sqrt(3.0);

RobotModel LoadModel() {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
  return LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
}

// The first sample time of the 10 ms grid at or after t_s.
double FirstSampleAtOrAfter(double t_s) { return std::ceil(t_s / kPeriod - 1e-9) * kPeriod; }

class TrajectoryValidatorTest : public ::testing::Test {
 protected:
  static constexpr int kJoints = 7;

  TrajectoryValidatorTest()
      : model_(LoadModel()), kinematics_(model_), trajectory_(kJoints, 1, {}) {}

  // 2 m straight ahead along +x in 8 s, arm upright (q = 0): peak v = 15/8 * 2/8 = 0.46875
  // m/s at t = 4 s, peak |a| = 10/sqrt(3) * 2/64 = 0.18042 m/s^2.
  RestToRest SlowDrive() const {
    RestToRest motion;
    motion.s_f_m = 2.0;
    motion.duration_s = 8.0;
    motion.q0_rad = Eigen::VectorXd::Zero(kJoints);
    motion.q_f_rad = Eigen::VectorXd::Zero(kJoints);
    return motion;
  }

  static WholeBodyState StartOf(const RestToRest& motion) {
    WholeBodyState start;
    start.x_m = motion.p0_W.x();
    start.y_m = motion.p0_W.y();
    start.yaw_rad = motion.yaw0_rad;
    start.q_rad = motion.q0_rad;
    return start;
  }

  // The trajectory's own end-effector pose at its end.
  Eigen::Isometry3d EndPose() const {
    TrajectorySample point = trajectory_.MakePoint();
    trajectory_.Evaluate(trajectory_.duration_s(), &point);
    return kinematics_.EndEffectorPose(point.state);
  }

  // Validates `motion` in `scene` against its own end pose (or `goal` if given).
  ValidationReport Run(const Scene& scene, const RestToRest& motion,
                       const BaseLimits& limits, const TrajectoryValidatorOptions& options = {},
                       const Eigen::Isometry3d* goal = nullptr) {
    testing::UpdateRestToRest(motion, &trajectory_);
    const TrajectoryValidator validator(kinematics_, scene, limits, options);
    const ValidationReport report =
        validator.Validate(SampleArcYaw(trajectory_), StartOf(motion), goal ? *goal : EndPose());
    RecordProperty("report", report.Report());
    return report;
  }
  ValidationReport Run(const Scene& scene, const RestToRest& motion) {
    return Run(scene, motion, model_.base_limits);
  }

  // An independent evaluation of the self-collision pair distances at time t_s.
  Eigen::VectorXd PairDistancesAt(double t_s) const {
    TrajectorySample point = trajectory_.MakePoint();
    trajectory_.Evaluate(t_s, &point);
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(point.state, &cache);
    const SelfCollision self(kinematics_);
    Eigen::VectorXd distances(self.num_pairs());
    self.Distances(cache, distances);
    return distances;
  }

  RobotModel model_;
  Kinematics kinematics_;
  ArcYawTrajectory trajectory_;
};

TEST_F(TrajectoryValidatorTest, SlowStraightDrivePassesWithHandComputedFigures) {
  // A low post (0.1 m tall, under the chassis top) turned 45 deg, its corner at (1, 0.7): the
  // base cylinder (r 0.40) passes it at x = 1 (t = 4 s, mid-ramp) with clearance 0.7 - 0.4.
  Scene scene;
  scene.boxes.push_back(MakeBox({1.0, 0.7 + 0.1 * std::numbers::sqrt2, 0.05}, {0.2, 0.2, 0.1},
                                std::numbers::pi / 4.0));
  const ValidationReport report = Run(scene, SlowDrive());
  EXPECT_TRUE(report.ok) << report.Report();
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kNone);
  EXPECT_EQ(report.num_samples, 801);  // t = 0, 0.01, ..., 7.99 and 8
  EXPECT_EQ(report.num_failed_samples, 0);
  EXPECT_NEAR(report.min_obstacle.clearance_m, 0.3, 1e-6);
  EXPECT_EQ(report.min_obstacle.part, -1);  // the base cylinder
  EXPECT_EQ(report.min_obstacle.box, 0);
  EXPECT_NEAR(report.min_obstacle.t_s, 4.0, 1e-9);
  EXPECT_NE(report.min_obstacle.name.find("base cylinder"), std::string::npos);
  // Arm upright: the closest self-collision pair is spheres 1 and 3 (centres 0.310 and
  // 0.484 m, radii 0.06 and 0.04): 0.174 - 0.1; the lowest sphere (0.22 m, r 0.06) is
  // 0.22 - 0.06 - 0.155 above the chassis top.
  EXPECT_NEAR(report.min_self.clearance_m, 0.074, 1e-9);
  EXPECT_NE(report.min_self.name.find("sphere 1 (link1) and sphere 3 (link3)"), std::string::npos)
      << report.min_self.name;
  EXPECT_NEAR(report.min_chassis.clearance_m, 0.005, 1e-9);
  EXPECT_EQ(report.min_chassis.part, 0);
  // Worst ratio: v at mid-ramp, 15/8 * 2 m / 8 s over v_max 1 m/s (a: 0.18042 / 0.8).
  EXPECT_EQ(report.worst_limit.limit, Limit::kLinearVelocity);
  EXPECT_NEAR(report.worst_limit.ratio, 15.0 / 8.0 * 2.0 / 8.0, 1e-9);
  EXPECT_NEAR(report.worst_limit.t_s, 4.0, 1e-9);
  // End effector against the hand-made end state (2, 0, 0, q = 0): only the Simpson error of
  // x (bounded by 8/2880 h^4 max|v''''| = 2.4e-5 m, h = 8/12 s).
  WholeBodyState end = StartOf(SlowDrive());
  end.x_m = 2.0;
  const Eigen::Isometry3d X_WE_hand = kinematics_.EndEffectorPose(end);
  const ValidationReport by_hand = Run(scene, SlowDrive(), model_.base_limits, {}, &X_WE_hand);
  EXPECT_TRUE(by_hand.ok) << by_hand.Report();
  // Simpson's error with f = s^(5) = 720 s_f / T^5 constant is exactly T h^4 f / 2880.
  const double simpson_error_m =
      8.0 * std::pow(8.0 / 12.0, 4) * 720.0 * 2.0 / std::pow(8.0, 5) / 2880.0;
  EXPECT_NEAR(by_hand.end_position_error_m, simpson_error_m, 1e-9);
  EXPECT_LT(by_hand.end_orientation_error_rad, 1e-9);
}

TEST_F(TrajectoryValidatorTest, BoxAcrossThePathFailsAsBaseCollisionWhenTheBaseReachesIt) {
  Scene scene;
  scene.boxes.push_back(MakeBox({1.6, 0.0, 0.25}, {0.2, 2.0, 0.5}));  // face at x = 1.5
  const ValidationReport report = Run(scene, SlowDrive());
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kBaseCollision) << failure.message;
  EXPECT_EQ(failure.index, -1);
  EXPECT_EQ(failure.box, 0);
  // Contact when the base front (x + 0.4) reaches 1.5: s = 1.1 m, Ramp(t / 8) = 0.55.
  const double t_contact = 8.0 * FirstCrossing(Ramp, 0.55);
  EXPECT_GE(failure.t_s, t_contact - kPeriod) << failure.message;
  EXPECT_LE(failure.t_s, FirstSampleAtOrAfter(t_contact) + 1e-9) << failure.message;
  EXPECT_LE(failure.value, 0.0);
  EXPECT_GT(failure.value, -0.005);  // at most one 10 ms step (v < 0.47 m/s) deep
  EXPECT_NE(failure.message.find("base cylinder vs box 0"), std::string::npos) << failure.message;
  EXPECT_LT(report.min_obstacle.clearance_m, 0.0);
  EXPECT_GT(report.num_failed_samples, 1);  // the scan goes on past the first failure
  EXPECT_EQ(report.num_samples, 801);
}

TEST_F(TrajectoryValidatorTest, FloatingBoxAtArmHeightFailsNamingTheSphere) {
  // z in [0.5, 0.9], face at x = 1: above the chassis top, so only arm spheres can touch it.
  // The widest sphere within that height is the elbow sphere 5 (link4, r 0.07, z 0.6675).
  Scene scene;
  scene.boxes.push_back(MakeBox({-5.0, 5.0, 0.5}, {1.0, 1.0, 1.0}));  // far away
  scene.boxes.push_back(MakeBox({1.2, 0.1, 0.7}, {0.4, 0.8, 0.4}));
  const ValidationReport report = Run(scene, SlowDrive());
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kArmCollision) << failure.message;
  EXPECT_EQ(failure.index, 5);
  EXPECT_EQ(failure.box, 1);
  EXPECT_NE(failure.message.find("sphere 5 (link4) vs box 1"), std::string::npos)
      << failure.message;
  // Sphere 5's centre is above the base origin (x offset 0): contact at x = 1 - 0.07.
  const double t_contact = 8.0 * FirstCrossing(Ramp, 0.93 / 2.0);
  EXPECT_GE(failure.t_s, t_contact - kPeriod) << failure.message;
  EXPECT_LE(failure.t_s, FirstSampleAtOrAfter(t_contact) + 1e-9) << failure.message;
}

TEST_F(TrajectoryValidatorTest, SameMotionFasterFailsANamedLimit) {
  // The slow drive in 2 s instead of 8: peak a = 10/sqrt(3) * 2/4 = 2.887 m/s^2 (ratio 3.61,
  // at t = 0.423 s), peak v = 1.875 m/s. The acceleration passes a_max (1 %) first.
  RestToRest motion = SlowDrive();
  motion.duration_s = 2.0;
  const ValidationReport report = Run(Scene{}, motion);
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kLimit);
  EXPECT_EQ(failure.limit, Limit::kLinearAcceleration) << failure.message;
  const double a_max = model_.base_limits.a_max_mps2;
  const double t_cross =
      2.0 * FirstCrossing([](double tau) { return 0.5 * RampAcceleration(tau); }, 1.01 * a_max,
                          0.5 - kSqrt3 / 6.0);
  EXPECT_GE(failure.t_s, t_cross - kPeriod) << failure.message;
  EXPECT_LE(failure.t_s, FirstSampleAtOrAfter(t_cross) + 1e-9) << failure.message;
  EXPECT_NE(failure.message.find("linear acceleration"), std::string::npos);
  // Worst ratio on the 10 ms grid, from the closed form.
  double worst = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double tau = k * kPeriod / 2.0;
    worst = std::max({worst, std::abs(0.5 * RampAcceleration(tau)) / a_max,
                      RampRate(tau) / model_.base_limits.v_max_mps});
  }
  EXPECT_EQ(report.worst_limit.limit, Limit::kLinearAcceleration);
  EXPECT_NEAR(report.worst_limit.ratio, worst, 1e-9);
  EXPECT_GT(worst, 3.6);
}

TEST_F(TrajectoryValidatorTest, CoupledVelocityViolationFailsAlthoughVAndOmegaAreWithinLimits) {
  // s and yaw on the same ramp, peaking at 0.7 v_max and 0.7 omega_max together at t = 4 s:
  // both box limits hold, but |v_max omega + omega_max v| = 1.4 v_max omega_max (eq. (9)).
  const BaseLimits& limits = model_.base_limits;
  RestToRest motion = SlowDrive();
  motion.s_f_m = 0.7 * limits.v_max_mps * 8.0 / 1.875;
  motion.yaw_f_rad = 0.7 * limits.omega_max_radps * 8.0 / 1.875;
  const ValidationReport report = Run(Scene{}, motion);
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kLimit);
  EXPECT_EQ(failure.limit, Limit::kCoupledVelocity) << failure.message;
  // Coupled ratio 1.4 RampRate / 1.875 crosses 1.01.
  const double t_cross =
      8.0 * FirstCrossing([](double tau) { return 1.4 * RampRate(tau) / 1.875; }, 1.01, 0.5);
  EXPECT_GE(failure.t_s, t_cross - kPeriod) << failure.message;
  EXPECT_LE(failure.t_s, FirstSampleAtOrAfter(t_cross) + 1e-9) << failure.message;
  EXPECT_EQ(report.worst_limit.limit, Limit::kCoupledVelocity);
  EXPECT_NEAR(report.worst_limit.ratio, 1.4, 1e-9);
  EXPECT_NEAR(report.worst_limit.t_s, 4.0, 1e-9);
  // The box limits alone would pass: v and omega each peak at 70 % of their limits.
  TrajectorySample point = trajectory_.MakePoint();
  trajectory_.Evaluate(4.0, &point);
  EXPECT_NEAR(point.v_mps / limits.v_max_mps, 0.7, 1e-9);
  EXPECT_NEAR(point.omega_radps / limits.omega_max_radps, 0.7, 1e-9);
}

TEST_F(TrajectoryValidatorTest, JointBeyondItsPositionLimitFails) {
  // Joint 1 (about the upright arm's own axis, limit 3.1 rad) turns to 3.3 rad.
  RestToRest motion = SlowDrive();
  motion.s_f_m = 0.0;
  motion.q_f_rad(0) = 3.3;
  const ValidationReport report = Run(Scene{}, motion);
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kLimit);
  EXPECT_EQ(failure.limit, Limit::kJointPosition) << failure.message;
  EXPECT_EQ(failure.index, 0);
  EXPECT_NE(failure.message.find("joint1 (index 0)"), std::string::npos) << failure.message;
  const double t_cross = 8.0 * FirstCrossing([](double tau) { return 3.3 * Ramp(tau); }, 3.1);
  EXPECT_GE(failure.t_s, t_cross - kPeriod) << failure.message;
  EXPECT_LE(failure.t_s, FirstSampleAtOrAfter(t_cross) + 1e-9) << failure.message;
  EXPECT_DOUBLE_EQ(failure.threshold, 3.1);
  // Worst ratio |q - mid| / half range at the end: 3.3 / 3.1.
  EXPECT_EQ(report.worst_limit.limit, Limit::kJointPosition);
  EXPECT_NEAR(report.worst_limit.ratio, 3.3 / 3.1, 1e-9);
  EXPECT_NEAR(report.worst_limit.t_s, 8.0, 1e-12);
}

TEST_F(TrajectoryValidatorTest, WrongEndEffectorGoalFailsWithTheErrorValues) {
  testing::UpdateRestToRest(SlowDrive(), &trajectory_);
  const Eigen::Isometry3d X_WE_end = EndPose();
  // 2 cm off in position.
  Eigen::Isometry3d shifted = X_WE_end;
  shifted.translation() += Eigen::Vector3d(0.0, 0.02, 0.0);
  ValidationReport report = Run(Scene{}, SlowDrive(), model_.base_limits, {}, &shifted);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kEndEffectorPosition);
  EXPECT_NEAR(report.first_failure.t_s, 8.0, 1e-12);
  EXPECT_NEAR(report.end_position_error_m, 0.02, 1e-12);
  EXPECT_NEAR(report.end_orientation_error_rad, 0.0, 1e-9);
  EXPECT_NE(report.first_failure.message.find("0.02 m"), std::string::npos)
      << report.first_failure.message;
  // 0.05 rad off in orientation (about a tilted axis), position right.
  Eigen::Isometry3d rotated = X_WE_end;
  rotated.linear() =
      X_WE_end.linear() * Eigen::AngleAxisd(0.05, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  report = Run(Scene{}, SlowDrive(), model_.base_limits, {}, &rotated);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kEndEffectorOrientation);
  EXPECT_NEAR(report.end_orientation_error_rad, 0.05, 1e-9);
  EXPECT_NEAR(report.end_position_error_m, 0.0, 1e-12);
  // Within tolerance (5 mm, 0.01 rad): passes.
  Eigen::Isometry3d near = X_WE_end;
  near.translation() += Eigen::Vector3d(0.005, 0.0, 0.0);
  near.linear() = X_WE_end.linear() * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX()).matrix();
  report = Run(Scene{}, SlowDrive(), model_.base_limits, {}, &near);
  EXPECT_TRUE(report.ok) << report.Report();
  EXPECT_NEAR(report.end_position_error_m, 0.005, 1e-12);
  EXPECT_NEAR(report.end_orientation_error_rad, 0.01, 1e-9);
}

TEST_F(TrajectoryValidatorTest, StartMismatchFailsAtTimeZero) {
  testing::UpdateRestToRest(SlowDrive(), &trajectory_);
  const TrajectoryValidator validator(kinematics_, Scene{}, model_.base_limits);
  const SampledTrajectory sampled = SampleArcYaw(trajectory_);
  WholeBodyState start = StartOf(SlowDrive());
  start.y_m += 0.005;
  ValidationReport report = validator.Validate(sampled, start, EndPose());
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kStart);
  EXPECT_EQ(report.first_failure.t_s, 0.0);
  EXPECT_NEAR(report.first_failure.value, 0.005, 1e-12);
  // A joint 2 mrad off is named.
  start = StartOf(SlowDrive());
  start.q_rad(4) = 0.002;
  report = validator.Validate(sampled, start, EndPose());
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kStart);
  EXPECT_EQ(report.first_failure.index, 4);
  EXPECT_NE(report.first_failure.message.find("joint5"), std::string::npos);
  // Yaw compared modulo 2 pi, and 0.5 mm / 0.5 mrad are within the tolerance.
  start = StartOf(SlowDrive());
  start.yaw_rad = 2.0 * std::numbers::pi + 0.0005;
  start.x_m = 0.0005;
  report = validator.Validate(sampled, start, EndPose());
  EXPECT_TRUE(report.ok) << report.Report();
}

// Wraps the arc length-yaw sampler and overwrites one quantity with NaN from t_bad_s on
// (for one 10 ms step).
SampledTrajectory WithNaN(const SampledTrajectory& inner, double t_bad_s, bool in_joint) {
  SampledTrajectory wrapped = inner;
  wrapped.make_sampler = [inner, t_bad_s, in_joint]() -> TrajectorySampler {
    TrajectorySampler sampler = inner.make_sampler();
    return [sampler, t_bad_s, in_joint](double t_s, TrajectorySample* sample) {
      sampler(t_s, sample);
      if (t_s >= t_bad_s - 1e-9 && t_s < t_bad_s + 0.005) {
        (in_joint ? sample->state.q_rad(2) : sample->omega_radps) =
            std::numeric_limits<double>::quiet_NaN();
      }
    };
  };
  return wrapped;
}

TEST_F(TrajectoryValidatorTest, NaNInTheTrajectoryFailsCleanlyNamingTimeAndQuantity) {
  testing::UpdateRestToRest(SlowDrive(), &trajectory_);
  const TrajectoryValidator validator(kinematics_, Scene{}, model_.base_limits);
  const WholeBodyState start = StartOf(SlowDrive());
  ValidationReport report =
      validator.Validate(WithNaN(SampleArcYaw(trajectory_), 1.0, false), start, EndPose());
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kNonFinite);
  EXPECT_NEAR(report.first_failure.t_s, 1.0, 1e-9);
  EXPECT_NE(report.first_failure.message.find("t = 1.000 s: omega_radps"), std::string::npos)
      << report.first_failure.message;
  EXPECT_EQ(report.num_samples, 801);  // the other samples are still checked
  EXPECT_EQ(report.num_failed_samples, 1);
  report = validator.Validate(WithNaN(SampleArcYaw(trajectory_), 8.0, true), start, EndPose());
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kNonFinite);
  EXPECT_EQ(report.first_failure.index, 2);
  EXPECT_NE(report.first_failure.message.find("q_rad of joint3"), std::string::npos)
      << report.first_failure.message;
  EXPECT_TRUE(std::isnan(report.end_position_error_m));  // the end state was not usable
}

TEST_F(TrajectoryValidatorTest, BadDurationsSamplersAndInputsFailWithoutThrowing) {
  testing::UpdateRestToRest(SlowDrive(), &trajectory_);
  const TrajectoryValidator validator(kinematics_, Scene{}, model_.base_limits);
  const WholeBodyState start = StartOf(SlowDrive());
  const Eigen::Isometry3d goal = EndPose();
  for (double duration : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity(), 1e9}) {
    SampledTrajectory sampled = SampleArcYaw(trajectory_);
    sampled.duration_s = duration;
    const ValidationReport report = validator.Validate(sampled, start, goal);
    EXPECT_FALSE(report.ok) << duration;
    EXPECT_EQ(report.first_failure.check, ValidationCheck::kInput) << duration;
    EXPECT_NE(report.first_failure.message.find("duration_s"), std::string::npos);
    EXPECT_EQ(report.num_samples, 0);
  }
  // A sampler that throws at t >= 3 s: a failure at 3 s, not an exception.
  SampledTrajectory throwing = SampleArcYaw(trajectory_);
  throwing.make_sampler = [inner = throwing]() -> TrajectorySampler {
    return [sampler = inner.make_sampler()](double t_s, TrajectorySample* sample) {
      if (t_s >= 3.0 - 1e-9) throw std::runtime_error("out of coefficients");
      sampler(t_s, sample);
    };
  };
  ValidationReport report = validator.Validate(throwing, start, goal);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kSampler);
  EXPECT_NEAR(report.first_failure.t_s, 3.0, 1e-9);
  EXPECT_NE(report.first_failure.message.find("out of coefficients"), std::string::npos);
  // Wrong sizes, empty sampler, non-finite start, a goal that is not a pose.
  SampledTrajectory empty = SampleArcYaw(trajectory_);
  empty.make_sampler = nullptr;
  EXPECT_EQ(validator.Validate(empty, start, goal).first_failure.check, ValidationCheck::kInput);
  WholeBodyState short_start = start;
  short_start.q_rad.resize(6);
  report = validator.Validate(SampleArcYaw(trajectory_), short_start, goal);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kInput);
  EXPECT_NE(report.first_failure.message.find("start state has 6 joints"), std::string::npos);
  WholeBodyState nan_start = start;
  nan_start.yaw_rad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validator.Validate(SampleArcYaw(trajectory_), nan_start, goal).first_failure.check,
            ValidationCheck::kInput);
  Eigen::Isometry3d sheared = goal;
  sheared.linear()(0, 1) += 0.1;
  EXPECT_EQ(validator.Validate(SampleArcYaw(trajectory_), start, sheared).first_failure.check,
            ValidationCheck::kInput);
}

TEST_F(TrajectoryValidatorTest, SelfCollidingArmFailsAsSelfCollision) {
  // Base still; the arm folds (elbow joint4 and wrist joint6 to 2 rad) until the tool sphere
  // meets the shoulder: both joints stay within their limits (2.355, 2.23 rad).
  RestToRest motion = SlowDrive();
  motion.s_f_m = 0.0;
  motion.q_f_rad(3) = 2.0;
  motion.q_f_rad(5) = 2.0;
  const ValidationReport report = Run(Scene{}, motion);
  ASSERT_FALSE(report.ok);
  const ValidationFailure& failure = report.first_failure;
  EXPECT_EQ(failure.check, ValidationCheck::kSelfCollision) << failure.message;
  ASSERT_GE(failure.index, 0);
  // Independently: the named pair overlaps at the failure time, and no pair did 10 ms before.
  const Eigen::VectorXd at = PairDistancesAt(failure.t_s);
  EXPECT_LE(at(failure.index), 0.0);
  EXPECT_NEAR(at(failure.index), failure.value, 1e-12);
  EXPECT_GT(PairDistancesAt(failure.t_s - kPeriod).minCoeff(), 0.0);
  EXPECT_NE(failure.message.find("self-collision pair"), std::string::npos);
  EXPECT_LT(report.min_self.clearance_m, 0.0);
}

TEST_F(TrajectoryValidatorTest, OnePercentLimitTolerance) {
  // Peak v of the slow drive is 0.46875 m/s at t = 4 s (a sample); choose v_max so that the
  // ratio is exactly 1.005, then 1.02.
  const double v_peak = 15.0 / 8.0 * 2.0 / 8.0;
  BaseLimits limits = model_.base_limits;
  limits.v_max_mps = v_peak / 1.005;
  ValidationReport report = Run(Scene{}, SlowDrive(), limits);
  EXPECT_TRUE(report.ok) << report.Report();
  EXPECT_EQ(report.worst_limit.limit, Limit::kLinearVelocity);
  EXPECT_NEAR(report.worst_limit.ratio, 1.005, 1e-9);
  limits.v_max_mps = v_peak / 1.02;
  report = Run(Scene{}, SlowDrive(), limits);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.limit, Limit::kLinearVelocity) << report.first_failure.message;
  EXPECT_NEAR(report.worst_limit.ratio, 1.02, 1e-9);
  // Ratio v / v_max = 1.02 RampRate / 1.875 first passes 1.01.
  const double t_cross =
      8.0 * FirstCrossing([](double tau) { return 1.02 * RampRate(tau) / 1.875; }, 1.01, 0.5);
  EXPECT_LE(report.first_failure.t_s, FirstSampleAtOrAfter(t_cross) + 1e-9);
  EXPECT_GE(report.first_failure.t_s, t_cross - kPeriod);
}

TEST_F(TrajectoryValidatorTest, EndNotAtRestFails) {
  RestToRest motion = SlowDrive();
  motion.v_end_mps = 0.1;
  const ValidationReport report = Run(Scene{}, motion);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kEndNotAtRest)
      << report.first_failure.message;
  EXPECT_NEAR(report.first_failure.value, 0.1, 1e-9);
  EXPECT_NEAR(report.first_failure.t_s, 8.0, 1e-12);
}

TEST_F(TrajectoryValidatorTest, SamplesEveryPeriodAndTheExactEnd) {
  for (double duration : {8.0, 1.234567, 0.004}) {
    RestToRest motion = SlowDrive();
    motion.duration_s = duration;
    motion.s_f_m = 0.0;
    testing::UpdateRestToRest(motion, &trajectory_);
    auto times = std::make_shared<std::vector<double>>();
    SampledTrajectory recording = SampleArcYaw(trajectory_);
    recording.make_sampler = [inner = recording, times]() -> TrajectorySampler {
      return [sampler = inner.make_sampler(), times](double t_s, TrajectorySample* sample) {
        times->push_back(t_s);
        sampler(t_s, sample);
      };
    };
    const TrajectoryValidator validator(kinematics_, Scene{}, model_.base_limits);
    const ValidationReport report = validator.Validate(recording, StartOf(motion), EndPose());
    EXPECT_TRUE(report.ok) << report.Report();
    ASSERT_EQ(static_cast<int>(times->size()), report.num_samples);
    const int expected = static_cast<int>(std::ceil(duration / kPeriod - 1e-9)) + 1;
    EXPECT_EQ(report.num_samples, expected) << duration;
    EXPECT_EQ(times->front(), 0.0);
    EXPECT_EQ(times->back(), duration);
    for (std::size_t k = 1; k + 1 < times->size(); ++k) {
      EXPECT_NEAR((*times)[k] - (*times)[k - 1], kPeriod, 1e-12);
    }
    EXPECT_LE(times->back() - (*times)[times->size() - 2], kPeriod + 1e-12);
    EXPECT_GT(times->back() - (*times)[times->size() - 2], 0.0);
  }
}

TEST_F(TrajectoryValidatorTest, StopAtFirstFailureEndsTheScanEarly) {
  Scene scene;
  scene.boxes.push_back(MakeBox({1.6, 0.0, 0.25}, {0.2, 2.0, 0.5}));
  TrajectoryValidatorOptions options;
  options.stop_at_first_failure = true;
  const ValidationReport report = Run(scene, SlowDrive(), model_.base_limits, options);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kBaseCollision);
  EXPECT_EQ(report.num_failed_samples, 1);
  EXPECT_EQ(report.num_samples,
            static_cast<int>(std::lround(report.first_failure.t_s / kPeriod)) + 1);
}

TEST_F(TrajectoryValidatorTest, ObstacleMarginIsApplied) {
  // The slow drive passes the post at 0.3 m: a 0.35 m margin makes that a failure.
  Scene scene;
  scene.boxes.push_back(MakeBox({1.0, 0.7 + 0.1 * std::numbers::sqrt2, 0.05}, {0.2, 0.2, 0.1},
                                std::numbers::pi / 4.0));
  TrajectoryValidatorOptions options;
  options.obstacle_margin_m = 0.35;
  const ValidationReport report = Run(scene, SlowDrive(), model_.base_limits, options);
  ASSERT_FALSE(report.ok);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kBaseCollision);
  EXPECT_NEAR(report.min_obstacle.clearance_m, 0.3, 1e-6);
}

TEST_F(TrajectoryValidatorTest, ConcurrentValidationsAgree) {
  Scene scene;
  scene.boxes.push_back(MakeBox({1.2, 0.1, 0.7}, {0.4, 0.8, 0.4}));
  RestToRest motion = SlowDrive();
  testing::UpdateRestToRest(motion, &trajectory_);
  const TrajectoryValidator validator(kinematics_, scene, model_.base_limits);
  const SampledTrajectory sampled = SampleArcYaw(trajectory_);
  const Eigen::Isometry3d goal = EndPose();
  const WholeBodyState start = StartOf(motion);
  const ValidationReport serial = validator.Validate(sampled, start, goal);
  std::vector<ValidationReport> reports(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    ValidationReport* out = &reports[i];
    threads.emplace_back([&validator, &sampled, &start, &goal, out] {
      *out = validator.Validate(sampled, start, goal);
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const ValidationReport& report : reports) {
    EXPECT_EQ(report.Report(), serial.Report());
    EXPECT_EQ(report.min_obstacle.clearance_m, serial.min_obstacle.clearance_m);
    EXPECT_EQ(report.first_failure.t_s, serial.first_failure.t_s);
  }
}

TEST_F(TrajectoryValidatorTest, PerSampleChecksDoNotAllocate) {
  // A passing validation allocates only its setup: as many allocations for 8 s (801
  // samples) as for 16 s (1601 samples).
  Scene scene;
  scene.boxes.push_back(MakeBox({1.0, 0.8, 0.05}, {0.2, 0.2, 0.1}));
  const TrajectoryValidator validator(kinematics_, scene, model_.base_limits);
  int counts[2];
  for (int i = 0; i < 2; ++i) {
    RestToRest motion = SlowDrive();
    motion.duration_s = 8.0 * (i + 1);
    testing::UpdateRestToRest(motion, &trajectory_);
    const SampledTrajectory sampled = SampleArcYaw(trajectory_);
    const Eigen::Isometry3d goal = EndPose();
    const WholeBodyState start = StartOf(motion);
    testing::AllocationCounter counter;
    const ValidationReport report = validator.Validate(sampled, start, goal);
    counts[i] = counter.count();
    EXPECT_TRUE(report.ok) << report.Report();
  }
  EXPECT_EQ(counts[0], counts[1]);
}

TEST_F(TrajectoryValidatorTest, ConstructorRejectsBadOptionsAndLimitsByName) {
  TrajectoryValidatorOptions options;
  options.sample_period_s = 0.0;
  try {
    TrajectoryValidator(kinematics_, Scene{}, model_.base_limits, options);
    ADD_FAILURE() << "no exception for sample_period_s = 0";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("sample_period_s"), std::string::npos);
  }
  options = {};
  options.limit_tolerance = -0.01;
  EXPECT_THROW(TrajectoryValidator(kinematics_, Scene{}, model_.base_limits, options),
               std::invalid_argument);
  BaseLimits limits = model_.base_limits;
  limits.omega_max_radps = std::numeric_limits<double>::quiet_NaN();
  try {
    TrajectoryValidator(kinematics_, Scene{}, limits);
    ADD_FAILURE() << "no exception for a NaN omega_max";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("omega_max_radps"), std::string::npos);
  }
}

// A stop (the plan's time limit) during the check ends it at the next sample, and a
// trajectory checked in part is never validated, even if every checked sample passed.
TEST_F(TrajectoryValidatorTest, AStopEndsTheCheckAndIsAFailure) {
  const RestToRest motion = SlowDrive();
  testing::UpdateRestToRest(motion, &trajectory_);
  const TrajectoryValidator validator(kinematics_, Scene{}, model_.base_limits);
  const SampledTrajectory full = SampleArcYaw(trajectory_);
  std::stop_source stop;
  SampledTrajectory stopping = full;
  stopping.make_sampler = [&full, &stop] {
    auto calls = std::make_shared<int>(0);
    TrajectorySampler inner = full.make_sampler();
    return TrajectorySampler([inner, calls, &stop](double t_s, TrajectorySample* sample) {
      if (++*calls == 100) stop.request_stop();  // during the 100th of 801 samples
      inner(t_s, sample);
    });
  };
  const ValidationReport report =
      validator.Validate(stopping, StartOf(motion), EndPose(), stop.get_token());
  EXPECT_FALSE(report.ok) << report.Report();
  EXPECT_TRUE(report.stopped);
  EXPECT_EQ(report.num_samples, 100);
  EXPECT_EQ(report.first_failure.check, ValidationCheck::kStopped);
  EXPECT_NE(report.first_failure.message.find("not validated"), std::string::npos)
      << report.first_failure.message;
  // The same trajectory without the stop passes.
  const ValidationReport whole = validator.Validate(full, StartOf(motion), EndPose());
  EXPECT_TRUE(whole.ok) << whole.Report();
  EXPECT_FALSE(whole.stopped);
  EXPECT_EQ(whole.num_samples, 801);
}

}  // namespace
}  // namespace topay

namespace topay {
namespace {

// Issue 18: a moving start. A 2 m drive in 8 s whose head moves (v 0.3 m/s, omega 0.1 rad/s,
// a 0.05, beta -0.02, joint 3 at 0.05 rad/s and 0.02 rad/s^2) passes against its own rates
// and fails, naming the rate, against others; a rest start's rates are not checked.
class MovingStartValidationTest : public ::testing::Test {
 protected:
  static constexpr int kJoints = 7;
  MovingStartValidationTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        trajectory_(kJoints, 1, {}) {
    rates_ = WholeBodyRates::Zero(kJoints);
    rates_.v_mps = 0.3;
    rates_.omega_radps = 0.1;
    rates_.a_mps2 = 0.05;
    rates_.beta_radps2 = -0.02;
    rates_.qd_radps(2) = 0.05;
    rates_.qdd_radps2(2) = 0.02;
    Eigen::MatrixXd head = Eigen::MatrixXd::Zero(kJoints + 2, 3);
    head.col(1) << rates_.v_mps, rates_.omega_radps, rates_.qd_radps;
    head.col(2) << rates_.a_mps2, rates_.beta_radps2, rates_.qdd_radps2;
    Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(kJoints + 2, 3);
    tail(0, 0) = 2.0;
    tail(1, 0) = 0.3;
    tail(4, 0) = 0.2;
    trajectory_.Update(Eigen::Vector2d::Zero(), head, tail,
                       Eigen::MatrixXd::Zero(kJoints + 2, 0), Eigen::VectorXd::Constant(1, 8.0));
    start_.q_rad = Eigen::VectorXd::Zero(kJoints);
    TrajectorySample end = trajectory_.MakePoint();
    trajectory_.Evaluate(8.0, &end);
    X_WE_goal_ = kinematics_.EndEffectorPose(end.state);
  }

  ValidationReport Validate(const WholeBodyRates& rates) const {
    const TrajectoryValidator validator(kinematics_, Scene(), model_.base_limits);
    return validator.Validate(SampleArcYaw(trajectory_), MovingState{start_, rates}, X_WE_goal_);
  }

  RobotModel model_;
  Kinematics kinematics_;
  ArcYawTrajectory trajectory_;
  WholeBodyRates rates_;
  WholeBodyState start_;
  Eigen::Isometry3d X_WE_goal_;
};

TEST_F(MovingStartValidationTest, PassesAgainstItsOwnRates) {
  const ValidationReport report = Validate(rates_);
  EXPECT_TRUE(report.ok) << report.Report();
}

TEST_F(MovingStartValidationTest, EachMismatchedRateFailsTheStartCheckByName) {
  struct Case {
    const char* name;
    void (*change)(WholeBodyRates*);
  };
  const Case cases[] = {
      {"forward speed v", [](WholeBodyRates* r) { r->v_mps += 0.002; }},
      {"yaw rate omega", [](WholeBodyRates* r) { r->omega_radps -= 0.002; }},
      {"forward acceleration a", [](WholeBodyRates* r) { r->a_mps2 += 0.002; }},
      {"yaw acceleration beta", [](WholeBodyRates* r) { r->beta_radps2 += 0.002; }},
      {"velocity", [](WholeBodyRates* r) { r->qd_radps(2) = 0.0; }},
      {"acceleration", [](WholeBodyRates* r) { r->qdd_radps2(5) = 0.01; }},
  };
  for (const Case& c : cases) {
    WholeBodyRates rates = rates_;
    c.change(&rates);
    const ValidationReport report = Validate(rates);
    EXPECT_FALSE(report.ok) << c.name;
    EXPECT_EQ(report.first_failure.check, ValidationCheck::kStart) << c.name;
    EXPECT_EQ(report.first_failure.t_s, 0.0) << c.name;
    EXPECT_NE(report.first_failure.message.find(c.name), std::string::npos)
        << report.first_failure.message;
  }
  // Within the tolerance (1e-3 by default) it passes.
  WholeBodyRates close = rates_;
  close.v_mps += 5e-4;
  close.qdd_radps2(2) -= 5e-4;
  EXPECT_TRUE(Validate(close).ok);
}

TEST_F(MovingStartValidationTest, RestRatesFailAMovingTrajectoryButTheRestCallDoesNotCheck) {
  EXPECT_EQ(Validate(WholeBodyRates{}).first_failure.check, ValidationCheck::kStart);
  const TrajectoryValidator validator(kinematics_, Scene(), model_.base_limits);
  EXPECT_TRUE(validator.Validate(SampleArcYaw(trajectory_), start_, X_WE_goal_).ok);
}

TEST_F(MovingStartValidationTest, BadRatesAreBadInput) {
  WholeBodyRates rates = rates_;
  rates.qd_radps.resize(3);
  EXPECT_EQ(Validate(rates).first_failure.check, ValidationCheck::kInput);
  rates = rates_;
  rates.beta_radps2 = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Validate(rates).first_failure.check, ValidationCheck::kInput);
}

}  // namespace
}  // namespace topay
