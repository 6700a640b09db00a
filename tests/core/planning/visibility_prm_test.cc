#include "core/planning/visibility_prm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stop_token>

#include "tests/core/planning/topo_test_scenes.h"

namespace topay {
namespace {

using namespace topo_test;

VisibilityPrmOptions SampleBudgetOnly(std::uint64_t seed, int samples = 2000) {
  VisibilityPrmOptions options;
  options.max_time_s = 0.0;  // deterministic: the sample budget binds
  options.max_samples = samples;
  options.seed = seed;
  return options;
}

class VisibilityPrmTest : public ::testing::Test {
 protected:
  VisibilityPrmTest()
      : scene_(Room({Pillar(0, 1.5), Pillar(0, -1.5), Pillar(-3, 3)})),
        field_(BaseField(scene_)),
        space_(field_, kRequired) {}
  Scene scene_;
  SignedDistanceField2 field_;
  BaseFreeSpace space_;
  const Eigen::Vector2d start_{-5, 0};
  const Eigen::Vector2d goal_{5, 0};
};

TEST_F(VisibilityPrmTest, GuardAndConnectorRulesHold) {
  const VisibilityPrmGraph graph = BuildVisibilityPrm(space_, start_, goal_, SampleBudgetOnly(3));
  ASSERT_GE(graph.nodes.size(), 2u);
  EXPECT_EQ(graph.nodes[0].p_W_m, start_);
  EXPECT_EQ(graph.nodes[1].p_W_m, goal_);
  EXPECT_EQ(graph.num_samples, 2000);
  EXPECT_FALSE(graph.time_limit_hit);
  EXPECT_EQ(graph.num_guards + graph.num_connectors, static_cast<int>(graph.nodes.size()));
  EXPECT_GE(graph.num_connectors,
            3);  // at least one per gap around the two pillars
  std::vector<int> guards;
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const PrmNode& node = graph.nodes[i];
    EXPECT_TRUE(space_.IsFree(node.p_W_m));
    if (node.kind == PrmNode::Kind::kGuard) {
      guards.push_back(static_cast<int>(i));
      continue;
    }
    // A connector joins exactly two guards it sees.
    ASSERT_EQ(node.neighbors.size(), 2u) << i;
    for (int g : node.neighbors) {
      EXPECT_EQ(graph.nodes[g].kind, PrmNode::Kind::kGuard);
      EXPECT_TRUE(space_.IsSegmentFree(node.p_W_m, graph.nodes[g].p_W_m));
    }
  }
  // Guards added by sampling see no earlier guard (start and goal are given).
  for (std::size_t a = 0; a < guards.size(); ++a) {
    for (std::size_t b = std::max<std::size_t>(a + 1, 2); b < guards.size(); ++b) {
      EXPECT_FALSE(
          space_.IsSegmentFree(graph.nodes[guards[a]].p_W_m, graph.nodes[guards[b]].p_W_m));
    }
  }
}

TEST_F(VisibilityPrmTest, SameSeedSameGraphOtherSeedOtherGraph) {
  const VisibilityPrmGraph a = BuildVisibilityPrm(space_, start_, goal_, SampleBudgetOnly(11));
  const VisibilityPrmGraph b = BuildVisibilityPrm(space_, start_, goal_, SampleBudgetOnly(11));
  const VisibilityPrmGraph c = BuildVisibilityPrm(space_, start_, goal_, SampleBudgetOnly(12));
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].p_W_m, b.nodes[i].p_W_m);
    EXPECT_EQ(a.nodes[i].neighbors, b.nodes[i].neighbors);
  }
  bool differs = a.nodes.size() != c.nodes.size();
  for (std::size_t i = 2; !differs && i < a.nodes.size(); ++i) {
    differs = a.nodes[i].p_W_m != c.nodes[i].p_W_m;
  }
  EXPECT_TRUE(differs);
}

TEST_F(VisibilityPrmTest, SamplesStayInTheAlignedBox) {
  // Diagonal start -> goal: box half-length |d|/2 + 1.5, half-width 4 about the
  // axis.
  const Eigen::Vector2d start(-4, -3), goal(4, 3);
  const VisibilityPrmGraph graph = BuildVisibilityPrm(space_, start, goal, SampleBudgetOnly(5));
  const Eigen::Vector2d u = (goal - start).normalized(), v(-u.y(), u.x());
  const Eigen::Vector2d centre = 0.5 * (start + goal);
  for (const PrmNode& node : graph.nodes) {
    EXPECT_LE(std::abs(u.dot(node.p_W_m - centre)), 5.0 + 1.5 + 1e-9);
    EXPECT_LE(std::abs(v.dot(node.p_W_m - centre)), 4.0 + 1e-9);
  }
}

TEST_F(VisibilityPrmTest, StopTokenAndTimeBudgetEndSampling) {
  std::stop_source source;
  source.request_stop();
  const VisibilityPrmGraph cancelled =
      BuildVisibilityPrm(space_, start_, goal_, SampleBudgetOnly(1), source.get_token());
  EXPECT_TRUE(cancelled.cancelled);
  EXPECT_EQ(cancelled.num_samples, 0);
  VisibilityPrmOptions timed = SampleBudgetOnly(1, 100'000'000);
  timed.max_time_s = 0.002;
  const VisibilityPrmGraph graph = BuildVisibilityPrm(space_, start_, goal_, timed);
  EXPECT_TRUE(graph.time_limit_hit);
  EXPECT_LT(graph.num_samples, 100'000'000);
}

TEST(PruneDeadEndsTest, RemovesChainsHangingOffTheGraph) {
  VisibilityPrmGraph graph;
  auto add = [&](double x, PrmNode::Kind kind) {
    PrmNode n;
    n.p_W_m = Eigen::Vector2d(x, 0);
    n.kind = kind;
    graph.nodes.push_back(n);
  };
  auto link = [&](int a, int b) {
    graph.nodes[a].neighbors.push_back(b);
    graph.nodes[b].neighbors.push_back(a);
  };
  add(0, PrmNode::Kind::kGuard);      // 0 start
  add(1, PrmNode::Kind::kGuard);      // 1 goal
  add(2, PrmNode::Kind::kConnector);  // 2 on a start-goal path
  add(3, PrmNode::Kind::kGuard);      // 3 dangling guard, hangs off 4
  add(4, PrmNode::Kind::kConnector);  // 4 joins 0 and 3 only: dead once 3 goes
  link(0, 2);
  link(2, 1);
  link(0, 4);
  link(4, 3);
  PruneDeadEnds(&graph);
  ASSERT_EQ(graph.nodes.size(), 3u);
  EXPECT_EQ(graph.nodes[2].p_W_m.x(), 2.0);
  EXPECT_EQ(graph.nodes[0].neighbors, std::vector<int>{2});
  EXPECT_EQ(graph.num_guards, 2);
  EXPECT_EQ(graph.num_connectors, 1);
}

}  // namespace
}  // namespace topay
