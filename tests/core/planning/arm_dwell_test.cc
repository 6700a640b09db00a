#include "core/planning/arm_dwell.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace topay {
namespace {

Eigen::VectorXd Joints(std::initializer_list<double> values) {
  Eigen::VectorXd q(static_cast<Eigen::Index>(values.size()));
  int i = 0;
  for (double v : values) q(i++) = v;
  return q;
}

TEST(ArmDwellTest, TheTimeNeededIsTheSlowestJointsTravelTimesTheFactorPlusTheMinimum) {
  ArmDwellOptions options;
  options.travel_time_factor = 1.5;
  options.min_time_s = 1.0;
  // Joint 2 is the slowest: 0.6 rad at 1.0 rad/s = 0.6 s (joint 1: 0.8 / 2 = 0.4 s).
  const double t = ArmTimeNeeded(Joints({0.0, 0.0}), Joints({0.8, -0.6}), Joints({2.0, 1.0}), options);
  EXPECT_NEAR(t, 1.5 * 0.6 + 1.0, 1e-12);
}

TEST(ArmDwellTest, ABaseThatStaysGetsStandingLayersUntilTheArmHasItsTime) {
  // One waypoint and the start's yaw: DiscreteSE2 gives one layer, no time at all.
  DiscreteSE2Path path = DiscreteSE2({Eigen::Vector2d(1.0, 2.0)}, 0.3, 0.3, BaseLimits{});
  ASSERT_EQ(path.num_layers(), 1);
  ArmDwellOptions options;  // 1.5 x travel + 1 s, layers at most 0.5 s apart
  const Eigen::VectorXd q0 = Joints({0.0, 0.0, 0.0}), q1 = Joints({0.5, -0.2, 0.1});
  const Eigen::VectorXd qd_max = Joints({2.35, 2.35, 2.35});
  const double needed = ArmTimeNeeded(q0, q1, qd_max, options);
  const double added = AddArmDwell(q0, q1, qd_max, options, &path);
  EXPECT_NEAR(added, needed, 1e-12);
  EXPECT_NEAR(path.total_time_s(), needed, 1e-12);
  EXPECT_EQ(path.num_layers(), 1 + static_cast<int>(std::ceil(needed / options.step_s)));
  for (int l = 1; l < path.num_layers(); ++l) {
    const Se2Layer& layer = path.layers[l];
    EXPECT_EQ(layer.x_m, 1.0);
    EXPECT_EQ(layer.y_m, 2.0);
    EXPECT_EQ(layer.yaw_rad, 0.3);
    EXPECT_TRUE(layer.turn_in_place);
    EXPECT_LE(layer.step_time_s, options.step_s + 1e-12);
    EXPECT_NEAR(layer.time_s - path.layers[l - 1].time_s, layer.step_time_s, 1e-12);
  }
  // The arm can now reach its goal at its speed limits: what the RRT*'s reach check asks.
  EXPECT_TRUE(((q1 - q0).cwiseAbs().array() <= qd_max.array() * path.total_time_s()).all());
}

TEST(ArmDwellTest, ASequenceLongEnoughIsLeftAlone) {
  DiscreteSE2Path path =
      DiscreteSE2({Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(4.0, 0.0)}, 0.0, 0.0, BaseLimits{});
  const int layers = path.num_layers();
  const double total = path.total_time_s();
  ASSERT_GT(total, 4.0);
  const Eigen::VectorXd q0 = Joints({0.0}), q1 = Joints({0.3});
  EXPECT_EQ(AddArmDwell(q0, q1, Joints({2.35}), ArmDwellOptions{}, &path), 0.0);
  EXPECT_EQ(path.num_layers(), layers);
  EXPECT_EQ(path.total_time_s(), total);
}

TEST(ArmDwellTest, ZeroFactorAndMinimumMeanNeverADwell) {
  DiscreteSE2Path path = DiscreteSE2({Eigen::Vector2d(0.0, 0.0)}, 0.0, 0.0, BaseLimits{});
  ArmDwellOptions options;
  options.travel_time_factor = 0.0;
  options.min_time_s = 0.0;
  EXPECT_EQ(AddArmDwell(Joints({0.0}), Joints({1.0}), Joints({2.35}), options, &path), 0.0);
  EXPECT_EQ(path.num_layers(), 1);
}

TEST(ArmDwellTest, OptionsOutOfRangeAreNamed) {
  const auto message = [](const ArmDwellOptions& o) {
    try {
      CheckArmDwellOptions(o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(ArmDwellOptions{}), "");
  ArmDwellOptions o;
  o.travel_time_factor = -1.0;
  EXPECT_NE(message(o).find("travel_time_factor"), std::string::npos);
  o = {};
  o.min_time_s = std::nan("");
  EXPECT_NE(message(o).find("min_time_s"), std::string::npos);
  o = {};
  o.step_s = 0.0;
  EXPECT_NE(message(o).find("step_s"), std::string::npos);
}

}  // namespace
}  // namespace topay
