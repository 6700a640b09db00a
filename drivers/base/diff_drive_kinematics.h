#pragma once
// Unicycle (v, omega) <-> wheel speeds of the differential-drive base, and encoder ticks ->
// wheel angle. config/robot/topay_mm.yaml has no wheel radius or track width (only
// base_limits), so the geometry is a DriveGeometry with documented defaults; the processes
// take them as options until the real base's values are in the robot YAML.

#include <cstdint>
#include <string>

namespace topay::base {

/// The base's drive geometry.
struct DriveGeometry {
  /// Wheel radius [m]. Default 0.10 m: a placeholder of the size of common AGV drive wheels
  /// (the TopAY base's value is not in config/robot/).
  double wheel_radius_m = 0.10;
  /// Distance between the two wheels' contact points [m]. Default 0.50 m: a placeholder that
  /// fits inside the 0.40 m-radius base cylinder of topay_mm.yaml.
  double track_width_m = 0.50;
  /// Encoder ticks per wheel revolution (odometry frame). Default 16384 (a 4096-line encoder
  /// counted on both edges of both channels, at the wheel).
  int ticks_per_rev = 16384;
};

/// Empty when every field is finite and positive, else what is wrong.
std::string CheckDriveGeometry(const DriveGeometry& geometry);

struct WheelSpeeds {
  double left_rad_per_s = 0.0;   ///< Positive drives forward.
  double right_rad_per_s = 0.0;
};

struct UnicycleVelocity {
  double v_m_per_s = 0.0;
  double omega_rad_per_s = 0.0;  ///< Counter-clockwise positive (left turn).
};

/// left = (v - omega * track / 2) / r, right = (v + omega * track / 2) / r. `geometry` must
/// pass CheckDriveGeometry.
WheelSpeeds UnicycleToWheelSpeeds(const UnicycleVelocity& velocity, const DriveGeometry& geometry);

/// The inverse: v = r (left + right) / 2, omega = r (right - left) / track.
UnicycleVelocity WheelSpeedsToUnicycle(const WheelSpeeds& speeds, const DriveGeometry& geometry);

/// The wheel angle [rad] of `ticks` encoder ticks (2 pi ticks / ticks_per_rev).
double WheelTicksToRadians(std::int32_t ticks, const DriveGeometry& geometry);

}  // namespace topay::base
