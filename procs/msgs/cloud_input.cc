#include "procs/msgs/cloud_input.h"

#include <cmath>
#include <sstream>

namespace topay::msgs {
namespace {

std::string Number(double value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

std::optional<CloudError> CheckSizes(const point_cloud_t& m, const CloudInputOptions& options) {
  if (m.num_coords < 0) return CloudError{"num_coords", Number(m.num_coords) + ": negative"};
  if (m.num_coords % 3 != 0) {
    return CloudError{"num_coords", Number(m.num_coords) + ": not a multiple of 3 (x, y, z)"};
  }
  if (static_cast<std::size_t>(m.num_coords) != m.p_SP.size()) {
    return CloudError{"num_coords", Number(m.num_coords) + ": the p_SP array holds " +
                                        Number(static_cast<double>(m.p_SP.size())) + " floats"};
  }
  if (m.num_coords / 3 > options.max_points) {
    return CloudError{"p_SP", Number(m.num_coords / 3) + " points: more than max_points (" +
                                  Number(options.max_points) + ")"};
  }
  return std::nullopt;
}

// The pose, or the error naming the first bad entry.
std::optional<CloudError> ReadPose(const point_cloud_t& m, const CloudInputOptions& options,
                                   Eigen::Isometry3d* X_WS) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(m.p_WS[i])) {
      return CloudError{"p_WS[" + std::to_string(i) + "]", Number(m.p_WS[i]) + ": not finite"};
    }
  }
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(m.quat_WS[i])) {
      return CloudError{"quat_WS[" + std::to_string(i) + "]",
                        Number(m.quat_WS[i]) + ": not finite"};
    }
  }
  Eigen::Quaterniond q_WS(m.quat_WS[0], m.quat_WS[1], m.quat_WS[2], m.quat_WS[3]);
  const double norm = q_WS.norm();
  if (!(std::abs(norm - 1.0) <= options.quaternion_norm_tolerance)) {
    return CloudError{"quat_WS", "norm " + Number(norm) + ": not a unit quaternion (tolerance " +
                                     Number(options.quaternion_norm_tolerance) + ")"};
  }
  q_WS.normalize();
  X_WS->setIdentity();
  X_WS->linear() = q_WS.toRotationMatrix();
  X_WS->translation() = Eigen::Vector3d(m.p_WS[0], m.p_WS[1], m.p_WS[2]);
  return std::nullopt;
}

}  // namespace

std::string CloudError::ToString() const { return "point_cloud_t." + field + ": " + message; }

std::optional<CloudError> CheckCloud(const point_cloud_t& message,
                                     const CloudInputOptions& options, CheckedCloud* cloud) {
  if (auto error = CheckSizes(message, options)) return error;
  if (auto error = ReadPose(message, options, &cloud->X_WS)) return error;
  cloud->utime = message.utime;
  const std::size_t n = message.p_SP.size() / 3;
  cloud->p_SP.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    cloud->p_SP[i] = {message.p_SP[3 * i], message.p_SP[3 * i + 1], message.p_SP[3 * i + 2]};
  }
  return std::nullopt;
}

}  // namespace topay::msgs
