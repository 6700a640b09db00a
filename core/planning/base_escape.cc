#include "core/planning/base_escape.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/angles.h"

namespace topay {
namespace {

// Unit directions by preference: smallest angle to the base's axis first, forwards first
// (DiscreteSE2 drives forwards only: an exit behind costs a turn in place first).
std::vector<Eigen::Vector2d> PreferredDirections(double heading_rad, int count) {
  struct Direction {
    double off_axis_rad;
    bool forwards;
    Eigen::Vector2d u;
  };
  std::vector<Direction> directions;
  for (int k = 0; k < count; ++k) {
    const double angle = heading_rad + std::numbers::pi + 2.0 * std::numbers::pi * k / count;
    const double from_backwards = std::abs(WrapAngle(angle - heading_rad - std::numbers::pi));
    const double from_forwards = std::abs(WrapAngle(angle - heading_rad));
    directions.push_back({std::min(from_backwards, from_forwards), from_forwards < from_backwards,
                          Eigen::Vector2d(std::cos(angle), std::sin(angle))});
  }
  std::stable_sort(directions.begin(), directions.end(), [](const Direction& a, const Direction& b) {
    if (a.off_axis_rad != b.off_axis_rad) return a.off_axis_rad < b.off_axis_rad - 1e-12;
    return a.forwards && !b.forwards;
  });
  std::vector<Eigen::Vector2d> units;
  for (const Direction& d : directions) units.push_back(d.u);
  return units;
}

bool MoveIsClear(const WholeBodyValidity& validity, const Eigen::Vector2d& a,
                 const Eigen::Vector2d& b, double step_m) {
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_m)));
  for (int k = 0; k <= steps; ++k) {
    if (!validity.IsBaseValid(a + (b - a) * (static_cast<double>(k) / steps))) return false;
  }
  return true;
}

// Where an escape may end: free on the field, and in the region if there is one.
struct ExitTest {
  const BaseFreeSpace& free_space;
  const BaseReachableRegion* region;

  bool operator()(const Eigen::Vector2d& p_W) const {
    return free_space.IsFree(p_W) && (region == nullptr || region->Contains(p_W));
  }
};

// The nearest exit reached by one straight move (rings outwards, preferred directions first).
std::optional<Eigen::Vector2d> StraightExit(const ExitTest& is_exit,
                                            const WholeBodyValidity& validity,
                                            const Eigen::Vector2d& p_W, double heading_rad,
                                            const BaseEscapeOptions& options) {
  const std::vector<Eigen::Vector2d> directions =
      PreferredDirections(heading_rad, options.num_directions);
  const int rings = static_cast<int>(std::floor(options.max_distance_m / options.step_m + 1e-9));
  for (int ring = 1; ring <= rings; ++ring) {
    const double radius_m = ring * options.step_m;
    for (const Eigen::Vector2d& u : directions) {
      const Eigen::Vector2d exit = p_W + radius_m * u;
      if (!is_exit(exit)) continue;
      if (MoveIsClear(validity, p_W, exit, options.check_step_m)) return exit;
    }
  }
  return std::nullopt;
}

// Dijkstra on the square lattice of spacing h centred on p_W (cells within max_distance_m),
// 8-connected; a node is open if the base check accepts it, an edge if its interior points
// every check_step_m do. Returns the lattice route p_W -> first exit node (p_W excluded).
class EscapeLattice {
 public:
  EscapeLattice(const WholeBodyValidity& validity, const Eigen::Vector2d& p_W,
                const BaseEscapeOptions& options)
      : validity_(validity), p_W_(p_W), options_(options),
        half_(static_cast<int>(std::floor(options.max_distance_m / options.route_step_m))),
        side_(2 * half_ + 1), state_(side_ * side_, kUnknown),
        cost_(side_ * side_, std::numeric_limits<double>::infinity()), parent_(side_ * side_, -1) {}

  std::vector<Eigen::Vector2d> RouteToExit(const ExitTest& is_exit) {
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    const int origin = half_ * side_ + half_;
    cost_[origin] = 0.0;
    state_[origin] = kOpen;
    open.push({0.0, origin});
    while (!open.empty()) {
      const auto [cost, node] = open.top();
      open.pop();
      if (cost > cost_[node]) continue;
      if (node != origin && is_exit(Position(node))) return Route(node);
      Expand(node);
      for (const auto& [next, next_cost] : expanded_) open.push({next_cost, next});
    }
    return {};
  }

 private:
  static constexpr char kUnknown = 0, kOpen = 1, kBlocked = 2;

