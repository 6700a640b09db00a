#include "core/planning/base_path.h"

namespace topay {

std::string_view BasePathSourceName(BasePathSource source) {
  switch (source) {
    case BasePathSource::kTopologicalPrm:
      return "topological_prm";
    case BasePathSource::kJumpPointSearch:
      return "jps";
    case BasePathSource::kStanding:
      return "standing";
  }
  return "unknown";
}

double PolylineLength(const std::vector<Eigen::Vector2d>& waypoints_W_m) {
  double length = 0.0;
  for (std::size_t i = 1; i < waypoints_W_m.size(); ++i) {
    length += (waypoints_W_m[i] - waypoints_W_m[i - 1]).norm();
  }
  return length;
}

}  // namespace topay
