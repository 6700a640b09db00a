// A trajectory message back into the core trajectory (procs/msgs/trajectory_from_message.h):
// a solved trajectory comes back sample for sample (x, y and every derivative); coefficients
// that are not a MINCO s = 3 solution, or a yaw0 that disagrees, are rejected with the reason.

#include "procs/msgs/trajectory_from_message.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/common/expect_same_motion.h"

#include <cmath>

namespace topay::msgs {
namespace {

constexpr int kJoints = 7;
constexpr int kPieces = 4;
constexpr int kDims = kJoints + 2;

/// A solved trajectory with moving boundaries (non-zero head and tail rates) and uneven pieces.
ArcYawTrajectory MakeTrajectory(const Eigen::Vector2d& p0_W_m) {
  ArcYawTrajectory trajectory(kJoints, kPieces, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(kDims, 3);
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(kDims, 3);
  Eigen::MatrixXd waypoints(kDims, kPieces - 1);
  head(1, 0) = 2.9;   // yaw near pi
  head(0, 1) = 0.2;   // already moving forward
  head(1, 1) = -0.1;
  head(0, 2) = 0.3;
  for (int d = 0; d < kDims; ++d) {
    if (d >= 2) head(d, 0) = -0.4 + 0.1 * d;
    tail(d, 0) = head(d, 0) + 1.2 + 0.1 * d;
    tail(d, 1) = 0.05 * (d % 3);
    for (int i = 0; i < kPieces - 1; ++i) waypoints(d, i) = head(d, 0) + (0.25 + 0.3 * i) * (1.0 + 0.1 * d) + 0.03 * (d % 2);
  }
  Eigen::VectorXd durations(kPieces);
  durations << 0.4, 1.3, 0.9, 2.2;
  trajectory.Update(p0_W_m, head, tail, waypoints, durations);
  return trajectory;
}

PolyTrajectory MakePoly(const Eigen::Vector2d& p0_W_m) {
  std::string error;
  PolyTrajectory poly = FromArcYaw(MakeTrajectory(p0_W_m), p0_W_m);
  poly.trajectory_id = 12;
  poly.goal_id = 3;
  // Through the message, as a receiver gets it.
  std::optional<PolyTrajectory> received = FromMessage(ToMessage(poly), &error);
  EXPECT_TRUE(received) << error;
  return *received;
}

void ExpectSamplesEqual(const TrajectorySample& a, const TrajectorySample& b, double tolerance) {
  topay::testing::ExpectSameMotion(a, b, tolerance, tolerance);
  EXPECT_NEAR(a.s_m, b.s_m, tolerance);
  EXPECT_LE((a.jerk - b.jerk).cwiseAbs().maxCoeff(), tolerance);
}

TEST(TrajectoryFromMessage, BoundaryDataAreTheSolvedProblemsOwn) {
  const Eigen::Vector2d p0(1.5, -2.0);
  const MincoBoundary b = BoundaryOf(MakePoly(p0));
  ASSERT_EQ(b.head.rows(), kDims);
  ASSERT_EQ(b.waypoints.cols(), kPieces - 1);
  EXPECT_NEAR(b.head(1, 0), 2.9, 1e-12);
  EXPECT_NEAR(b.head(0, 1), 0.2, 1e-12);
  EXPECT_NEAR(b.head(0, 2), 0.3, 1e-12);
  EXPECT_NEAR(b.head(1, 1), -0.1, 1e-12);
  EXPECT_NEAR(b.tail(4, 1), 0.05, 1e-9);
  EXPECT_NEAR(b.tail(0, 0), 1.2, 1e-9);
  EXPECT_NEAR(b.waypoints(0, 1), 0.55, 1e-9);
  EXPECT_EQ(b.durations_s(3), 2.2);
}

TEST(TrajectoryFromMessage, RebuildsASolvedTrajectorySampleForSample) {
  const Eigen::Vector2d p0(1.5, -2.0);
  const ArcYawTrajectory original = MakeTrajectory(p0);
  std::string error;
  const std::optional<ArcYawTrajectory> rebuilt = ToArcYaw(MakePoly(p0), {}, &error);
  ASSERT_TRUE(rebuilt) << error;
  EXPECT_LT(RelativeCoefficientError(MakePoly(p0), rebuilt->minco().coefficients()), 1e-12);
  EXPECT_DOUBLE_EQ(rebuilt->duration_s(), original.duration_s());
  TrajectorySample expected = original.MakePoint(), got = rebuilt->MakePoint();
  int samples = 0;
  for (double t = 0.0; t <= original.duration_s() + 1e-12; t += 0.01, ++samples) {
    SCOPED_TRACE(t);
    original.Evaluate(t, &expected);
    rebuilt->Evaluate(t, &got);
    ExpectSamplesEqual(got, expected, 1e-9);
  }
  EXPECT_GT(samples, 400);
  // The base really moved: x, y come from the integration, not from the message.
  original.Evaluate(original.duration_s(), &expected);
  EXPECT_GT((Eigen::Vector2d(expected.state.x_m, expected.state.y_m) - p0).norm(), 0.5);
}

TEST(TrajectoryFromMessage, RejectsCoefficientsThatAreNoMincoSolution) {
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.coefficients(6 * 2 + 4, 3) += 1e-3;  // piece 2's t^4 coefficient of joint 2: C^4 broken
  std::string error;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
  EXPECT_NE(error.find("trajectory 12 (goal 3): not a MINCO s = 3 trajectory"), std::string::npos) << error;

  PolyTrajectory arbitrary = MakePoly(Eigen::Vector2d::Zero());
  arbitrary.coefficients.setRandom();
  arbitrary.yaw0_rad = arbitrary.coefficients(0, 1);
  error.clear();
  EXPECT_FALSE(ToArcYaw(arbitrary, {}, &error));
  EXPECT_NE(error.find("not a MINCO"), std::string::npos) << error;
}

// Found by tests/fuzz/trajectory_message_fuzz.cc (regressions/trajectory_message/): a joint
// coefficient of 3.7e307 made the size of the coefficients overflow, the relative difference
// came out 0 and the trajectory was accepted, though its joints sample to inf.
TEST(TrajectoryFromMessage, RejectsCoefficientsTooLargeToEvaluate) {
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.coefficients(6 * 1 + 2, 4) = 3.7e307;
  std::string error;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
  EXPECT_NE(error.find("not a MINCO s = 3 trajectory"), std::string::npos) << error;
  EXPECT_EQ(RelativeCoefficientError(poly, poly.coefficients), std::numeric_limits<double>::infinity());
}

// Found by tests/fuzz/trajectory_message_fuzz.cc (regressions/trajectory_message/, sixteenth
// session): coefficients of 3e304 (their weighted size just under the evaluable bound) re-solved
// to NaN in one joint; every comparison with NaN being false, the difference came out finite and
// the trajectory was accepted, though it sampled to NaN joints. A re-solve with a non-finite
// coefficient differs infinitely.
TEST(TrajectoryFromMessage, AReSolveWithANonFiniteCoefficientDiffersInfinitely) {
  const PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  Eigen::MatrixXd resolved = poly.coefficients;
  EXPECT_EQ(RelativeCoefficientError(poly, resolved), 0.0);
  resolved(6 * 2 + 3, 5) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(RelativeCoefficientError(poly, resolved), std::numeric_limits<double>::infinity());
  resolved(6 * 2 + 3, 5) = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(RelativeCoefficientError(poly, resolved), std::numeric_limits<double>::infinity());
}

// Found by tests/fuzz/trajectory_message_fuzz.cc (regressions/trajectory_message/): with a
// 9e-20 s or a 135,001 s piece an accepted trajectory, sent again, no longer re-solved to itself.
TEST(TrajectoryFromMessage, RejectsPiecesOutsideTheDurationBounds) {
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.durations_s(2) = 9e-20;
  std::string error;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
  EXPECT_NE(error.find("trajectory 12 (goal 3): piece 2 lasts 9e-20 s, not in [0.001, 100] s"), std::string::npos)
      << error;
  poly = MakePoly(Eigen::Vector2d::Zero());
  poly.durations_s(1) = 135001.0;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
  EXPECT_NE(error.find("piece 1 lasts 135001 s"), std::string::npos) << error;
}

TEST(TrajectoryFromMessage, ToleratesRoundingButNotMore) {
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.coefficients *= 1.0 + 1e-13;  // a scaled MINCO solution is one (the problem is linear)
  std::string error;
  EXPECT_TRUE(ToArcYaw(poly, {.trajectory = {}, .coefficient_tolerance = 1e-9, .yaw0_tolerance_rad = 1e-6}, &error))
      << error;
  poly.coefficients(6 * 1 + 5, 0) *= 1.0 + 1e-6;  // s's t^5 of piece 1
  EXPECT_FALSE(ToArcYaw(poly, {.trajectory = {}, .coefficient_tolerance = 1e-9, .yaw0_tolerance_rad = 1e-6}, &error));
}

TEST(TrajectoryFromMessage, RejectsAYaw0ThatDisagrees) {
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.yaw0_rad += 0.01;
  std::string error;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
  EXPECT_NE(error.find("yaw0_rad"), std::string::npos) << error;
  poly.yaw0_rad = NAN;
  EXPECT_FALSE(ToArcYaw(poly, {}, &error));
}

TEST(TrajectoryFromMessage, ASinglePieceIsAlwaysASolution) {
  // One quintic: head and tail fix all six coefficients, so any finite polynomial is MINCO's.
  PolyTrajectory poly = MakePoly(Eigen::Vector2d::Zero());
  poly.durations_s = Eigen::VectorXd::Constant(1, 1.5);
  poly.coefficients = poly.coefficients.topRows(6).eval();
  poly.coefficients(5, 2) = 0.7;
  std::string error;
  EXPECT_TRUE(ToArcYaw(poly, {}, &error)) << error;
}

}  // namespace
}  // namespace topay::msgs
