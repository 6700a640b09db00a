#include "procs/viz/scan_view.h"

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "procs/viz/base64.h"

namespace topay::viz {

std::optional<nlohmann::json> ScanPayload(const point_cloud_t& msg, const ScanViewOptions& options,
                                          std::string* error) {
  if (msg.num_coords < 0 || msg.num_coords % 3 != 0 || msg.p_SP.size() != static_cast<std::size_t>(msg.num_coords)) {
    *error = "point_cloud_t.num_coords: not 3 x the points";
    return std::nullopt;
  }
  const Eigen::Vector3d p_WS(msg.p_WS[0], msg.p_WS[1], msg.p_WS[2]);
  const Eigen::Quaterniond q_WS(msg.quat_WS[0], msg.quat_WS[1], msg.quat_WS[2], msg.quat_WS[3]);
  if (!p_WS.allFinite() || !q_WS.coeffs().allFinite() || q_WS.norm() < 0.5) {
    *error = "point_cloud_t.p_WS / quat_WS: not a finite pose";
    return std::nullopt;
  }
  const Eigen::Matrix3d R_WS = q_WS.normalized().toRotationMatrix();
  const int num_points = msg.num_coords / 3;
  const int stride = std::max(1, (num_points + options.max_points - 1) / std::max(1, options.max_points));
  std::vector<std::int16_t> cm;
  cm.reserve(3 * (num_points / stride + 1));
  for (int i = 0; i < num_points; i += stride) {
    const Eigen::Vector3d p_SP(msg.p_SP[3 * i], msg.p_SP[3 * i + 1], msg.p_SP[3 * i + 2]);
    const Eigen::Vector3d d_cm = 100.0 * (R_WS * p_SP);
    if (!d_cm.allFinite() || d_cm.cwiseAbs().maxCoeff() > 32767.0) continue;
    for (int k = 0; k < 3; ++k) cm.push_back(static_cast<std::int16_t>(std::lround(d_cm[k])));
  }
  return nlohmann::json{{"t", msg.utime * 1e-6},
                        {"p_WS_m", {p_WS.x(), p_WS.y(), p_WS.z()}},
                        {"count", cm.size() / 3},
                        {"points_total", num_points},
                        {"points_cm", Base64OfInt16(cm)}};
}

}  // namespace topay::viz
