#include "core/planning/layered_rrt_search.h"

#include <algorithm>
#include <cmath>

namespace topay {

LayeredRrtSearch::LayeredRrtSearch(const DiscreteSE2Path& base, const Eigen::VectorXd& q_start,
                                   const Eigen::VectorXd& q_goal, const WholeBodyValidity& validity,
                                   const ArmRrtStarOptions& options, const Eigen::VectorXd& weights,
                                   std::stop_token stop)
    : base_(base),
      validity_(validity),
      options_(options),
      stop_(std::move(stop)),
      rng_(options.seed),
      sampler_(q_start, q_goal, weights),
      workspace_(validity.MakeWorkspace()),
      trees_{LayeredArmTree(base.num_layers(), 0, q_start, +1, weights),
             LayeredArmTree(base.num_layers(), base.num_layers() - 1, q_goal, -1, weights)},
      qd_max_(validity.model().joint_limits.qd_max_radps) {
  ComputeLayerBoxes(q_start, q_goal);
}

void LayeredRrtSearch::ComputeLayerBoxes(const Eigen::VectorXd& q_start,
                                         const Eigen::VectorXd& q_goal) {
  const JointLimits& limits = validity_.model().joint_limits;
  const double total = base_.total_time_s();
  for (const Se2Layer& layer : base_.layers) {
    // Reachable at |qd_i| <= qd_max_i: |q_i - q_start_i| <= qd_max_i t and
    // |q_goal_i - q_i| <= qd_max_i (T - t).
    const Eigen::VectorXd from_start = qd_max_ * layer.time_s;
    const Eigen::VectorXd to_goal = qd_max_ * (total - layer.time_s);
    box_low_.push_back(limits.q_min_rad.cwiseMax(q_start - from_start).cwiseMax(q_goal - to_goal));
    box_high_.push_back(limits.q_max_rad.cwiseMin(q_start + from_start).cwiseMin(q_goal + to_goal));
  }
}

bool LayeredRrtSearch::Interrupted() const {
  if (stop_.stop_requested()) return true;
  return watch_.ElapsedS() >= options_.time_budget_s;
}

void LayeredRrtSearch::SampleQ(int layer, Eigen::VectorXd* q) {
  const Eigen::VectorXd& low = box_low_[static_cast<std::size_t>(layer)];
  const Eigen::VectorXd& high = box_high_[static_cast<std::size_t>(layer)];
  if (std::isfinite(c_max_)) {
    for (int draw = 0; draw < options_.max_informed_draws; ++draw) {
      sampler_.Sample(c_max_, &rng_, q);
      if ((q->array() >= low.array()).all() && (q->array() <= high.array()).all()) return;
    }
  }
  q->resize(low.size());
  for (Eigen::Index i = 0; i < low.size(); ++i) (*q)(i) = rng_.Uniform(low(i), high(i));
}

RrtTarget LayeredRrtSearch::Sample(int a) {
  const int b = 1 - a;
  RrtTarget target;
  const int first = 1;
  const int last = base_.num_layers() - 2;
  if (last < first || rng_.Uniform01() < options_.goal_bias) {
    target.layer = trees_[b].root_layer();
    target.q_rad = trees_[b].node(0).q_rad;
    target.tree = b;
    target.node = 0;
    return target;
  }
  target.layer = static_cast<int>(rng_.UniformInt(first, last));
  const Eigen::VectorXd& stow = validity_.model().stow_q_rad;
  if (stow.size() > 0 && rng_.Uniform01() < options_.stow_bias) {
    const std::size_t layer = static_cast<std::size_t>(target.layer);
    target.q_rad = stow.cwiseMax(box_low_[layer]).cwiseMin(box_high_[layer]);
    return target;
  }
  SampleQ(target.layer, &target.q_rad);
  return target;
}

std::optional<Eigen::VectorXd> LayeredRrtSearch::Steer(int tree, int from, const RrtTarget& target,
                                                       bool* reached) const {
  const LayeredArmTree::Node& node = trees_[tree].node(from);
  const int gap = (target.layer - node.layer) * trees_[tree].direction();
  *reached = false;
  if (gap < 1) return std::nullopt;
  const int next_layer = node.layer + trees_[tree].direction();
  const double step_time =
      base_.layers[static_cast<std::size_t>(std::max(next_layer, node.layer))].step_time_s;
  Eigen::VectorXd step = (target.q_rad - node.q_rad) / gap;
  // Uniform scaling keeps the direction: max_i |dq_i| / (qd_max_i dt) <= 1.
  const double ratio = (step.cwiseAbs().array() / (qd_max_.array() * step_time)).maxCoeff();
  const bool clipped = !(ratio <= 1.0);
  if (clipped) {
    if (!std::isfinite(ratio)) return std::nullopt;  // dt = 0 and a non-zero step
    step /= ratio;
  }
  *reached = gap == 1 && !clipped;
  if (*reached) return target.q_rad;
  // A state on the other tree's root layer is useful only if it is that root.
  if (next_layer == trees_[1 - tree].root_layer()) return std::nullopt;
  return Eigen::VectorXd(node.q_rad + step);
}

bool LayeredRrtSearch::EdgeValid(int layer_a, const Eigen::VectorXd& q_a, int layer_b,
                                 const Eigen::VectorXd& q_b) {
  const Se2Layer& la = base_.layers[static_cast<std::size_t>(layer_a)];
  const Se2Layer& lb = base_.layers[static_cast<std::size_t>(layer_b)];
  edge_a_.x_m = la.x_m;
  edge_a_.y_m = la.y_m;
  edge_a_.yaw_rad = la.yaw_rad;
  edge_a_.q_rad = q_a;
  edge_b_.x_m = lb.x_m;
  edge_b_.y_m = lb.y_m;
  edge_b_.yaw_rad = lb.yaw_rad;
  edge_b_.q_rad = q_b;
  return validity_.CheckEdge(edge_a_, edge_b_, &workspace_, /*check_base=*/false) ==
         ValidityFailure::kNone;
}

/// Joint speed feasibility of the edge from node `from` to q on the next layer.
bool LayeredRrtSearch::EdgeFeasible(int tree, int from, const Eigen::VectorXd& q_to) {
  const LayeredArmTree::Node& node = trees_[tree].node(from);
  const int next_layer = node.layer + trees_[tree].direction();
  const double step_time =
      base_.layers[static_cast<std::size_t>(std::max(next_layer, node.layer))].step_time_s;
  const double tolerance = 1e-9;
  return ((q_to - node.q_rad).cwiseAbs().array() <=
          qd_max_.array() * step_time * (1.0 + tolerance) + tolerance)
      .all();
}

int LayeredRrtSearch::Link(int tree, int nearest, const Eigen::VectorXd& q) {
  // ChooseParent: cheapest cost-to-root through a neighbour on the layer behind, lazily
  // checked in order of that cost. `nearest` is known valid and feasible.
  LayeredArmTree& t = trees_[tree];
  const int behind = t.node(nearest).layer;
  t.Near(behind, q, options_.rewire_radius_rad, options_.max_neighbours, &near_);
  std::vector<std::pair<double, int>> candidates;
  candidates.reserve(near_.size() + 1);
  candidates.emplace_back(t.node(nearest).cost + t.Distance(t.node(nearest).q_rad, q), nearest);
  for (const auto& [distance, id] : near_) {
    if (id != nearest) candidates.emplace_back(t.node(id).cost + distance, id);
  }
  std::sort(candidates.begin(), candidates.end());
  const int layer = behind + t.direction();
  for (const auto& [cost, id] : candidates) {
    if (id == nearest) return t.Add(id, q);
    if (Interrupted()) break;
    if (EdgeFeasible(tree, id, q) && EdgeValid(t.node(id).layer, t.node(id).q_rad, layer, q)) {
      return t.Add(id, q);
    }
  }
  return t.Add(nearest, q);
}

void LayeredRrtSearch::Rewire(int tree, int id) {
  LayeredArmTree& t = trees_[tree];
  const int ahead = t.node(id).layer + t.direction();
  if (ahead < 0 || ahead >= base_.num_layers()) return;
  t.Near(ahead, t.node(id).q_rad, options_.rewire_radius_rad, options_.max_neighbours, &near_);
  const std::vector<std::pair<double, int>> neighbours = near_;
  bool changed = false;
  for (const auto& [distance, other] : neighbours) {
    if (Interrupted()) break;
    if (t.node(id).cost + distance >= t.node(other).cost - 1e-12) continue;
    if (!EdgeFeasible(tree, id, t.node(other).q_rad)) continue;
    if (!EdgeValid(t.node(id).layer, t.node(id).q_rad, ahead, t.node(other).q_rad)) continue;
    t.Reparent(other, id);
    changed = true;
  }
  if (changed) RefreshBestCost();
}

double LayeredRrtSearch::BridgeCost(const RrtBridge& bridge) const {
  const LayeredArmTree::Node& s = trees_[0].node(bridge.start_node);
  const LayeredArmTree::Node& g = trees_[1].node(bridge.goal_node);
  return s.cost + trees_[0].Distance(s.q_rad, g.q_rad) + g.cost;
}

void LayeredRrtSearch::RefreshBestCost() {
  for (const RrtBridge& bridge : bridges_) c_max_ = std::min(c_max_, BridgeCost(bridge));
  stats_.final_cost = c_max_;
}

void LayeredRrtSearch::TryUpdateCost(int tree, int node_in_tree, int other_node) {
  // c = Cost(n_n) + Heu(n_n, n_s) + Cost(n_s), n_s a node of the other tree.
  RrtBridge bridge;
  bridge.start_node = tree == 0 ? node_in_tree : other_node;
  bridge.goal_node = tree == 0 ? other_node : node_in_tree;
  const double cost = BridgeCost(bridge);
  if (!(cost < c_max_)) return;
  bridges_.push_back(bridge);
  const bool first = !std::isfinite(c_max_);
  if (first) {
    stats_.time_to_first_solution_s = watch_.ElapsedS();
    stats_.first_cost = cost;
  }
  c_max_ = cost;
  stats_.final_cost = cost;
  ++stats_.num_solutions;
  if (first && options_.on_first_solution) options_.on_first_solution(cost);
}

int LayeredRrtSearch::ExtendOnce(int t, int from, const RrtTarget& target, bool* connected) {
  *connected = false;
  bool reached = false;
  const std::optional<Eigen::VectorXd> q = Steer(t, from, target, &reached);
  if (!q) return -1;
  const int from_layer = trees_[t].node(from).layer;
  const int layer = from_layer + trees_[t].direction();
  if (!EdgeValid(from_layer, trees_[t].node(from).q_rad, layer, *q)) return -1;
  if (reached && target.tree == 1 - t) {
    TryUpdateCost(t, from, target.node);
    *connected = true;
    return -1;
  }
  if (trees_[0].size() + trees_[1].size() >= options_.max_nodes) return -1;
  const int id = Link(t, from, *q);
  Rewire(t, id);
  return id;
}

void LayeredRrtSearch::TryConnect(int b, int from, const RrtTarget& target) {
  // Greedy RRT-Connect extension of tree b towards `target` (a node of the other tree).
  int current = from;
  while (current >= 0 && !Interrupted()) {
    bool connected = false;
    current = ExtendOnce(b, current, target, &connected);
    if (connected) return;
  }
}

void LayeredRrtSearch::Iterate() {
  if (trees_[a_].size() > trees_[1 - a_].size()) a_ = 1 - a_;  // TrySwap
  const int a = a_;
  const int b = 1 - a;
  const RrtTarget sample = Sample(a);
  const int nearest = trees_[a].Nearest(sample.layer, sample.q_rad);
  if (nearest < 0) return;
  bool connected = false;
  const int n_s = ExtendOnce(a, nearest, sample, &connected);
  if (n_s < 0) return;  // invalid, blocked, or landed on T_b (TryUpdateCost done)
  // Grow T_b towards the new node: Nearest, Steer, then TryConnect greedily.
  RrtTarget towards_new;
  towards_new.layer = trees_[a].node(n_s).layer;
  towards_new.q_rad = trees_[a].node(n_s).q_rad;
  towards_new.tree = a;
  towards_new.node = n_s;
  const int other_nearest = trees_[b].Nearest(towards_new.layer, towards_new.q_rad);
  if (other_nearest < 0) return;
  const int n_os = ExtendOnce(b, other_nearest, towards_new, &connected);
  if (n_os < 0) return;
  TryConnect(b, n_os, towards_new);
}

ArmRrtStarResult LayeredRrtSearch::Run() {
  stats_.cost_lower_bound = sampler_.min_cost();
  ArmRrtStarStatus status = ArmRrtStarStatus::kNoSolution;
  std::string message = "no connection within the budget";
  while (true) {
    if (stop_.stop_requested()) {
      stats_.cancelled = true;
      status = ArmRrtStarStatus::kCancelled;
      message = "cancelled";
      break;
    }
    if (Interrupted()) {
      message = "time budget exhausted without a connection";
      break;
    }
    if (options_.max_iterations > 0 && stats_.iterations >= options_.max_iterations) {
      message = "iteration cap reached without a connection";
      break;
    }
    if (std::isfinite(c_max_) && (options_.stop_at_first_solution ||
                                  c_max_ <= stats_.cost_lower_bound * (1.0 + 1e-9) + 1e-12)) {
      break;
    }
    ++stats_.iterations;
    Iterate();
  }
  if (stop_.stop_requested()) stats_.cancelled = true;
  return Finish(status, std::move(message));
}

ArmRrtStarResult LayeredRrtSearch::Finish(ArmRrtStarStatus no_solution_status,
                                          std::string message) {
  ArmRrtStarResult result;
  stats_.nodes_start_tree = trees_[0].size();
  stats_.nodes_goal_tree = trees_[1].size();
  stats_.elapsed_s = watch_.ElapsedS();
  if (bridges_.empty()) {
    result.status = no_solution_status;
    result.message = std::move(message);
    result.stats = stats_;
    return result;
  }
  // MergeTree: the cheapest bridge with the trees' current costs.
  const RrtBridge* best = &bridges_.front();
  for (const RrtBridge& bridge : bridges_) {
    if (BridgeCost(bridge) < BridgeCost(*best)) best = &bridge;
  }
  std::vector<int> start_ids, goal_ids;
  trees_[0].PathToRoot(best->start_node, &start_ids);
  trees_[1].PathToRoot(best->goal_node, &goal_ids);
  std::vector<Eigen::VectorXd> qs;
  for (int id : start_ids) qs.push_back(trees_[0].node(id).q_rad);
  for (auto it = goal_ids.rbegin(); it != goal_ids.rend(); ++it) {
    qs.push_back(trees_[1].node(*it).q_rad);
  }
  result.path.cost = 0.0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    result.path.states.push_back(base_.State(static_cast<int>(k), qs[k]));
    result.path.times_s.push_back(base_.layers[k].time_s);
    if (k > 0) result.path.cost += trees_[0].Distance(qs[k - 1], qs[k]);
  }
  stats_.final_cost = result.path.cost;
  result.status = ArmRrtStarStatus::kSuccess;
  result.stats = stats_;
  return result;
}

}  // namespace topay
