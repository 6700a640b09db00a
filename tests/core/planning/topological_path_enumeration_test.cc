#include "core/planning/topological_path_enumeration.h"

#include <gtest/gtest.h>

#include <stop_token>

namespace topay {
namespace {

// Start 0, goal 1; routes 0-2-1, 0-3-1, 0-4-5-1, and a cross link 2-5.
VisibilityPrmGraph DiamondGraph() {
  VisibilityPrmGraph graph;
  for (int i = 0; i < 6; ++i) {
    PrmNode n;
    n.p_W_m = Eigen::Vector2d(i, 0);
    graph.nodes.push_back(n);
  }
  auto link = [&](int a, int b) {
    graph.nodes[a].neighbors.push_back(b);
    graph.nodes[b].neighbors.push_back(a);
  };
  link(0, 4);
  link(4, 5);
  link(5, 1);
  link(0, 2);
  link(2, 1);
  link(0, 3);
  link(3, 1);
  link(2, 5);
  return graph;
}

std::vector<double> NodeIds(const std::vector<Eigen::Vector2d>& path) {
  std::vector<double> ids;
  for (const Eigen::Vector2d& p : path) ids.push_back(p.x());
  return ids;
}

TEST(EnumerateRawPathsTest, FindsAllSimplePathsFewestHopsFirst) {
  const RawPathEnumeration out = EnumerateRawPaths(DiamondGraph(), {});
  // Simple paths: 0-4-5-1, 0-4-5-2-1, 0-2-1, 0-2-5-1, 0-3-1.
  EXPECT_EQ(out.num_found, 5);
  ASSERT_EQ(out.paths_W_m.size(), 5u);
  for (std::size_t i = 1; i < out.paths_W_m.size(); ++i) {
    EXPECT_LE(out.paths_W_m[i - 1].size(), out.paths_W_m[i].size());
  }
  EXPECT_EQ(NodeIds(out.paths_W_m[0]), (std::vector<double>{0, 2, 1}));
  EXPECT_EQ(NodeIds(out.paths_W_m[1]), (std::vector<double>{0, 3, 1}));
  EXPECT_EQ(NodeIds(out.paths_W_m.back()), (std::vector<double>{0, 4, 5, 2, 1}));
  EXPECT_FALSE(out.expansion_cap_hit);
}

TEST(EnumerateRawPathsTest, CapsAndKeepCount) {
  RawPathEnumerationOptions options;
  options.max_raw_paths = 2;
  options.keep_fewest_hops = 1;
  const RawPathEnumeration out = EnumerateRawPaths(DiamondGraph(), options);
  EXPECT_EQ(out.num_found, 2);
  ASSERT_EQ(out.paths_W_m.size(), 1u);
  options.max_raw_paths = 300;
  options.max_expansions = 3;
  EXPECT_TRUE(EnumerateRawPaths(DiamondGraph(), options).expansion_cap_hit);
}

TEST(EnumerateRawPathsTest, DisconnectedGraphGivesNoPath) {
  VisibilityPrmGraph graph = DiamondGraph();
  for (PrmNode& n : graph.nodes) n.neighbors.clear();
  EXPECT_EQ(EnumerateRawPaths(graph, {}).num_found, 0);
  EXPECT_EQ(EnumerateRawPaths(VisibilityPrmGraph{}, {}).num_found, 0);
}

}  // namespace
}  // namespace topay
