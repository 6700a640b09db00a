#include "core/collision/scene_clearance.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/primitive_box_distance.h"

namespace topay {
namespace {

// Exact minimum over boxes with AABB pruning: box i is examined only if the separation of its
// AABB from the primitive's AABB (a lower bound of the primitive-box distance, valid when
// positive) is at most the best distance so far; the bucket grid visits the boxes near the
// primitive first and stops once every other box's AABB is farther than the best. `exact(i)`
// gives the signed distance to box i. Ties go to the lowest box index, as a scan in index
// order would give.
template <typename ExactDistance>
void MinimumOverBoxes(const BoxBucketGrid& grid,
                      const std::vector<Eigen::AlignedBox3d>& box_bounds,
                      const Eigen::AlignedBox3d& primitive_bounds, double cutoff_m,
                      ExactDistance exact, double* min_m, int* min_box) {
  double best = cutoff_m;
  int best_box = -1;
  grid.VisitNear(
      primitive_bounds.min().head<2>(), primitive_bounds.max().head<2>(),
      [&best] { return best; },
      [&](int i) {
        const double gap_squared = box_bounds[i].squaredExteriorDistance(primitive_bounds);
        // distance >= gap > 0: skip if gap > best.
        if (gap_squared > 0.0 && (best <= 0.0 || gap_squared > best * best)) return;
        const double distance = exact(i);
        if (distance < best || (distance == best && best_box >= 0 && i < best_box)) {
          best = distance;
          best_box = i;
        }
      });
  *min_m = best_box >= 0 ? best : SceneClearance::kInfinity;
  *min_box = best_box;
}

std::vector<Eigen::AlignedBox3d> WorldBoundsOf(const Scene& scene) {
  std::vector<Eigen::AlignedBox3d> bounds;
  bounds.reserve(scene.boxes.size());
  for (const OrientedBox& box : scene.boxes) bounds.push_back(box.WorldBounds());
  return bounds;
}

}  // namespace

SceneClearanceChecker::SceneClearanceChecker(const Kinematics& kinematics, const Scene& scene,
                                             const SceneClearanceOptions& options)
    : kinematics_(kinematics),
      scene_(scene),
      options_(options),
      self_collision_(kinematics),
      box_bounds_W_(WorldBoundsOf(scene)),
      buckets_(box_bounds_W_) {}

SceneClearanceWorkspace SceneClearanceChecker::MakeWorkspace() const {
  SceneClearanceWorkspace workspace;
  workspace.cache = kinematics_.MakeCache();
  workspace.pair_distances_m.resize(self_collision_.num_pairs());
  workspace.chassis_margins_m.resize(self_collision_.num_spheres());
  return workspace;
}

SceneClearance SceneClearanceChecker::Compute(const WholeBodyState& state,
                                              SceneClearanceWorkspace* workspace) const {
  kinematics_.Update(state, &workspace->cache);
  SceneClearance clearance;
  ComputeObstacleParts(workspace->cache, options_.cutoff_m, &clearance);
  ComputeSelf(workspace, &clearance);
  clearance.min_m = std::min({clearance.base_m, clearance.spheres_m, clearance.self_m,
                              clearance.chassis_m});
  return clearance;
}

SceneClearance SceneClearanceChecker::Compute(const WholeBodyState& state) const {
  SceneClearanceWorkspace workspace = MakeWorkspace();
  return Compute(state, &workspace);
}

bool SceneClearanceChecker::IsCollisionFree(const WholeBodyState& state,
                                            double obstacle_margin_m, double self_margin_m,
                                            SceneClearanceWorkspace* workspace) const {
  kinematics_.Update(state, &workspace->cache);
  SceneClearance clearance;
  ComputeSelf(workspace, &clearance);
  if (!(clearance.self_m > self_margin_m && clearance.chassis_m > self_margin_m)) return false;
  // Only a box nearer than the margin can make the state not free.
  ComputeObstacleParts(workspace->cache, std::min(options_.cutoff_m, obstacle_margin_m),
                       &clearance);
  return clearance.IsCollisionFree(obstacle_margin_m, self_margin_m);
}

void SceneClearanceChecker::ComputeObstacleParts(const KinematicsCache& cache, double cutoff_m,
                                                 SceneClearance* clearance) const {
  clearance->base_m =
      BaseClearance(cache.X_WB.translation().head<2>(), cutoff_m, &clearance->base_box);
  ComputeSpheres(cache, cutoff_m, clearance);
}

double SceneClearanceChecker::BaseClearance(const Eigen::Vector2d& p_WB, double cutoff_m,
                                            int* box) const {
  const BaseCylinder& base = kinematics_.model().base_cylinder;
  const VerticalCylinder cylinder{p_WB, base.radius_m, 0.0, base.height_m};
  const Eigen::Vector3d extent(base.radius_m, base.radius_m, 0.0);
  const Eigen::Vector3d p_low(p_WB.x(), p_WB.y(), 0.0);
  const Eigen::AlignedBox3d bounds(p_low - extent,
                                   p_low + extent + Eigen::Vector3d(0.0, 0.0, base.height_m));
  double distance;
  int nearest;
  MinimumOverBoxes(
      buckets_, box_bounds_W_, bounds, cutoff_m,
      [&](int i) { return SignedDistanceCylinderToBox(scene_.boxes[i], cylinder); }, &distance,
      &nearest);
  if (box != nullptr) *box = nearest;
  return distance;
}

double SceneClearanceChecker::PointClearance(const Eigen::Vector3d& p_W, double cutoff_m,
                                             int* box) const {
  double distance;
  int nearest;
  MinimumOverBoxes(
      buckets_, box_bounds_W_, Eigen::AlignedBox3d(p_W, p_W), cutoff_m,
      [&](int i) { return SignedDistanceToBox(scene_.boxes[i], p_W); }, &distance, &nearest);
  if (box != nullptr) *box = nearest;
  return distance;
}

void SceneClearanceChecker::ComputeSpheres(const KinematicsCache& cache, double cutoff_m,
                                           SceneClearance* out) const {
  const std::vector<CollisionSphere>& spheres = kinematics_.model().spheres;
  out->spheres_m = SceneClearance::kInfinity;
  out->sphere = -1;
  out->sphere_box = -1;
  for (int s = 0; s < static_cast<int>(spheres.size()); ++s) {
    const Eigen::Vector3d& p_WS = cache.p_WS[s];
    const double r = spheres[s].radius_m;
    const Eigen::Vector3d extent = Eigen::Vector3d::Constant(r);
    double distance;
    int box;
    // Earlier spheres' best tightens the cutoff: only a nearer box can change the minimum.
    MinimumOverBoxes(
        buckets_, box_bounds_W_, Eigen::AlignedBox3d(p_WS - extent, p_WS + extent),
        std::min(cutoff_m, out->spheres_m),
        [&](int i) { return SignedDistanceSphereToBox(scene_.boxes[i], p_WS, r); }, &distance,
        &box);
    if (box >= 0 && distance < out->spheres_m) {
      out->spheres_m = distance;
      out->sphere = s;
      out->sphere_box = box;
    }
  }
}

void SceneClearanceChecker::ComputeSelf(SceneClearanceWorkspace* workspace,
                                        SceneClearance* out) const {
  self_collision_.Distances(workspace->cache, workspace->pair_distances_m);
  self_collision_.ChassisMargins(workspace->cache, workspace->chassis_margins_m);
  out->self_m = SceneClearance::kInfinity;
  out->self_pair = -1;
  for (int k = 0; k < workspace->pair_distances_m.size(); ++k) {
    if (workspace->pair_distances_m(k) < out->self_m) {
      out->self_m = workspace->pair_distances_m(k);
      out->self_pair = k;
    }
  }
  out->chassis_m = SceneClearance::kInfinity;
  out->chassis_sphere = -1;
  for (int s = 0; s < workspace->chassis_margins_m.size(); ++s) {
    if (workspace->chassis_margins_m(s) < out->chassis_m) {
      out->chassis_m = workspace->chassis_margins_m(s);
      out->chassis_sphere = s;
    }
  }
}

}  // namespace topay
