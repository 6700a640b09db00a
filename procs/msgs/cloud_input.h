#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "topay/point_cloud_t.hpp"

namespace topay::msgs {

/// Limits on an incoming POINT_CLOUD message (topay::point_cloud_t).
struct CloudInputOptions {
  /// Clouds with more points are rejected whole: 200,000 is ten Mid-360 scans (20,000 points
  /// each); more is a sender bug, and filtering it would blow the mapper's per-scan budget.
  int max_points = 200000;
  /// |quat_WS| may differ from 1 by this much and is then renormalised (doubles that went
  /// through floats or text keep |q| within ~1e-6 of 1); a larger deviation is a broken pose
  /// and the cloud is rejected. Must be in (0, 1).
  double quaternion_norm_tolerance = 1e-3;
};

/// A point_cloud_t that passed CheckCloud: the sensor pose X_WS is a proper rigid transform
/// and the points p_SP are the message's, as given (individual points may still be NaN or
/// infinite: the scan filter drops and counts them).
struct CheckedCloud {
  std::int64_t utime = 0;                                  ///< Capture time, us since epoch.
  Eigen::Isometry3d X_WS = Eigen::Isometry3d::Identity();  ///< Sensor pose at capture.
  std::vector<Eigen::Vector3f> p_SP;                       ///< Points in S, m.
};

/// Why a message was rejected: the field and what was wrong with its value.
struct CloudError {
  std::string field;    ///< e.g. "num_coords", "quat_WS", "p_WS[2]".
  std::string message;  ///< e.g. "-3: negative".
  /// "point_cloud_t.<field>: <message>".
  std::string ToString() const;
};

/// Checks `message` and, if it is sound, fills *cloud (its vector's capacity is reused across
/// calls: allocation-free once it has held the largest cloud). Rejected (returned error,
/// *cloud unspecified): num_coords negative, not a multiple of 3, or not the array's length;
/// more than options.max_points points; a non-finite p_WS or quat_WS entry; a quaternion whose
/// norm differs from 1 by more than options.quaternion_norm_tolerance.
std::optional<CloudError> CheckCloud(const point_cloud_t& message,
                                     const CloudInputOptions& options, CheckedCloud* cloud);

}  // namespace topay::msgs
