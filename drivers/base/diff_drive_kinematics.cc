#include "drivers/base/diff_drive_kinematics.h"

#include <cmath>
#include <numbers>

namespace topay::base {
namespace {

bool IsPositiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

}  // namespace

std::string CheckDriveGeometry(const DriveGeometry& geometry) {
  if (!IsPositiveFinite(geometry.wheel_radius_m)) return "wheel_radius_m must be finite and > 0";
  if (!IsPositiveFinite(geometry.track_width_m)) return "track_width_m must be finite and > 0";
  if (geometry.ticks_per_rev <= 0) return "ticks_per_rev must be > 0";
  return "";
}

WheelSpeeds UnicycleToWheelSpeeds(const UnicycleVelocity& velocity,
                                  const DriveGeometry& geometry) {
  const double half_track_m = 0.5 * geometry.track_width_m;
  WheelSpeeds speeds;
  speeds.left_rad_per_s =
      (velocity.v_m_per_s - velocity.omega_rad_per_s * half_track_m) / geometry.wheel_radius_m;
  speeds.right_rad_per_s =
      (velocity.v_m_per_s + velocity.omega_rad_per_s * half_track_m) / geometry.wheel_radius_m;
  return speeds;
}

UnicycleVelocity WheelSpeedsToUnicycle(const WheelSpeeds& speeds, const DriveGeometry& geometry) {
  UnicycleVelocity velocity;
  velocity.v_m_per_s =
      0.5 * geometry.wheel_radius_m * (speeds.left_rad_per_s + speeds.right_rad_per_s);
  velocity.omega_rad_per_s = geometry.wheel_radius_m *
                             (speeds.right_rad_per_s - speeds.left_rad_per_s) /
                             geometry.track_width_m;
  return velocity;
}

double WheelTicksToRadians(std::int32_t ticks, const DriveGeometry& geometry) {
  return 2.0 * std::numbers::pi * static_cast<double>(ticks) / geometry.ticks_per_rev;
}

}  // namespace topay::base
