#include "core/robot/robot_body_filter.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

RobotBodyFilter::RobotBodyFilter(double margin_m) : margin_m_(margin_m) {
  if (!std::isfinite(margin_m) || margin_m < 0.0) {
    throw std::invalid_argument("RobotBodyFilter: margin_m must be finite and >= 0, got " +
                                std::to_string(margin_m));
  }
}

void RobotBodyFilter::Update(const RobotModel& model, const KinematicsCache& cache) {
  const double margin = margin_m_;
  const Eigen::Vector3d p_WB = cache.X_WB.translation();
  const double cylinder_radius = model.base_cylinder.radius_m + margin;
  p_WA_xy_ = p_WB.head<2>().cast<float>();
  cylinder_radius_squared_ = static_cast<float>(cylinder_radius * cylinder_radius);
  cylinder_z_min_ = static_cast<float>(-margin);
  cylinder_z_max_ = static_cast<float>(model.base_cylinder.height_m + margin);
  bounds_W_ = Eigen::AlignedBox3f(
      Eigen::Vector3f(p_WA_xy_.x() - cylinder_radius, p_WA_xy_.y() - cylinder_radius,
                      cylinder_z_min_),
      Eigen::Vector3f(p_WA_xy_.x() + cylinder_radius, p_WA_xy_.y() + cylinder_radius,
                      cylinder_z_max_));
  spheres_.resize(model.spheres.size());
  for (std::size_t s = 0; s < spheres_.size(); ++s) {
    const double radius = model.spheres[s].radius_m + margin;
    const Eigen::Vector3f p_WC = cache.p_WS[s].cast<float>();
    spheres_[s] = {p_WC, static_cast<float>(radius * radius)};
    const Eigen::Vector3f extent = Eigen::Vector3f::Constant(static_cast<float>(radius));
    bounds_W_.extend(p_WC - extent);
    bounds_W_.extend(p_WC + extent);
  }
}

bool RobotBodyFilter::Contains(const Eigen::Vector3f& p_W) const {
  if (!bounds_W_.contains(p_W)) return false;
  if (p_W.z() >= cylinder_z_min_ && p_W.z() <= cylinder_z_max_ &&
      (p_W.head<2>() - p_WA_xy_).squaredNorm() <= cylinder_radius_squared_) {
    return true;
  }
  for (const Sphere& sphere : spheres_) {
    if ((p_W - sphere.p_WC).squaredNorm() <= sphere.radius_squared) return true;
  }
  return false;
}

int RobotBodyFilter::RemoveFrom(std::vector<Eigen::Vector3f>* p_WP) const {
  std::size_t kept = 0;
  for (const Eigen::Vector3f& p_W : *p_WP) {
    if (!Contains(p_W)) (*p_WP)[kept++] = p_W;
  }
  const int removed = static_cast<int>(p_WP->size() - kept);
  p_WP->resize(kept);
  return removed;
}

}  // namespace topay
