#include "procs/planner/goal_screen.h"

#include <fmt/format.h>

#include "procs/planner/planner_world.h"

namespace topay::planner {

std::string ScreenGoal(const msgs::PlanGoal& goal, const MapIntake& map, const ReachHeights& reach,
                       const GoalCheckOptions& options) {
  const Eigen::Vector3d p = goal.X_WE.translation();
  if (p.z() < reach.min_z_m || p.z() > reach.max_z_m) {
    return fmt::format("target height {:.3f} m is outside the arm's reach [{:.3f}, {:.3f}] m from any base pose",
                       p.z(), reach.min_z_m, reach.max_z_m);
  }
  if (!map.has_map()) return "";  // the plan itself waits for (and reports) the missing map
  const Eigen::AlignedBox3d bounds = GridBounds(map.receiver().geometry());
  if (!bounds.contains(p)) {
    return fmt::format("target ({:.3f}, {:.3f}, {:.3f}) m is outside the map [{:.2f}, {:.2f}] x [{:.2f}, {:.2f}] x [{:.2f}, {:.2f}] m",
                       p.x(), p.y(), p.z(), bounds.min().x(), bounds.max().x(), bounds.min().y(),
                       bounds.max().y(), bounds.min().z(), bounds.max().z());
  }
  if (map.NearBlocked(p, options.target_clearance_m)) {
    return fmt::format("target ({:.3f}, {:.3f}, {:.3f}) m is inside an obstacle of the map (a blocked voxel within {:.3f} m)",
                       p.x(), p.y(), p.z(), options.target_clearance_m);
  }
  return "";
}

}  // namespace topay::planner
