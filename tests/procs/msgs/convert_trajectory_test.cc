// poly_trajectory_t <-> the arc length-yaw MINCO trajectory (procs/msgs/convert_trajectory.h):
// the coefficients survive the wire bit for bit and evaluate to the core trajectory's values.

#include "procs/msgs/convert_trajectory.h"

#include <gtest/gtest.h>

#include <vector>

#include "topay_msgs/checked_decode.h"

namespace topay::msgs {
namespace {

constexpr int kJoints = 7;
constexpr int kPieces = 3;

ArcYawTrajectory MakeTrajectory() {
  ArcYawTrajectory trajectory(kJoints, kPieces, {});
  const int dims = kJoints + 2;
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(dims, 3);
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(dims, 3);
  Eigen::MatrixXd waypoints(dims, kPieces - 1);
  head(1, 0) = 0.3;  // yaw at the start
  for (int d = 0; d < dims; ++d) {
    tail(d, 0) = 0.5 + 0.1 * d;
    waypoints(d, 0) = 0.2 + 0.05 * d;
    waypoints(d, 1) = 0.35 + 0.07 * d;
  }
  trajectory.Update(Eigen::Vector2d(1.5, -2.0), head, tail, waypoints, Eigen::Vector3d(0.8, 1.1, 0.9));
  return trajectory;
}

poly_trajectory_t ThroughBytes(const poly_trajectory_t& msg) {
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  std::string error;
  const auto decoded = CheckedDecode<poly_trajectory_t>(bytes.data(), bytes.size(), &error);
  EXPECT_TRUE(decoded) << error;
  return *decoded;
}

TEST(ConvertTrajectory, RoundTripsCoefficientsDurationsAndIds) {
  const ArcYawTrajectory core = MakeTrajectory();
  PolyTrajectory poly = FromArcYaw(core, Eigen::Vector2d(1.5, -2.0));
  poly.trajectory_id = 9;
  poly.goal_id = 4;
  poly.start_utime = 1'700'000'000'000'000;
  const poly_trajectory_t msg = ThroughBytes(ToMessage(poly));
  EXPECT_EQ(msg.num_coeffs, kPieces * (2 + kJoints) * 6);
  std::string error;
  const auto back = FromMessage(msg, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->coefficients, core.minco().coefficients());
  EXPECT_EQ(back->durations_s, core.minco().durations());
  EXPECT_EQ(back->p0_W_m, Eigen::Vector2d(1.5, -2.0));
  EXPECT_EQ(back->yaw0_rad, 0.3);
  EXPECT_EQ(back->trajectory_id, 9);
  EXPECT_EQ(back->goal_id, 4);
  EXPECT_EQ(back->start_utime, poly.start_utime);
  EXPECT_EQ(back->num_joints(), kJoints);
}

TEST(ConvertTrajectory, EvaluatesLikeTheCoreTrajectory) {
  const ArcYawTrajectory core = MakeTrajectory();
  std::string error;
  const auto poly = FromMessage(ToMessage(FromArcYaw(core, Eigen::Vector2d(1.5, -2.0))), &error);
  ASSERT_TRUE(poly) << error;
  Eigen::VectorXd expected(kJoints + 2);
  for (double t = 0.0; t <= core.duration_s(); t += 0.05) {
    double local = 0.0;
    const int piece = core.minco().LocatePiece(t, &local);
    core.minco().EvaluatePiece(piece, local, 0, expected);
    EXPECT_TRUE(poly->Evaluate(t).isApprox(expected, 1e-9)) << "t = " << t;
  }
}

TEST(ConvertTrajectory, RejectsInconsistentMessages) {
  const poly_trajectory_t good = ToMessage(FromArcYaw(MakeTrajectory(), Eigen::Vector2d::Zero()));
  std::string error;
  poly_trajectory_t msg = good;
  msg.num_coeffs -= 6;
  msg.coeffs.resize(msg.num_coeffs);
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("num_coeffs"), std::string::npos);
  msg = good;
  msg.durations_s[1] = 0.0;
  EXPECT_FALSE(FromMessage(msg, &error));
  EXPECT_NE(error.find("durations_s"), std::string::npos);
  msg = good;
  msg.coeffs[5] = NAN;
  EXPECT_FALSE(FromMessage(msg, &error));
}

}  // namespace
}  // namespace topay::msgs
