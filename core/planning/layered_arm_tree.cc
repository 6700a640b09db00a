#include "core/planning/layered_arm_tree.h"

#include <algorithm>
#include <limits>

namespace topay {

LayeredArmTree::LayeredArmTree(int num_layers, int root_layer, const Eigen::VectorXd& q_root,
                               int direction, const Eigen::VectorXd& weights)
    : direction_(direction),
      sqrt_weights_(weights.cwiseSqrt()),
      by_layer_(static_cast<std::size_t>(num_layers)) {
  Node root;
  root.layer = root_layer;
  root.q_rad = q_root;
  nodes_.push_back(std::move(root));
  by_layer_[static_cast<std::size_t>(root_layer)].push_back(0);
}

double LayeredArmTree::Distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  return sqrt_weights_.cwiseProduct(a - b).norm();
}

int LayeredArmTree::Nearest(int layer, const Eigen::VectorXd& q) const {
  int best = -1;
  double best_distance_sq = std::numeric_limits<double>::infinity();
  for (int l = root_layer(); (layer - l) * direction_ >= 1; l += direction_) {
    for (int id : by_layer_[static_cast<std::size_t>(l)]) {
      const double d_sq = sqrt_weights_.cwiseProduct(nodes_[id].q_rad - q).squaredNorm();
      if (d_sq < best_distance_sq) {
        best_distance_sq = d_sq;
        best = id;
      }
    }
  }
  return best;
}

void LayeredArmTree::Near(int layer, const Eigen::VectorXd& q, double radius, int max_count,
                          std::vector<std::pair<double, int>>* out) const {
  out->clear();
  if (layer < 0 || layer >= static_cast<int>(by_layer_.size())) return;
  for (int id : by_layer_[static_cast<std::size_t>(layer)]) {
    const double d = Distance(nodes_[id].q_rad, q);
    if (d <= radius) out->emplace_back(d, id);
  }
  const std::size_t keep = std::min(out->size(), static_cast<std::size_t>(max_count));
  std::partial_sort(out->begin(), out->begin() + static_cast<std::ptrdiff_t>(keep), out->end());
  out->resize(keep);
}

int LayeredArmTree::Add(int parent, const Eigen::VectorXd& q_rad) {
  Node node;
  node.layer = nodes_[parent].layer + direction_;
  node.q_rad = q_rad;
  node.parent = parent;
  node.cost = nodes_[parent].cost + Distance(nodes_[parent].q_rad, q_rad);
  const int id = size();
  by_layer_[static_cast<std::size_t>(node.layer)].push_back(id);
  nodes_.push_back(std::move(node));
  nodes_[parent].children.push_back(id);
  return id;
}

void LayeredArmTree::Reparent(int id, int new_parent) {
  Node& node = nodes_[id];
  std::vector<int>& siblings = nodes_[node.parent].children;
  siblings.erase(std::find(siblings.begin(), siblings.end(), id));
  node.parent = new_parent;
  nodes_[new_parent].children.push_back(id);
  const double new_cost = nodes_[new_parent].cost + Distance(nodes_[new_parent].q_rad, node.q_rad);
  ShiftSubtreeCost(id, new_cost - node.cost);
}

void LayeredArmTree::ShiftSubtreeCost(int id, double delta) {
  // Iterative depth-first walk: subtrees can be as deep as the layer count.
  std::vector<int> stack{id};
  while (!stack.empty()) {
    const int current = stack.back();
    stack.pop_back();
    nodes_[current].cost += delta;
    for (int child : nodes_[current].children) stack.push_back(child);
  }
}

void LayeredArmTree::PathToRoot(int id, std::vector<int>* ids_root_first) const {
  ids_root_first->clear();
  for (int current = id; current >= 0; current = nodes_[current].parent) {
    ids_root_first->push_back(current);
  }
  std::reverse(ids_root_first->begin(), ids_root_first->end());
}

}  // namespace topay
