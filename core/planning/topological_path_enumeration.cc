#include "core/planning/topological_path_enumeration.h"

#include <algorithm>
#include <numeric>

namespace topay {
namespace {

// Iterative DFS over simple paths from node 0 to node 1.
class SimplePathDfs {
 public:
  SimplePathDfs(const VisibilityPrmGraph& graph, const RawPathEnumerationOptions& options,
                std::stop_token stop, RawPathEnumeration* out)
      : graph_(graph),
        options_(options),
        stop_(std::move(stop)),
        out_(out),
        on_path_(graph.nodes.size(), false) {}

  std::vector<std::vector<int>> Run() {
    std::vector<std::vector<int>> found;
    if (graph_.nodes.size() < 2) return found;
    Push(0);
    std::int64_t expansions = 0;
    while (!stack_.empty()) {
      if (static_cast<int>(found.size()) >= options_.max_raw_paths) break;
      if (++expansions > options_.max_expansions) {
        out_->expansion_cap_hit = true;
        break;
      }
      if ((expansions & 1023) == 0 && stop_.stop_requested()) {
        out_->cancelled = true;
        break;
      }
      Frame& top = stack_.back();
      const std::vector<int>& neighbors = graph_.nodes[top.node].neighbors;
      if (top.next >= neighbors.size()) {
        Pop();
        continue;
      }
      const int next = neighbors[top.next++];
      if (on_path_[next]) continue;
      if (next == 1) {
        std::vector<int> path;
        for (const Frame& f : stack_) path.push_back(f.node);
        path.push_back(1);
        found.push_back(std::move(path));
        continue;
      }
      Push(next);
    }
    return found;
  }

 private:
  struct Frame {
    int node;
    std::size_t next;
  };
  void Push(int node) {
    stack_.push_back({node, 0});
    on_path_[node] = true;
  }
  void Pop() {
    on_path_[stack_.back().node] = false;
    stack_.pop_back();
  }

  const VisibilityPrmGraph& graph_;
  const RawPathEnumerationOptions& options_;
  std::stop_token stop_;
  RawPathEnumeration* out_;
  std::vector<bool> on_path_;
  std::vector<Frame> stack_;
};

}  // namespace

RawPathEnumeration EnumerateRawPaths(const VisibilityPrmGraph& graph,
                                     const RawPathEnumerationOptions& options,
                                     std::stop_token stop) {
  RawPathEnumeration out;
  std::vector<std::vector<int>> found = SimplePathDfs(graph, options, stop, &out).Run();
  out.num_found = static_cast<int>(found.size());
  std::vector<int> order(found.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return found[a].size() < found[b].size(); });
  const int keep = std::min<int>(options.keep_fewest_hops, static_cast<int>(order.size()));
  for (int k = 0; k < keep; ++k) {
    std::vector<Eigen::Vector2d> path;
    for (int node : found[order[k]]) path.push_back(graph.nodes[node].p_W_m);
    out.paths_W_m.push_back(std::move(path));
  }
  return out;
}

}  // namespace topay
