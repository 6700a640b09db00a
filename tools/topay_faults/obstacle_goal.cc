#include "obstacle_goal.h"

#include <limits>
#include <stdexcept>

namespace topay::tools {

Eigen::Vector3d ChooseObstacleGoal(const std::vector<Eigen::Vector3d>& box_centers_m,
                                   const std::optional<Eigen::Vector2d>& p_robot_m, double near_m,
                                   std::mt19937_64* random) {
  if (box_centers_m.empty()) throw std::invalid_argument("ChooseObstacleGoal: no boxes");
  std::vector<std::size_t> candidates;
  std::size_t nearest = 0;
  double nearest_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < box_centers_m.size(); ++i) {
    if (!p_robot_m) {
      candidates.push_back(i);
      continue;
    }
    const double distance_m = (box_centers_m[i].head<2>() - *p_robot_m).norm();
    if (distance_m <= near_m) candidates.push_back(i);
    if (distance_m < nearest_m) nearest_m = distance_m, nearest = i;
  }
  if (candidates.empty()) return box_centers_m[nearest];
  std::uniform_int_distribution<std::size_t> pick(0, candidates.size() - 1);
  return box_centers_m[candidates[pick(*random)]];
}

}  // namespace topay::tools
