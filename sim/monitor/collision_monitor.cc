#include "sim/monitor/collision_monitor.h"

#include <cmath>
#include <stdexcept>

#include "core/geometry/primitive_box_distance.h"
#include "core/geometry/vertical_cylinder.h"

namespace topay::sim {
namespace {

// Body ids: 0 the base, 1..S the spheres, then the P self pairs, then the S chassis checks.
std::vector<std::string> BodyNames(const RobotModel& model) {
  const auto sphere = [&](int s) {
    return "sphere " + std::to_string(s) + " (link " + model.links[model.spheres[s].link].name +
           ")";
  };
  std::vector<std::string> names{"base"};
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int s = 0; s < num_spheres; ++s) names.push_back(sphere(s));
  for (const auto& [i, j] : model.self_collision_pairs) {
    names.push_back("self: sphere " + std::to_string(i) + " - sphere " + std::to_string(j));
  }
  for (int s = 0; s < num_spheres; ++s) names.push_back("chassis: " + sphere(s));
  return names;
}

const CollisionMonitorOptions& Checked(const CollisionMonitorOptions& options) {
  if (!std::isfinite(options.contact_tolerance_m) || options.contact_tolerance_m < 0.0) {
    throw std::invalid_argument("CollisionMonitorOptions::contact_tolerance_m must be finite "
                                "and >= 0");
  }
  return options;
}

}  // namespace

CollisionMonitor::CollisionMonitor(const Kinematics& kinematics,
                                   const CollisionMonitorOptions& options)
    : kinematics_(kinematics),
      options_(Checked(options)),
      self_collision_(kinematics),
      num_spheres_(static_cast<int>(kinematics.model().spheres.size())),
      num_pairs_(self_collision_.num_pairs()),
      grid_(box_bounds_W_),
      cache_(kinematics.MakeCache()),
      pair_distances_m_(num_pairs_),
      chassis_margins_m_(num_spheres_),
      events_(BodyNames(kinematics.model()), options.max_recorded_events) {
  raw_.reserve(64);
}

void CollisionMonitor::SetWorld(const std::vector<OrientedBox>& boxes) {
  boxes_ = boxes;
  box_bounds_W_.clear();
  for (const OrientedBox& box : boxes_) box_bounds_W_.push_back(box.WorldBounds());
  grid_ = BoxBucketGrid(box_bounds_W_);
}

void CollisionMonitor::Add(int body, int box, double depth_m) {
  if (!(depth_m > options_.contact_tolerance_m)) return;
  // One pair id per (body, box): box + 1 in the low 32 bits (-1 for no box).
  const std::int64_t pair = (std::int64_t{body} << 32) | std::int64_t{box + 1};
  raw_.push_back({pair, body, box, depth_m});
}

void CollisionMonitor::CheckBase() {
  const BaseCylinder& base = kinematics_.model().base_cylinder;
  const Eigen::Vector2d axis = cache_.X_WB.translation().head<2>();
  const VerticalCylinder cylinder{axis, base.radius_m, 0.0, base.height_m};
  const Eigen::AlignedBox3d bounds(
      Eigen::Vector3d(axis.x() - base.radius_m, axis.y() - base.radius_m, 0.0),
      Eigen::Vector3d(axis.x() + base.radius_m, axis.y() + base.radius_m, base.height_m));
  // Solids can only overlap where their AABBs meet: bound 0 stops after the touching buckets.
  grid_.VisitNear(bounds.min().head<2>(), bounds.max().head<2>(), [] { return 0.0; },
                  [&](int i) {
                    if (!box_bounds_W_[i].intersects(bounds)) return;
                    Add(0, i, -SignedDistanceCylinderToBox(boxes_[i], cylinder));
                  });
}

void CollisionMonitor::CheckSpheres() {
  const std::vector<CollisionSphere>& spheres = kinematics_.model().spheres;
  for (int s = 0; s < num_spheres_; ++s) {
    const Eigen::Vector3d& p_WS = cache_.p_WS[s];
    const double r = spheres[s].radius_m;
    const Eigen::AlignedBox3d bounds(p_WS.array() - r, p_WS.array() + r);
    grid_.VisitNear(bounds.min().head<2>(), bounds.max().head<2>(), [] { return 0.0; },
                    [&](int i) {
                      if (!box_bounds_W_[i].intersects(bounds)) return;
                      Add(1 + s, i, -SignedDistanceSphereToBox(boxes_[i], p_WS, r));
                    });
  }
}

void CollisionMonitor::CheckSelf() {
  if (options_.check_self) {
    // d_k = |p_i - p_j| - r_i - r_j (core/robot/self_collision.h); depth = -d_k.
    self_collision_.Distances(cache_, pair_distances_m_);
    for (int k = 0; k < num_pairs_; ++k) Add(1 + num_spheres_ + k, -1, -pair_distances_m_(k));
  }
  if (options_.check_chassis) {
    // m_s = z_s - r_s - chassis top; depth = -m_s.
    self_collision_.ChassisMargins(cache_, chassis_margins_m_);
    for (int s = 0; s < num_spheres_; ++s) {
      Add(1 + num_spheres_ + num_pairs_ + s, -1, -chassis_margins_m_(s));
    }
  }
}

const std::vector<Contact>& CollisionMonitor::Check(const WholeBodyState& state, double t_s) {
  kinematics_.Update(state, &cache_);
  raw_.clear();
  CheckBase();
  CheckSpheres();
  CheckSelf();
  return events_.Step(t_s, &raw_);
}

}  // namespace topay::sim
