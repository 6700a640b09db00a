// Unicycle <-> wheel speed conversion of the differential-drive base, and ticks -> radians.
#include "drivers/base/diff_drive_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace topay::base {
namespace {

TEST(DiffDriveKinematicsTest, DefaultsAreValid) {
  const DriveGeometry geometry;
  EXPECT_EQ(CheckDriveGeometry(geometry), "");
  EXPECT_DOUBLE_EQ(geometry.wheel_radius_m, 0.10);
  EXPECT_DOUBLE_EQ(geometry.track_width_m, 0.50);
  EXPECT_EQ(geometry.ticks_per_rev, 16384);
}

TEST(DiffDriveKinematicsTest, RejectsBadGeometry) {
  DriveGeometry geometry;
  geometry.wheel_radius_m = 0.0;
  EXPECT_EQ(CheckDriveGeometry(geometry), "wheel_radius_m must be finite and > 0");
  geometry = DriveGeometry{};
  geometry.track_width_m = NAN;
  EXPECT_EQ(CheckDriveGeometry(geometry), "track_width_m must be finite and > 0");
  geometry = DriveGeometry{};
  geometry.ticks_per_rev = 0;
  EXPECT_EQ(CheckDriveGeometry(geometry), "ticks_per_rev must be > 0");
}

TEST(DiffDriveKinematicsTest, StraightAndTurningInPlace) {
  const DriveGeometry geometry;  // r = 0.1 m, track 0.5 m
  const WheelSpeeds straight = UnicycleToWheelSpeeds({1.0, 0.0}, geometry);
  EXPECT_DOUBLE_EQ(straight.left_rad_per_s, 10.0);
  EXPECT_DOUBLE_EQ(straight.right_rad_per_s, 10.0);
  const WheelSpeeds spin = UnicycleToWheelSpeeds({0.0, 0.9}, geometry);  // omega_max
  EXPECT_DOUBLE_EQ(spin.left_rad_per_s, -2.25);
  EXPECT_DOUBLE_EQ(spin.right_rad_per_s, 2.25);  // left turn: right wheel forward
}

TEST(DiffDriveKinematicsTest, RoundTripBothWays) {
  DriveGeometry geometry;
  geometry.wheel_radius_m = 0.0825;
  geometry.track_width_m = 0.43;
  for (double v = -1.0; v <= 1.0; v += 0.25) {
    for (double omega = -0.9; omega <= 0.9; omega += 0.3) {
      const UnicycleVelocity back =
          WheelSpeedsToUnicycle(UnicycleToWheelSpeeds({v, omega}, geometry), geometry);
      EXPECT_NEAR(back.v_m_per_s, v, 1e-12);
      EXPECT_NEAR(back.omega_rad_per_s, omega, 1e-12);
    }
  }
  const WheelSpeeds speeds{3.0, -1.5};
  const WheelSpeeds again =
      UnicycleToWheelSpeeds(WheelSpeedsToUnicycle(speeds, geometry), geometry);
  EXPECT_NEAR(again.left_rad_per_s, 3.0, 1e-12);
  EXPECT_NEAR(again.right_rad_per_s, -1.5, 1e-12);
}

TEST(DiffDriveKinematicsTest, RobotLimitsFitTheWheelSpeedFrame) {
  // v_max 1.0 m/s with omega_max 0.9 rad/s (topay_mm.yaml) on the default geometry stays well
  // inside the wheel speed frame's +-30 rad/s.
  const WheelSpeeds fastest = UnicycleToWheelSpeeds({1.0, 0.9}, DriveGeometry{});
  EXPECT_LT(std::abs(fastest.right_rad_per_s), 30.0);
  EXPECT_DOUBLE_EQ(fastest.right_rad_per_s, 12.25);
}

TEST(DiffDriveKinematicsTest, TicksToRadians) {
  const DriveGeometry geometry;
  EXPECT_DOUBLE_EQ(WheelTicksToRadians(16384, geometry), 2.0 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(WheelTicksToRadians(-4096, geometry), -0.5 * std::numbers::pi);
}

}  // namespace
}  // namespace topay::base
