#include "procs/planner/goal_screen.h"

#include <fmt/format.h>

#include "core/map/unseen_pocket.h"
#include "procs/planner/planner_world.h"

namespace topay::planner {

std::string ScreenGoal(const msgs::PlanGoal& goal, const MapIntake& map, const ReachHeights& reach,
                       const GoalCheckOptions& options) {
  const Eigen::Vector3d p = goal.X_WE.translation();
  if (p.z() < reach.min_z_m || p.z() > reach.max_z_m) {
    return fmt::format("target height {:.3f} m is outside the arm's reach [{:.3f}, {:.3f}] m from any base pose",
                       p.z(), reach.min_z_m, reach.max_z_m);
  }
  return ScreenTargetInMap(p, map, options);
}

std::string ScreenTargetInMap(const Eigen::Vector3d& p, const MapIntake& map, const GoalCheckOptions& options) {
  if (!map.has_map()) return "";  // the plan itself waits for (and reports) the missing map
  const GridGeometry3& grid = map.receiver().geometry();
  const Eigen::AlignedBox3d bounds = GridBounds(grid);
  if (!bounds.contains(p)) {
    return fmt::format("target ({:.3f}, {:.3f}, {:.3f}) m is outside the map [{:.2f}, {:.2f}] x [{:.2f}, {:.2f}] x [{:.2f}, {:.2f}] m",
                       p.x(), p.y(), p.z(), bounds.min().x(), bounds.max().x(), bounds.min().y(),
                       bounds.max().y(), bounds.min().z(), bounds.max().z());
  }
  if (map.NearBlocked(p, options.target_clearance_m)) {
    return fmt::format("target ({:.3f}, {:.3f}, {:.3f}) m is inside an obstacle of the map (a blocked voxel within {:.3f} m)",
                       p.x(), p.y(), p.z(), options.target_clearance_m);
  }
  if (options.unseen_pocket_reach_m > 0.0) {
    UnseenPocketOptions pocket_options;
    pocket_options.max_reach_m = options.unseen_pocket_reach_m;
    pocket_options.min_occupied_rim_share = options.unseen_pocket_rim_share;
    const UnseenPocket pocket = FindUnseenPocket(grid, map.receiver().states(), p, pocket_options);
    if (pocket.enclosed) {
      const Eigen::Vector2d size = pocket.extent_W_m.sizes();
      return fmt::format("target ({:.3f}, {:.3f}, {:.3f}) m is inside an obstacle of the map: a body seen only from "
                         "outside (the target's voxel never observed, in an unseen pocket of {} voxels, {:.2f} x {:.2f} m, "
                         "{} of the {} voxels around it occupied)",
                         p.x(), p.y(), p.z(), pocket.voxels, size.x(), size.y(), pocket.rim_occupied,
                         pocket.rim_occupied + pocket.rim_free);
    }
  }
  return "";
}

}  // namespace topay::planner
