// The protective field: its length from speed, which kept points it counts (inside the moved
// base cylinder, in the height band, enough of them, from a fresh scan), and the base path ahead
// on a reference.

#include "core/control/protective_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace topay {
namespace {

constexpr double kRadius = 0.40;

BaseCylinder Base() { return BaseCylinder{kRadius, 0.155}; }
BaseLimits Limits() { return BaseLimits{1.0, 0.8, 0.9, 1.0}; }

// The base axis along +x from the origin, 2 cm apart, `length_m` long.
std::vector<Eigen::Vector2d> StraightPath(double length_m) {
  std::vector<Eigen::Vector2d> path;
  for (double x = 0.0; x <= length_m + 1e-9; x += 0.02) path.emplace_back(x, 0.0);
  return path;
}

// `count` points around (x, y) at height z, 1 mm apart in z.
std::vector<Eigen::Vector3f> Cluster(double x, double y, double z, int count) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < count; ++i) points.emplace_back(x, y, z + 0.001 * i);
  return points;
}

TEST(ProtectiveFieldTest, LengthIsReactionPlusBrakingPlusLookahead) {
  const ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  EXPECT_DOUBLE_EQ(field.LengthM(0.0), 0.10);
  // 1 m/s: 0.25 s of reaction, 1 / (2 x 0.8) m of braking, 0.1 m.
  EXPECT_NEAR(field.LengthM(1.0), 0.25 + 0.625 + 0.10, 1e-12);
  EXPECT_NEAR(field.LengthM(-0.5), 0.5 * 0.25 + 0.25 / 1.6 + 0.10, 1e-12);
  EXPECT_DOUBLE_EQ(field.LengthM(3.0), field.LengthM(1.0));  // capped at v_max
  EXPECT_NEAR(field.ReachM(), field.LengthM(1.0) + 0.35 + kRadius - 0.05, 1e-12);
}

TEST(ProtectiveFieldTest, AnObstacleOnThePathIsEnteredWhereTheBaseWouldReachIt) {
  ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  field.SetScan(Cluster(1.0, 0.0, 0.2, 10), 0.0, Eigen::Vector2d::Zero());
  EXPECT_EQ(field.num_kept(), 10);
  const ProtectiveFieldCheck check = field.Check(StraightPath(0.9), 0.05);
  EXPECT_TRUE(check.scan_fresh);
  EXPECT_TRUE(check.entered);
  EXPECT_EQ(check.num_inside, 10);
  // The field's cylinder (radius 0.35) first holds x = 1 at the pose x = 0.66 (next 2 cm step).
  EXPECT_NEAR(check.distance_ahead_m, 0.66, 0.021);
  EXPECT_NEAR(check.path_length_m, 0.9, 1e-9);
  EXPECT_FLOAT_EQ(check.p_W_first.x(), 1.0f);
  // A shorter path (a slower robot) stops short of it.
  EXPECT_FALSE(field.Check(StraightPath(0.6), 0.05).entered);
  EXPECT_EQ(field.Check(StraightPath(0.6), 0.05).num_inside, 0);
}

TEST(ProtectiveFieldTest, ThePointMustLieRadialMarginInsideTheOutline) {
  ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  // Beside a straight path: 0.36 m from the axis (4 cm inside the outline) is a graze, 0.34 m
  // (6 cm inside) is an obstacle on the path.
  field.SetScan(Cluster(0.5, 0.36, 0.2, 10), 0.0, Eigen::Vector2d::Zero());
  EXPECT_FALSE(field.Check(StraightPath(1.0), 0.0).entered);
  field.SetScan(Cluster(0.5, 0.34, 0.2, 10), 0.0, Eigen::Vector2d::Zero());
  EXPECT_TRUE(field.Check(StraightPath(1.0), 0.0).entered);
  ProtectiveFieldOptions wide;
  wide.radial_margin_m = 0.0;
  ProtectiveField wide_field(wide, Base(), Limits());
  wide_field.SetScan(Cluster(0.5, 0.39, 0.2, 10), 0.0, Eigen::Vector2d::Zero());
  EXPECT_TRUE(wide_field.Check(StraightPath(1.0), 0.0).entered);
}

TEST(ProtectiveFieldTest, FewerThanMinPointsDoNotStopTheRobot) {
  ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  field.SetScan(Cluster(0.5, 0.0, 0.2, 4), 0.0, Eigen::Vector2d::Zero());
  const ProtectiveFieldCheck four = field.Check(StraightPath(1.0), 0.0);
  EXPECT_EQ(four.num_inside, 4);
  EXPECT_FALSE(four.entered);
  field.SetScan(Cluster(0.5, 0.0, 0.2, 5), 0.0, Eigen::Vector2d::Zero());
  EXPECT_TRUE(field.Check(StraightPath(1.0), 0.0).entered);
}

