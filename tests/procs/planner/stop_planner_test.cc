// The planner's safe stop (procs/planner/stop_planner.h): from a point of a moving trajectory, a
// stopping trajectory C2-continuous with it there, at rest at its end, within the robot's limits;
// the blind stop's ratio (stop.blind_duration_per_rate_ratio 1.6) stops in about 70 % of the
// time and 75 % of the distance of the default (3.0; lengthened once by the limit check), still
// within the limits.

#include "procs/planner/stop_planner.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/validate/limit_ratios.h"
#include "tests/procs/tracker/tracker_test_trajectory.h"

namespace topay::planner {
namespace {

struct StopFigures {
  double duration_s = 0.0;
  double distance_m = 0.0;      // arc length run while stopping
  double worst_ratio = 0.0;     // largest value / limit over the samples (WorstRateRatio)
  double start_jump_v = 0.0;    // |v| and |a| differences from the current trajectory at t0
  double start_jump_a = 0.0;
  double end_speed = 0.0;       // |v| + |omega| + max |qd| at the end
};

StopFigures Measure(const ArcYawTrajectory& current, double t0_s, const ArcYawTrajectory& stop, const RobotModel& model) {
  StopFigures f;
  f.duration_s = stop.duration_s();
  TrajectorySample s = stop.MakePoint(), c = current.MakePoint();
  current.Evaluate(t0_s, &c);
  stop.Evaluate(0.0, &s);
  f.start_jump_v = std::abs(s.v_mps - c.v_mps);
  f.start_jump_a = std::abs(s.a_mps2 - c.a_mps2);
  const double s0 = s.s_m;
  for (double t = 0.0; t <= stop.duration_s() + 1e-9; t += 0.01) {
    stop.Evaluate(t, &s);
    f.worst_ratio = std::max(f.worst_ratio, WorstRateRatio(s, model.base_limits, model.joint_limits).ratio);
  }
  stop.Evaluate(stop.duration_s(), &s);
  f.distance_m = s.s_m - s0;
  f.end_speed = std::abs(s.v_mps) + std::abs(s.omega_radps) + s.qd_radps.cwiseAbs().maxCoeff();
  return f;
}

TEST(StopPlanner, TheBlindStopIsShorterAndStillWithinTheLimits) {
  const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                          std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  const StopPlanner planner(model, model.base_limits);
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(model.num_joints());
  // 1.8 m of arc in 4 s with a small turn and joint motion: near its top speed at t0.
  const ArcYawTrajectory current =
      test::TrackerTestTrajectory(Eigen::Vector2d::Zero(), 0.0, q0, 1.8, 0.3, Eigen::VectorXd::Constant(7, 0.2));
  const double t0 = 1.5;
  std::string why;
  const std::optional<ArcYawTrajectory> normal = planner.Make(current, t0, &why);
  ASSERT_TRUE(normal.has_value()) << why;
  const std::optional<ArcYawTrajectory> blind = planner.Make(current, t0, &why, 1.6);
  ASSERT_TRUE(blind.has_value()) << why;
  const StopFigures n = Measure(current, t0, *normal, model), b = Measure(current, t0, *blind, model);
  std::printf("stop from t0 %.1f s: default %.2f s, %.2f m; blind %.2f s, %.2f m (worst limit ratio %.3f)\n", t0,
              n.duration_s, n.distance_m, b.duration_s, b.distance_m, b.worst_ratio);
  EXPECT_GT(n.distance_m, 0.1) << "moving at t0";
  EXPECT_LT(b.duration_s, 0.75 * n.duration_s);  // measured 1.93 s against 2.78 s
  EXPECT_LT(b.distance_m, 0.8 * n.distance_m);    // 0.78 m against 1.06 m
  for (const StopFigures& f : {n, b}) {
    EXPECT_LE(f.worst_ratio, 1.01);  // the validator's limit tolerance
    EXPECT_LT(f.start_jump_v, 1e-6);  // C2 with the current trajectory at t0
    EXPECT_LT(f.start_jump_a, 1e-4);
    EXPECT_LT(f.end_speed, 1e-6);     // at rest
  }
}

}  // namespace
}  // namespace topay::planner
