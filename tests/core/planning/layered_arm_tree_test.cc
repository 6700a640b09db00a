#include "core/planning/layered_arm_tree.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

Eigen::VectorXd Q(double a, double b) { return (Eigen::VectorXd(2) << a, b).finished(); }

TEST(LayeredArmTreeTest, AddsNodesOnTheNextLayerWithPathCosts) {
  const Eigen::VectorXd w = (Eigen::VectorXd(2) << 1.0, 4.0).finished();
  LayeredArmTree tree(5, 4, Q(0, 0), -1, w);  // grows from layer 4 downwards
  const int a = tree.Add(0, Q(3, 0));
  const int b = tree.Add(a, Q(3, 1));
  EXPECT_EQ(tree.node(a).layer, 3);
  EXPECT_EQ(tree.node(b).layer, 2);
  EXPECT_DOUBLE_EQ(tree.node(a).cost, 3.0);
  EXPECT_DOUBLE_EQ(tree.node(b).cost, 3.0 + 2.0);  // sqrt(4 * 1^2)
  EXPECT_EQ(tree.nodes_on_layer(3), std::vector<int>{a});
  std::vector<int> path;
  tree.PathToRoot(b, &path);
  EXPECT_EQ(path, (std::vector<int>{0, a, b}));
}

TEST(LayeredArmTreeTest, NearestLooksOnlyBehindTheLayer) {
  LayeredArmTree tree(6, 0, Q(0, 0), +1, Eigen::VectorXd::Ones(2));
  const int a = tree.Add(0, Q(1, 0));
  const int b = tree.Add(a, Q(5, 5));
  EXPECT_EQ(tree.Nearest(3, Q(5, 5)), b);  // b on layer 2 is behind layer 3
  EXPECT_EQ(tree.Nearest(2, Q(5, 5)), a);  // b's own layer is not behind
  EXPECT_EQ(tree.Nearest(0, Q(5, 5)), -1);
  std::vector<std::pair<double, int>> near;
  tree.Add(0, Q(0, 2));
  tree.Near(1, Q(0, 0), 1.5, 5, &near);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0].second, a);
  tree.Near(1, Q(0, 0), 3.0, 5, &near);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_LE(near[0].first, near[1].first);
}

TEST(LayeredArmTreeTest, ReparentUpdatesTheWholeSubtree) {
  LayeredArmTree tree(4, 0, Q(0, 0), +1, Eigen::VectorXd::Ones(2));
  const int far = tree.Add(0, Q(3, 4));   // cost 5
  const int near = tree.Add(0, Q(0, 1));  // cost 1
  const int child = tree.Add(far, Q(0, 2));
  const int grandchild = tree.Add(child, Q(0, 3));
  EXPECT_DOUBLE_EQ(tree.node(grandchild).cost, 5.0 + std::sqrt(13.0) + 1.0);
  // Move `child` under `near`: its cost becomes 1 + 1, the grandchild's 3.
  tree.Reparent(child, near);
  EXPECT_EQ(tree.node(child).parent, near);
  EXPECT_DOUBLE_EQ(tree.node(child).cost, 2.0);
  EXPECT_DOUBLE_EQ(tree.node(grandchild).cost, 3.0);
  EXPECT_TRUE(tree.node(far).children.empty());
}

}  // namespace
}  // namespace topay