TEST(ProtectiveFieldTest, OnlyPointsInTheHeightBandAndWithinReachAreKept) {
  ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  std::vector<Eigen::Vector3f> points = Cluster(0.5, 0.0, 0.02, 10);  // the floor's returns
  const std::vector<Eigen::Vector3f> table_top = Cluster(0.5, 0.0, 0.40, 10);  // under a table top
  points.insert(points.end(), table_top.begin(), table_top.end());
  const std::vector<Eigen::Vector3f> far = Cluster(field.ReachM() + 0.1, 0.0, 0.2, 10);
  points.insert(points.end(), far.begin(), far.end());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  points.emplace_back(nan, 0.0f, 0.2f);
  points.emplace_back(0.5f, 0.0f, nan);
  field.SetScan(points, 0.0, Eigen::Vector2d::Zero());
  EXPECT_EQ(field.num_kept(), 0);
  EXPECT_FALSE(field.Check(StraightPath(1.0), 0.0).entered);
  field.SetScan(Cluster(0.5, 0.0, 0.34, 10), 0.0, Eigen::Vector2d::Zero());
  EXPECT_EQ(field.num_kept(), 10);
}

TEST(ProtectiveFieldTest, AStaleOrFutureScanChecksNothing) {
  ProtectiveField field(ProtectiveFieldOptions{}, Base(), Limits());
  EXPECT_FALSE(field.Check(StraightPath(1.0), 0.0).scan_fresh);  // none yet
  field.SetScan(Cluster(0.5, 0.0, 0.2, 10), 10.0, Eigen::Vector2d::Zero());
  EXPECT_TRUE(field.Check(StraightPath(1.0), 10.35).entered);
  const ProtectiveFieldCheck stale = field.Check(StraightPath(1.0), 10.36);
  EXPECT_FALSE(stale.scan_fresh);
  EXPECT_FALSE(stale.entered);
  EXPECT_EQ(stale.num_inside, 0);
  EXPECT_FALSE(field.Check(StraightPath(1.0), 9.6).scan_fresh);  // 0.4 s in the future
  field.ClearScan();
  EXPECT_FALSE(field.Check(StraightPath(1.0), 10.0).scan_fresh);
  EXPECT_EQ(field.num_kept(), 0);
}

TEST(ProtectiveFieldTest, BadOptionsAreRejectedByName) {
  const auto message = [](auto edit) {
    ProtectiveFieldOptions o;
    edit(&o);
    try {
      ProtectiveField field(o, Base(), Limits());
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->reaction_s = -0.1; }).find("reaction_s"), std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->lookahead_m = NAN; }).find("lookahead_m"), std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->radial_margin_m = 0.6; }).find("radial_margin_m"),
            std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->radial_margin_m = -0.4; }).find("leaves no field"),
            std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->z_max_m = 0.0; }).find("z_max_m"), std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->min_points = 0; }).find("min_points"), std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->max_scan_age_s = 0.0; }).find("max_scan_age_s"),
            std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->step_m = -1.0; }).find("step_m"), std::string::npos);
  EXPECT_NE(message([](ProtectiveFieldOptions* o) { o->self_margin_m = -1.0; }).find("self_margin_m"),
            std::string::npos);
  EXPECT_EQ(message([](ProtectiveFieldOptions*) {}), "accepted");
}

// A reference along +x at speed_mps from x = 0 at its start (3 s long), on the tracker's clock.
TrackerReference Line(double start_s, double speed_mps) {
  TrackerReference reference;
  reference.trajectory_id = 1;
  reference.start_time_s = start_s;
  reference.duration_s = 3.0;
  reference.sampler = [speed_mps](double t_s, TrajectorySample* sample) {
    sample->state.x_m = speed_mps * t_s;
    sample->state.y_m = 0.0;
  };
  return reference;
}

TEST(BasePathAheadTest, CoversTheLengthInStepsFromNow) {
  std::vector<Eigen::Vector2d> path;
  TrajectorySample sample;
  BasePathAhead(Line(10.0, 1.0), 11.0, 0.5, 0.02, 5.0, &path, &sample);
  ASSERT_GE(path.size(), 2u);
  EXPECT_NEAR(path.front().x(), 1.0, 1e-12);  // 1 s along
  EXPECT_NEAR(path.back().x(), 1.5, 0.021);
  for (std::size_t k = 1; k < path.size(); ++k) EXPECT_LE((path[k] - path[k - 1]).norm(), 0.02 + 1e-12);
}

TEST(BasePathAheadTest, EndsAtTheTrajectorysEndAndAtTheHorizon) {
  std::vector<Eigen::Vector2d> path;
  TrajectorySample sample;
  BasePathAhead(Line(0.0, 1.0), 2.9, 1.0, 0.02, 5.0, &path, &sample);
  EXPECT_NEAR(path.back().x(), 3.0, 1e-12);  // the end, 0.1 m on: the robot stops there
  BasePathAhead(Line(0.0, 0.0), 0.0, 1.0, 0.02, 0.5, &path, &sample);  // no progress: the horizon
  EXPECT_GE(path.size(), 26u);  // 0, 0.02, ..., 0.5 s (and 0.5 s again if 25 steps fall short)
  EXPECT_LE(path.size(), 27u);
  BasePathAhead(Line(5.0, 1.0), 4.0, 0.1, 0.02, 5.0, &path, &sample);  // not started: from its start
  EXPECT_NEAR(path.front().x(), 0.0, 1e-12);
  BasePathAhead(TrackerReference{}, 0.0, 1.0, 0.02, 5.0, &path, &sample);  // no sampler
  EXPECT_TRUE(path.empty());
}

}  // namespace
}  // namespace topay
