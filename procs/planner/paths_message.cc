#include "procs/planner/paths_message.h"

namespace topay::planner {

planner_paths_t ToPathsMessage(const WholeBodyPlanResult& result, std::int64_t utime, std::int64_t goal_id,
                               std::int64_t trajectory_id) {
  planner_paths_t msg;
  msg.utime = utime;
  msg.goal_id = goal_id;
  msg.trajectory_id = trajectory_id;
  msg.chosen = -1;
  const std::vector<BasePath>& paths = result.front_end.base_paths;
  if (const CandidateReport* chosen = result.chosen_candidate()) {
    const int path = chosen->path_index;
    if (path >= 0 && path < static_cast<int>(result.front_end.paths.size())) {
      const int base = result.front_end.paths[path].path.base_path_index;
      if (base >= 0 && base < static_cast<int>(paths.size())) msg.chosen = base;
    }
  }
  msg.num_paths = static_cast<std::int32_t>(paths.size());
  for (const BasePath& path : paths) {
    msg.path_points.push_back(static_cast<std::int32_t>(path.waypoints_W_m.size()));
    msg.length_m.push_back(path.length_m);
    msg.source.push_back(std::string(BasePathSourceName(path.source)));
    for (const Eigen::Vector2d& p : path.waypoints_W_m) {
      msg.x_m.push_back(p.x());
      msg.y_m.push_back(p.y());
    }
  }
  msg.num_points = static_cast<std::int32_t>(msg.x_m.size());
  return msg;
}

}  // namespace topay::planner
