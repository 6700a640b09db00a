#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/box_bucket_grid.h"
#include "core/geometry/oriented_box.h"
#include "core/robot/kinematics.h"
#include "core/robot/self_collision.h"
#include "core/robot/whole_body_state.h"
#include "sim/monitor/contact_events.h"

namespace topay::sim {

struct CollisionMonitorOptions {
  /// A pair is in contact when its penetration depth exceeds this (m, >= 0): 0 reports every
  /// overlap, however shallow (touching, depth 0, is no contact).
  double contact_tolerance_m = 0.0;
  /// Check the self-collision sphere pairs (RobotModel::self_collision_pairs).
  bool check_self = true;
  /// Check every arm sphere against the chassis top, as SceneClearance::chassis_m does (the
  /// sphere's lowest point below the base cylinder's height, wherever the sphere is).
  bool check_chassis = true;
  /// Events kept with their details for Report() and events(); counting goes on beyond.
  std::int64_t max_recorded_events = 100000;
};

/// The ground-truth collision monitor, the judge of a closed-loop run: at every plant step it
/// checks the robot's whole collision model, as core/collision/scene_clearance.h defines it,
/// against the world's exact boxes and reports EVERY contact, not only the worst:
///  - "base": the base cylinder (RobotModel::base_cylinder about the base axis, from the
///    ground to the chassis top) vs each box, depth = -SignedDistanceCylinderToBox;
///  - "sphere s (link L)": each arm collision sphere vs each box,
///    depth = -SignedDistanceSphereToBox;
///  - "self: sphere i - sphere j": each self-collision pair, depth = r_i + r_j - |p_i - p_j|;
///  - "chassis: sphere s (link L)": each sphere dipping below the chassis top,
///    depth = chassis height - (z_s - r_s).
/// Boxes are found through a BoxBucketGrid (core/geometry): only boxes whose AABB meets the
/// primitive's AABB can overlap it, so a check costs the boxes near the robot. A (body, box)
/// pair in contact over consecutive checks is one event (ContactEvents). Box indices refer to
/// the vector last given to SetWorld; an event whose pair is still in contact after a
/// SetWorld continues.
///
/// The Kinematics must outlive the monitor. Check allocates only when it reports contacts
/// (their names).
class CollisionMonitor {
 public:
  using Counts = ContactEvents::Counts;

  /// Throws std::invalid_argument for a negative or non-finite tolerance.
  explicit CollisionMonitor(const Kinematics& kinematics,
                            const CollisionMonitorOptions& options = {});

  /// Replaces the world's boxes (boxes may appear or disappear at run time).
  void SetWorld(const std::vector<OrientedBox>& boxes);

  /// Checks one state at plant time t_s; returns the contacts that started at this step (new
  /// events) and updates the counts. Throws std::invalid_argument for a state of the wrong
  /// size or with a NaN (from Kinematics::Update).
  const std::vector<Contact>& Check(const WholeBodyState& state, double t_s);

  /// Every contact at the last step.
  const std::vector<Contact>& active() const { return events_.active(); }
  const Counts& counts() const { return events_.counts(); }
  const std::vector<ContactEvent>& events() const { return events_.events(); }
  /// The counts and the deepest events, for the process to print on exit.
  std::string Report() const { return events_.Report(); }

  int num_boxes() const { return static_cast<int>(boxes_.size()); }

 private:
  void CheckBase();
  void CheckSpheres();
  void CheckSelf();
  void Add(int body, int box, double depth_m);

  const Kinematics& kinematics_;
  CollisionMonitorOptions options_;
  SelfCollision self_collision_;
  int num_spheres_ = 0;
  int num_pairs_ = 0;
  std::vector<OrientedBox> boxes_;
  std::vector<Eigen::AlignedBox3d> box_bounds_W_;
  BoxBucketGrid grid_;
  KinematicsCache cache_;
  Eigen::VectorXd pair_distances_m_;
  Eigen::VectorXd chassis_margins_m_;
  std::vector<RawContact> raw_;
  ContactEvents events_;
};

}  // namespace topay::sim