  Eigen::Vector2d Position(int node) const {
    return p_W_ + options_.route_step_m * Eigen::Vector2d(node % side_ - half_, node / side_ - half_);
  }
  bool IsOpen(int node) {
    if (state_[node] == kUnknown) {
      const Eigen::Vector2d p = Position(node);
      const bool inside = (p - p_W_).norm() <= options_.max_distance_m + 1e-9;
      state_[node] = inside && validity_.IsBaseValid(p) ? kOpen : kBlocked;
    }
    return state_[node] == kOpen;
  }
  bool EdgeIsClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / options_.check_step_m)));
    for (int k = 1; k < steps; ++k) {
      if (!validity_.IsBaseValid(a + (b - a) * (static_cast<double>(k) / steps))) return false;
    }
    return true;
  }
  void Expand(int node) {
    expanded_.clear();
    const int i = node % side_, j = node / side_;
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || i + di < 0 || i + di >= side_ || j + dj < 0 ||
            j + dj >= side_) {
          continue;
        }
        const int next = node + dj * side_ + di;
        const double next_cost = cost_[node] + options_.route_step_m * std::hypot(di, dj);
        if (next_cost >= cost_[next] || !IsOpen(next)) continue;
        if (!EdgeIsClear(Position(node), Position(next))) continue;
        cost_[next] = next_cost;
        parent_[next] = node;
        expanded_.push_back({next, next_cost});
      }
    }
  }
  std::vector<Eigen::Vector2d> Route(int node) const {
    std::vector<Eigen::Vector2d> route;
    for (int n = node; parent_[n] >= 0; n = parent_[n]) route.push_back(Position(n));
    std::reverse(route.begin(), route.end());
    return route;
  }

  const WholeBodyValidity& validity_;
  Eigen::Vector2d p_W_;
  const BaseEscapeOptions& options_;
  int half_, side_;
  std::vector<char> state_;
  std::vector<double> cost_;
  std::vector<int> parent_;
  std::vector<std::pair<int, double>> expanded_;
};

// String pulling: from each kept waypoint, straight on to the farthest route point that a
// clear straight move reaches (the lattice moves themselves are clear).
std::vector<Eigen::Vector2d> Shorten(const WholeBodyValidity& validity, const Eigen::Vector2d& p_W,
                                     const std::vector<Eigen::Vector2d>& route, double step_m) {
  std::vector<Eigen::Vector2d> kept;
  Eigen::Vector2d anchor = p_W;
  std::size_t k = 0;
  while (k < route.size()) {
    std::size_t reach = k;  // route[k] is always reachable from the anchor (a lattice move)
    while (reach + 1 < route.size() && MoveIsClear(validity, anchor, route[reach + 1], step_m)) {
      ++reach;
    }
    kept.push_back(route[reach]);
    anchor = route[reach];
    k = reach + 1;
  }
  return kept;
}

}  // namespace

double BaseEscape::LengthFrom(const Eigen::Vector2d& from_W) const {
  double length_m = 0.0;
  Eigen::Vector2d previous = from_W;
  for (const Eigen::Vector2d& p : waypoints_W_m) {
    length_m += (p - previous).norm();
    previous = p;
  }
  return length_m;
}

void CheckBaseEscapeOptions(const BaseEscapeOptions& o) {
  const auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("BaseEscapeOptions::") + field + " must be " + rule);
  };
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  require(positive(o.max_distance_m), "max_distance_m", "finite and > 0");
  require(positive(o.step_m), "step_m", "finite and > 0");
  require(positive(o.check_step_m), "check_step_m", "finite and > 0");
  require(o.num_directions >= 4, "num_directions", ">= 4");
  require(std::isfinite(o.route_step_m) && o.route_step_m >= 0.0, "route_step_m",
          "finite and >= 0 (0: straight moves only)");
}

std::optional<BaseEscape> FindBaseEscape(const BaseFreeSpace& free_space,
                                         const WholeBodyValidity& validity,
                                         const Eigen::Vector2d& p_W, double heading_rad,
                                         const BaseEscapeOptions& options,
                                         const BaseReachableRegion* region) {
  CheckBaseEscapeOptions(options);
  if (!p_W.allFinite() || !std::isfinite(heading_rad)) return std::nullopt;
  const ExitTest is_exit{free_space, region};
  if (const auto exit = StraightExit(is_exit, validity, p_W, heading_rad, options)) {
    return BaseEscape{{*exit}};
  }
  if (options.route_step_m <= 0.0 || !validity.IsBaseValid(p_W)) return std::nullopt;
  const std::vector<Eigen::Vector2d> route =
      EscapeLattice(validity, p_W, options).RouteToExit(is_exit);
  if (route.empty()) return std::nullopt;
  return BaseEscape{Shorten(validity, p_W, route, options.check_step_m)};
}

}  // namespace topay
