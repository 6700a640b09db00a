#include "core/planning/visibility_prm.h"

#include <algorithm>

#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/planning/uvd_equivalence.h"

namespace topay {
namespace {

// Uniform samples in the rectangle aligned with start -> goal.
class AlignedBoxSampler {
 public:
  AlignedBoxSampler(const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                    const VisibilityPrmOptions& options)
      : center_(0.5 * (start + goal)), rng_(options.seed) {
    const Eigen::Vector2d d = goal - start;
    const double length = d.norm();
    axis_u_ = length > 0.0 ? Eigen::Vector2d(d / length) : Eigen::Vector2d::UnitX();
    axis_v_ = Eigen::Vector2d(-axis_u_.y(), axis_u_.x());
    half_length_ = 0.5 * length + options.sample_margin_length_m;
    half_width_ = options.sample_half_width_m;
  }
  Eigen::Vector2d Sample() {
    const double a = rng_.Uniform(-half_length_, half_length_);
    const double b = rng_.Uniform(-half_width_, half_width_);
    return center_ + a * axis_u_ + b * axis_v_;
  }

 private:
  Eigen::Vector2d center_;
  Eigen::Vector2d axis_u_;
  Eigen::Vector2d axis_v_;
  double half_length_ = 0.0;
  double half_width_ = 0.0;
  Rng rng_;
};

int AddNode(VisibilityPrmGraph* graph, const Eigen::Vector2d& p, PrmNode::Kind kind) {
  PrmNode node;
  node.p_W_m = p;
  node.kind = kind;
  graph->nodes.push_back(std::move(node));
  if (kind == PrmNode::Kind::kGuard) {
    ++graph->num_guards;
  } else {
    ++graph->num_connectors;
  }
  return static_cast<int>(graph->nodes.size()) - 1;
}

void AddEdge(VisibilityPrmGraph* graph, int a, int b) {
  graph->nodes[a].neighbors.push_back(b);
  graph->nodes[b].neighbors.push_back(a);
}

// Up to 3 guards visible from p (3 is enough to tell "exactly two" apart).
int VisibleGuards(const BaseFreeSpace& free_space, const VisibilityPrmGraph& graph,
                  const std::vector<int>& guards, const Eigen::Vector2d& p, int visible[3]) {
  int count = 0;
  for (int g : guards) {
    if (free_space.IsSegmentFree(p, graph.nodes[g].p_W_m)) {
      visible[count++] = g;
      if (count == 3) break;
    }
  }
  return count;
}

// The topological connector rule: if g1 and g2 already share a connector whose
// path is UVD-equivalent to g1-p-g2, keep the shorter one and report true; else
// false.
bool MergeWithEquivalentConnector(const BaseFreeSpace& free_space, VisibilityPrmGraph* graph,
                                  int g1, int g2, const Eigen::Vector2d& p, double resolution) {
  const Eigen::Vector2d& p1 = graph->nodes[g1].p_W_m;
  const Eigen::Vector2d& p2 = graph->nodes[g2].p_W_m;
  const std::vector<Eigen::Vector2d> candidate{p1, p, p2};
  const double candidate_length = (p - p1).norm() + (p2 - p).norm();
  for (int c : graph->nodes[g1].neighbors) {
    const std::vector<int>& c_neighbors = graph->nodes[c].neighbors;
    if (std::find(c_neighbors.begin(), c_neighbors.end(), g2) == c_neighbors.end()) continue;
    const Eigen::Vector2d pc = graph->nodes[c].p_W_m;
    if (!UvdEquivalent(free_space, {p1, pc, p2}, candidate, resolution)) continue;
    if (candidate_length < (pc - p1).norm() + (p2 - pc).norm()) graph->nodes[c].p_W_m = p;
    return true;
  }
  return false;
}

}  // namespace

VisibilityPrmGraph BuildVisibilityPrm(const BaseFreeSpace& free_space,
                                      const Eigen::Vector2d& start_W_m,
                                      const Eigen::Vector2d& goal_W_m,
                                      const VisibilityPrmOptions& options, std::stop_token stop) {
  const Stopwatch watch;
  const double resolution = options.uvd_resolution_m > 0.0
                                ? options.uvd_resolution_m
                                : free_space.field().geometry().resolution_m;
  VisibilityPrmGraph graph;
  std::vector<int> guards{AddNode(&graph, start_W_m, PrmNode::Kind::kGuard),
                          AddNode(&graph, goal_W_m, PrmNode::Kind::kGuard)};
  AlignedBoxSampler sampler(start_W_m, goal_W_m, options);
  while (graph.num_samples < options.max_samples) {
    if (stop.stop_requested()) {
      graph.cancelled = true;
      break;
    }
    if (options.max_time_s > 0.0 && watch.ElapsedS() > options.max_time_s) {
      graph.time_limit_hit = true;
      break;
    }
    const Eigen::Vector2d p = sampler.Sample();
    ++graph.num_samples;
    if (!free_space.IsFree(p)) continue;
    ++graph.num_free_samples;
    int visible[3];
    const int num_visible = VisibleGuards(free_space, graph, guards, p, visible);
    if (num_visible == 0) {
      guards.push_back(AddNode(&graph, p, PrmNode::Kind::kGuard));
    } else if (num_visible == 2 && !MergeWithEquivalentConnector(free_space, &graph, visible[0],
                                                                 visible[1], p, resolution)) {
      const int c = AddNode(&graph, p, PrmNode::Kind::kConnector);
      AddEdge(&graph, c, visible[0]);
      AddEdge(&graph, c, visible[1]);
    }
  }
  return graph;
}

void PruneDeadEnds(VisibilityPrmGraph* graph) {
  std::vector<PrmNode>& nodes = graph->nodes;
  const int n = static_cast<int>(nodes.size());
  std::vector<bool> removed(n, false);
  std::vector<int> degree(n);
  std::vector<int> queue;
  for (int i = 0; i < n; ++i) {
    degree[i] = static_cast<int>(nodes[i].neighbors.size());
    if (i > 1 && degree[i] < 2) queue.push_back(i);
  }
  while (!queue.empty()) {
    const int i = queue.back();
    queue.pop_back();
    if (removed[i]) continue;
    removed[i] = true;
    for (int j : nodes[i].neighbors) {
      if (!removed[j] && --degree[j] < 2 && j > 1) queue.push_back(j);
    }
  }
  std::vector<int> new_index(n, -1);
  std::vector<PrmNode> kept;
  for (int i = 0; i < n; ++i) {
    if (removed[i]) continue;
    new_index[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(nodes[i]));
  }
  graph->num_guards = 0;
  graph->num_connectors = 0;
  for (PrmNode& node : kept) {
    std::vector<int> neighbors;
    for (int j : node.neighbors) {
      if (new_index[j] >= 0) neighbors.push_back(new_index[j]);
    }
    node.neighbors = std::move(neighbors);
    if (node.kind == PrmNode::Kind::kGuard) {
      ++graph->num_guards;
    } else {
      ++graph->num_connectors;
    }
  }
  nodes = std::move(kept);
}

}  // namespace topay
