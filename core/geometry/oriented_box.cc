#include "core/geometry/oriented_box.h"

#include <cmath>

namespace topay {
namespace {

// Signed distance from a point in the frame of a centred, axis-aligned box of half sizes h,
// with its gradient in that frame. Outside: norm of the clamped excess. Inside: the largest
// (least negative) of the per-axis excesses, i.e. minus the depth to the nearest face.
template <int Dim>
double SignedDistanceCentred(const Eigen::Matrix<double, Dim, 1>& p,
                             const Eigen::Matrix<double, Dim, 1>& h,
                             Eigen::Matrix<double, Dim, 1>* gradient) {
  const Eigen::Matrix<double, Dim, 1> excess = p.cwiseAbs() - h;
  const Eigen::Matrix<double, Dim, 1> outside = excess.cwiseMax(0.0);
  const double outside_norm = outside.norm();
  if (outside_norm > 0.0) {
    if (gradient) {
      for (int i = 0; i < Dim; ++i) {
        (*gradient)(i) = std::copysign(outside(i), p(i)) / outside_norm;
      }
    }
    return outside_norm;
  }
  int axis = 0;
  const double depth = excess.maxCoeff(&axis);
  if (gradient) {
    gradient->setZero();
    (*gradient)(axis) = p(axis) >= 0.0 ? 1.0 : -1.0;
  }
  return depth;
}

}  // namespace

Eigen::Vector3d OrientedBox::ToBoxFrame(const Eigen::Vector3d& p_W) const {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  const Eigen::Vector3d d = p_W - center_W_m;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
}

Eigen::AlignedBox3d OrientedBox::WorldBounds() const {
  const double c = std::abs(std::cos(yaw_rad));
  const double s = std::abs(std::sin(yaw_rad));
  const Eigen::Vector3d h = HalfSize();
  const Eigen::Vector3d extent(c * h.x() + s * h.y(), s * h.x() + c * h.y(), h.z());
  return Eigen::AlignedBox3d(center_W_m - extent, center_W_m + extent);
}

double SignedDistanceToBox(const OrientedBox& box, const Eigen::Vector3d& p_W,
                           Eigen::Vector3d* gradient_W) {
  const Eigen::Vector3d p_B = box.ToBoxFrame(p_W);
  Eigen::Vector3d gradient_B;
  const double distance =
      SignedDistanceCentred<3>(p_B, box.HalfSize(), gradient_W ? &gradient_B : nullptr);
  if (gradient_W) {
    const double c = std::cos(box.yaw_rad);
    const double s = std::sin(box.yaw_rad);
    *gradient_W = {c * gradient_B.x() - s * gradient_B.y(),
                   s * gradient_B.x() + c * gradient_B.y(), gradient_B.z()};
  }
  return distance;
}

double SignedDistanceToFootprint(const OrientedBox& box, const Eigen::Vector2d& p_W) {
  const Eigen::Vector3d p_B = box.ToBoxFrame({p_W.x(), p_W.y(), box.center_W_m.z()});
  return SignedDistanceCentred<2>(p_B.head<2>(), box.HalfSize().head<2>(), nullptr);
}

}  // namespace topay
