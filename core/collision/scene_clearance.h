#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/box_bucket_grid.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "core/robot/self_collision.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Exact clearances (m) of one whole-body state, part by part. A part with nothing to check
/// (or, with a finite SceneClearanceOptions::cutoff_m, nothing within the cutoff) reports
/// +infinity and index -1. Obstacle distances are signed: negative = minus the penetration
/// depth (see core/geometry/primitive_box_distance.h).
struct SceneClearance {
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  double base_m = kInfinity;     ///< Base cylinder vs every box.
  int base_box = -1;             ///< Index in Scene::boxes of the nearest box to the base.
  double spheres_m = kInfinity;  ///< Every arm sphere vs every box.
  int sphere = -1;               ///< The sphere (RobotModel::spheres index) attaining it...
  int sphere_box = -1;           ///< ...and its nearest box.
  double self_m = kInfinity;     ///< Self-collision pairs: |p_i - p_j| - r_i - r_j.
  int self_pair = -1;            ///< Index in RobotModel::self_collision_pairs.
  double chassis_m = kInfinity;  ///< Arm above the chassis: min_s z_s - r_s - chassis top.
  int chassis_sphere = -1;
  double min_m = kInfinity;      ///< Minimum of the four parts.

  double obstacle_m() const { return base_m < spheres_m ? base_m : spheres_m; }

  /// True if the obstacle clearances (base, spheres) exceed obstacle_margin_m and the self
  /// clearances (pairs, chassis) exceed self_margin_m. Two margins because the chassis margin
  /// of the lowest sphere is a fixed property of the robot (5 mm for the TopAY arm), so an
  /// obstacle safety margin cannot apply to it.
  bool IsCollisionFree(double obstacle_margin_m = 0.0, double self_margin_m = 0.0) const {
    return base_m > obstacle_margin_m && spheres_m > obstacle_margin_m &&
           self_m > self_margin_m && chassis_m > self_margin_m;
  }
};

struct SceneClearanceOptions {
  /// Obstacle distances beyond cutoff_m are not resolved: boxes whose world AABB is farther
  /// than cutoff_m from a primitive are not examined, and a part with no box nearer than the
  /// cutoff reports +infinity. Default +infinity: every part's minimum is exact (boxes are
  /// still skipped when their AABB is farther than the best distance found so far, which
  /// cannot change the minimum).
  double cutoff_m = std::numeric_limits<double>::infinity();
};

/// Buffers for allocation-free queries; make one per thread with MakeWorkspace().
struct SceneClearanceWorkspace {
  KinematicsCache cache;
  Eigen::VectorXd pair_distances_m;
  Eigen::VectorXd chassis_margins_m;
};

/// Exact whole-body clearance of states in a Scene: the independent ground truth (no distance
/// fields) for task generation and trajectory validation. Each box's world AABB is computed
/// once and listed in a uniform xy bucket grid (BoxBucketGrid, built in the constructor in
/// time linear in the boxes); a query visits the buckets around the primitive (sphere or base
/// cylinder, by its own AABB) ring by ring and stops once every unvisited box's AABB is
/// farther than the best distance found so far (or the cutoff), and a box is examined exactly
/// only if its AABB is not farther than that. So a query's cost grows with the boxes near the
/// robot, not with the scene's box count, and the result is the exact minimum (ties: the
/// lowest box index).
/// The Kinematics (and its model) and the Scene must outlive this object; the scene's boxes
/// must not change (AABBs are cached).
class SceneClearanceChecker {
 public:
  SceneClearanceChecker(const Kinematics& kinematics, const Scene& scene,
                        const SceneClearanceOptions& options = {});

  SceneClearanceWorkspace MakeWorkspace() const;
  const Scene& scene() const { return scene_; }
  const Kinematics& kinematics() const { return kinematics_; }

  /// Clearance of `state`; allocation-free given a workspace. Throws std::invalid_argument
  /// for a state of the wrong size or with a NaN (from Kinematics::Update).
  SceneClearance Compute(const WholeBodyState& state, SceneClearanceWorkspace* workspace) const;
  /// Convenience: allocates a workspace.
  SceneClearance Compute(const WholeBodyState& state) const;

  /// Same as Compute(...).IsCollisionFree(obstacle_margin_m, self_margin_m), faster: only
  /// boxes within the obstacle margin are examined.
  bool IsCollisionFree(const WholeBodyState& state, double obstacle_margin_m,
                       double self_margin_m, SceneClearanceWorkspace* workspace) const;

  /// Exact clearance of the base cylinder alone with its axis at p_WB (it does not depend on
  /// yaw or q), and the nearest box in *box (-1 if none within the cutoff, then +infinity).
  double BaseClearance(const Eigen::Vector2d& p_WB, double cutoff_m, int* box = nullptr) const;

  /// Exact signed distance (m) from the point p_W to the nearest box (negative inside one),
  /// and that box in *box; +infinity and -1 for a scene without boxes (or none within
  /// cutoff_m).
  double PointClearance(const Eigen::Vector3d& p_W, double cutoff_m = SceneClearance::kInfinity,
                        int* box = nullptr) const;

  /// Obstacle parts only (base and spheres), from a cache already updated for the state.
  /// Boxes farther than cutoff_m are skipped (parts with nothing nearer report +infinity).
  void ComputeObstacleParts(const KinematicsCache& cache, double cutoff_m,
                            SceneClearance* clearance) const;

 private:
  void ComputeSpheres(const KinematicsCache& cache, double cutoff_m, SceneClearance* out) const;
  void ComputeSelf(SceneClearanceWorkspace* workspace, SceneClearance* out) const;

  const Kinematics& kinematics_;
  const Scene& scene_;
  SceneClearanceOptions options_;
  SelfCollision self_collision_;
  std::vector<Eigen::AlignedBox3d> box_bounds_W_;
  BoxBucketGrid buckets_;  // after box_bounds_W_, from which it is built
};

}  // namespace topay
