#include "core/planning/jump_point_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include "core/common/stopwatch.h"
#include "core/planning/base_free_space.h"
#include "core/planning/base_path.h"
#include "core/planning/traversable_grid.h"

namespace topay {
namespace {

using Status = JumpPointSearchResult::Status;
constexpr int kNone = TraversableGrid::kNoCell;

// The traversable cells of the field and the jump primitives of JPS without
// corner cutting.
class JpsGrid : public TraversableGrid {
 public:
  using TraversableGrid::TraversableGrid;
  // A cell reached moving straight along (dx, dy) has a forced neighbour on
  // side (sx, sy) (perpendicular unit) when that side cell is free but its
  // predecessor along the line is blocked: no path through the previous cell
  // reaches it as cheaply.
  bool ForcedSide(int x, int y, int dx, int dy, int sx, int sy) const {
    return Free(x + sx, y + sy) && !Free(x - dx + sx, y - dy + sy);
  }
  bool HasForcedNeighbour(int x, int y, int dx, int dy) const {
    return ForcedSide(x, y, dx, dy, dy, dx) || ForcedSide(x, y, dx, dy, -dy, -dx);
  }

  // Jump from (x, y) along a straight direction; returns the cell index of the
  // jump point (goal or a cell with a forced neighbour) or kNone.
  int JumpStraight(int x, int y, int dx, int dy, int goal) const {
    while (CanStep(x, y, dx, dy)) {
      x += dx;
      y += dy;
      const int index = Index(x, y);
      if (index == goal || HasForcedNeighbour(x, y, dx, dy)) return index;
    }
    return kNone;
  }
  // Jump diagonally: a cell is a jump point if it is the goal or a straight
  // jump from it along either component finds one.
  int JumpDiagonal(int x, int y, int dx, int dy, int goal) const {
    while (CanStep(x, y, dx, dy)) {
      x += dx;
      y += dy;
      const int index = Index(x, y);
      if (index == goal || JumpStraight(x, y, dx, 0, goal) != kNone ||
          JumpStraight(x, y, 0, dy, goal) != kNone) {
        return index;
      }
    }
    return kNone;
  }
  int Jump(int x, int y, int dx, int dy, int goal) const {
    return dx != 0 && dy != 0 ? JumpDiagonal(x, y, dx, dy, goal) : JumpStraight(x, y, dx, dy, goal);
  }
};

int Sign(int v) { return (v > 0) - (v < 0); }

// Octile distance in cells (exact cost of a straight or diagonal run;
// admissible heuristic).
double Octile(int dx, int dy) {
  dx = std::abs(dx);
  dy = std::abs(dy);
  return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
}

// Pruned successor directions of a node reached along (dx, dy) ((0, 0) for the
// start).
int SuccessorDirections(const JpsGrid& grid, int x, int y, int dx, int dy, int dirs[8][2]) {
  int n = 0;
  auto add = [&](int a, int b) {
    dirs[n][0] = a;
    dirs[n][1] = b;
    ++n;
  };
  if (dx == 0 && dy == 0) {
    for (int a = -1; a <= 1; ++a) {
      for (int b = -1; b <= 1; ++b) {
        if (a != 0 || b != 0) add(a, b);
      }
    }
  } else if (dx != 0 && dy != 0) {
    add(dx, 0);
    add(0, dy);
    add(dx, dy);
  } else {
    add(dx, dy);
    for (int side : {-1, 1}) {
      const int sx = dy * side, sy = dx * side;  // perpendicular
      if (grid.ForcedSide(x, y, dx, dy, sx, sy)) {
        add(sx, sy);
        add(dx + sx, dy + sy);
      }
    }
  }
  return n;
}

JumpPointSearchResult Fail(Status status, std::string reason) {
  JumpPointSearchResult result;
  result.status = status;
  result.reason = std::move(reason);
  return result;
}

struct OpenEntry {
  double f;
  int index;
  bool operator>(const OpenEntry& o) const { return f > o.f || (f == o.f && index > o.index); }
};

// A* over jump points; fills the cell path (start cell ... goal cell, jump
// points only).
Status SearchJumpPoints(const JpsGrid& grid, int start, int goal, std::int64_t max_expansions,
                        const std::stop_token& stop, std::vector<int>* jump_points,
                        std::int64_t* num_expanded) {
  const int nx = grid.nx();
  const int gx = goal % nx, gy = goal / nx;
  // Sparse node states: A* over jump points touches few of the grid's cells (a dense array
  // per search would cost more than the search on a fine grid).
  struct Node {
    double cost = std::numeric_limits<double>::infinity();
    int parent = kNone;
    bool closed = false;
  };
  std::unordered_map<int, Node> nodes;
  nodes.reserve(4096);
  std::priority_queue<OpenEntry, std::vector<OpenEntry>, std::greater<>> open;
  nodes[start].cost = 0.0;
  open.push({Octile(gx - start % nx, gy - start / nx), start});
  *num_expanded = 0;
  while (!open.empty()) {
    const int current = open.top().index;
    open.pop();
    Node& node = nodes[current];
    if (node.closed) continue;  // stale entry
    node.closed = true;
    if (current == goal) {
      for (int c = goal; c != kNone; c = nodes[c].parent) jump_points->push_back(c);
      std::reverse(jump_points->begin(), jump_points->end());
      return Status::kSuccess;
    }
    if (++*num_expanded > max_expansions) return Status::kExpansionCapHit;
    if ((*num_expanded & 255) == 1 && stop.stop_requested()) return Status::kCancelled;
    const int x = current % nx, y = current / nx;
    int dx = 0, dy = 0;
    const int current_parent = node.parent;
    const double current_cost = node.cost;
    if (current_parent != kNone) {
      dx = Sign(x - current_parent % nx);
      dy = Sign(y - current_parent / nx);
    }
    int dirs[8][2];
    const int num_dirs = SuccessorDirections(grid, x, y, dx, dy, dirs);
    for (int k = 0; k < num_dirs; ++k) {
      const int next = grid.Jump(x, y, dirs[k][0], dirs[k][1], goal);
      if (next == kNone) continue;
      Node& successor = nodes[next];  // may rehash: `node` is not used below
      if (successor.closed) continue;
      const int ux = next % nx, uy = next / nx;
      // Runs between jump points are straight or diagonal: their cost is the
      // octile distance.
      const double g = current_cost + Octile(ux - x, uy - y);
      if (g < successor.cost) {
        successor.cost = g;
        successor.parent = current;
        open.push({g + Octile(gx - ux, gy - uy), next});
      }
    }
  }
  return Status::kNoPath;
}

}  // namespace

JumpPointSearchResult JumpPointSearch(const SignedDistanceField2& field,
                                      const Eigen::Vector2d& start_W_m,
                                      const Eigen::Vector2d& goal_W_m,
                                      const JumpPointSearchOptions& options, std::stop_token stop) {
  const Stopwatch watch;
  if (!start_W_m.allFinite() || !goal_W_m.allFinite()) {
    return Fail(Status::kInvalidInput, "JPS: start or goal position is not finite");
  }
  if (!std::isfinite(options.safe_distance_m)) {
    return Fail(Status::kInvalidInput, "JPS: safe_distance_m is not finite");
  }
  const BaseFreeSpace free_space(field, options.safe_distance_m);
  if (!free_space.IsFree(start_W_m)) {
    return Fail(Status::kStartBlocked,
                "JPS: start is outside the map or closer than the safe "
                "distance to an obstacle");
  }
  if (!free_space.IsFree(goal_W_m)) {
    return Fail(Status::kGoalBlocked,
                "JPS: goal is outside the map or closer than the safe "
                "distance to an obstacle");
  }
  JumpPointSearchResult result;
  result.status = Status::kSuccess;
  if (free_space.IsSegmentFree(start_W_m, goal_W_m)) {
    result.path_W_m = {start_W_m, goal_W_m};
  } else {
    const JpsGrid grid(field, options.safe_distance_m);
    const int start = ConnectToGrid(field, grid, free_space, start_W_m);
    if (start == kNone) {
      return Fail(Status::kStartBlocked, "JPS: start sees no traversable cell centre nearby");
    }
    const int goal = ConnectToGrid(field, grid, free_space, goal_W_m);
    if (goal == kNone) {
      return Fail(Status::kGoalBlocked, "JPS: goal sees no traversable cell centre nearby");
    }
    std::vector<int> jump_points;
    const Status status = SearchJumpPoints(grid, start, goal, options.max_expansions, stop,
                                           &jump_points, &result.num_expanded);
    if (status == Status::kNoPath) {
      return Fail(status, "JPS: goal is not connected to the start on the inflated grid");
    }
    if (status == Status::kExpansionCapHit) {
      return Fail(status, "JPS: expansion cap hit");
    }
    if (status == Status::kCancelled) return Fail(status, "JPS: cancelled");
    result.path_W_m.push_back(start_W_m);
    for (int c : jump_points) {
      result.path_W_m.push_back(field.geometry().CellCenter(c % grid.nx(), c / grid.nx()));
    }
    result.path_W_m.push_back(goal_W_m);
  }
  result.grid_length_m = PolylineLength(result.path_W_m);
  if (options.shortcut) {
    result.path_W_m = ShortcutPath(free_space, result.path_W_m, options.shortcut_options);
  }
  result.length_m = PolylineLength(result.path_W_m);
  result.time_s = watch.ElapsedS();
  return result;
}

}  // namespace topay
