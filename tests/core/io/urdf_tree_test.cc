#include "core/io/urdf_tree.h"

#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay {
namespace {

std::string Links(std::initializer_list<const char*> names) {
  std::string text;
  for (const char* name : names) text += std::string("<link name=\"") + name + "\"/>";
  return text;
}

std::string Joint(const std::string& name, const std::string& parent, const std::string& child) {
  return "<joint name=\"" + name + "\" type=\"revolute\"><parent link=\"" + parent +
         "\"/><child link=\"" + child +
         "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
         "velocity=\"1\"/></joint>";
}

std::string Robot(const std::string& body) { return "<robot name=\"r\">" + body + "</robot>"; }

// The URDF must fail with a ConfigError naming the file, the field and every word in `words`.
void ExpectNotATree(const std::string& urdf, const std::string& field,
                    std::initializer_list<const char*> words) {
  try {
    ParseUrdfTree(urdf, "bad.urdf");
    ADD_FAILURE() << "no error for " << urdf;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "bad.urdf");
    EXPECT_EQ(e.field(), field) << e.what();
    for (const char* word : words) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << word << " in " << e.what();
    }
  }
}

TEST(UrdfTreeTest, AChainFlattensDepthFirst) {
  const UrdfTree tree = ParseUrdfTree(
      Robot(Links({"a", "b", "c", "d"}) + Joint("j1", "a", "b") + Joint("j2", "b", "c") +
            Joint("j3", "a", "d")),
      "ok.urdf");
  ASSERT_EQ(tree.links.size(), 4u);
  EXPECT_EQ(tree.links[0].name, "a");
  EXPECT_EQ(tree.links[0].parent, -1);
  for (std::size_t l = 1; l < tree.links.size(); ++l) {
    EXPECT_LT(tree.links[l].parent, static_cast<int>(l));
    EXPECT_GE(tree.links[l].parent, 0);
  }
  // Depth-first: b's subtree (b, c) before the sibling d.
  EXPECT_EQ(tree.links[1].name, "b");
  EXPECT_EQ(tree.links[2].name, "c");
  EXPECT_EQ(tree.links[2].parent, 1);
  EXPECT_EQ(tree.links[3].name, "d");
  EXPECT_EQ(tree.links[3].parent, 0);
  EXPECT_EQ(tree.joint_names.size(), 3u);
}

// A long chain is flattened without recursion (a deep recursion would overflow the stack).
TEST(UrdfTreeTest, ALongChainLoads) {
  constexpr int kLinks = 20000;
  std::string body = "<link name=\"l0\"/>";
  for (int i = 1; i < kLinks; ++i) {
    const std::string link = "l" + std::to_string(i);
    body += "<link name=\"" + link + "\"/>" +
            Joint("j" + std::to_string(i), "l" + std::to_string(i - 1), link);
  }
  const UrdfTree tree = ParseUrdfTree(Robot(body), "long.urdf");
  ASSERT_EQ(tree.links.size(), static_cast<std::size_t>(kLinks));
  EXPECT_EQ(tree.links.back().name, "l" + std::to_string(kLinks - 1));
  EXPECT_EQ(tree.links.back().parent, kLinks - 2);
}

// The crash: c has two parents (a and b).
TEST(UrdfTreeTest, ALinkWithTwoParentsIsAnError) {
  ExpectNotATree(Robot(Links({"a", "b", "c"}) + Joint("j1", "a", "b") + Joint("j2", "a", "c") +
                       Joint("j3", "b", "c")),
                 "joint[j3].child", {"'c'", "'j2'", "tree"});
  // Two joints between the same pair of links.
  ExpectNotATree(Robot(Links({"a", "b"}) + Joint("j1", "a", "b") + Joint("j2", "a", "b")),
                 "joint[j2].child", {"'b'", "'j1'"});
}

TEST(UrdfTreeTest, ACycleIsAnError) {
  // b -> c -> b beside the root a: b has the parents a and c. Cycles are found in the XML,
  // before urdfdom builds a tree it would not free (core/io/urdf_joint_cycles.h).
  ExpectNotATree(Robot(Links({"a", "b", "c"}) + Joint("j1", "a", "b") + Joint("j2", "b", "c") +
                       Joint("j3", "c", "b")),
                 "joint[j3].child", {"'j2' -> 'j3'", "cycle"});
  // A cycle that hangs off nothing: a is the only root, b and c form a loop of their own.
  ExpectNotATree(Robot(Links({"a", "b", "c", "d"}) + Joint("j1", "a", "d") +
                       Joint("j2", "b", "c") + Joint("j3", "c", "b")),
                 "joint[j3].child", {"'j2' -> 'j3'", "cycle"});
  // A cycle through every link (no root at all).
  ExpectNotATree(Robot(Links({"a", "b"}) + Joint("j1", "a", "b") + Joint("j2", "b", "a")),
                 "joint[j2].child", {"'j1' -> 'j2'", "cycle"});
  // A joint whose parent is its child.
  ExpectNotATree(Robot(Links({"a", "b"}) + Joint("j1", "a", "b") + Joint("j2", "b", "b")),
                 "joint[j2].child", {"'j2'", "cycle"});
  // The same as the only parent of b (the robot_model fuzz target's leak): a two-link cycle of
  // its own, and two roots beside a cycle (urdfdom's "two roots" after building it).
  ExpectNotATree(Robot(Links({"a", "b", "c"}) + Joint("j1", "a", "c") + Joint("j2", "b", "b")),
                 "joint[j2].child", {"'j2'", "cycle"});
  ExpectNotATree(Robot(Links({"a", "b", "c", "d", "e"}) + Joint("j1", "a", "e") + Joint("j2", "c", "d") +
                       Joint("j3", "d", "c")),
                 "joint[j3].child", {"'j2' -> 'j3'", "cycle"});
}

TEST(UrdfTreeTest, SeveralRootsMissingLinksAndDuplicatesAreErrors) {
  ExpectNotATree(Robot(Links({"a", "b", "c"}) + Joint("j1", "a", "b")), "robot",
                 {"root", "[a]", "[c]"});
  ExpectNotATree(Robot(Links({"a", "b"}) + Joint("j1", "a", "b") + Joint("j2", "b", "ghost")),
                 "robot", {"ghost", "j2"});
  ExpectNotATree(Robot(Links({"a", "b", "b"}) + Joint("j1", "a", "b")), "robot",
                 {"'b'", "unique"});
  ExpectNotATree(Robot(Links({"a", "b", "c"}) + Joint("j1", "a", "b") + Joint("j1", "b", "c")),
                 "robot", {"'j1'", "unique"});
}

// urdfdom's XML parser recurses per element: a deep document (7 MB, under the file size
// limit) would overflow the stack; it is rejected before parsing.
TEST(UrdfTreeTest, DeeplyNestedXmlIsAnError) {
  constexpr int kDepth = 1000000;
  std::string text = "<robot name=\"r\">";
  for (int i = 0; i < kDepth; ++i) text += "<a>";
  for (int i = 0; i < kDepth; ++i) text += "</a>";
  ExpectNotATree(text + "</robot>", "robot", {"nest deeper than 100"});
  // Comments, self-closing elements and quoted '>' do not count as nesting.
  const UrdfTree tree = ParseUrdfTree(
      Robot("<!-- <a><a><a> -->" + Links({"a", "b"}) + "<link name=\"c>\"/>" +
            Joint("j1", "a", "b") + Joint("j2", "a", "c>")),
      "ok.urdf");
  EXPECT_EQ(tree.links.size(), 3u);
}

TEST(UrdfTreeTest, AJointAxisIsAUnitVectorWhateverItsScale) {
  // The norm of an axis with entries near 1e308 overflowed: the joint got the zero vector as
  // its axis (found by the robot_model fuzz target, tests/fuzz/regressions/robot_model/
  // axis_norm_overflow).
  const auto axis_of = [](const std::string& xyz) {
    const UrdfTree tree = ParseUrdfTree(
        Robot(Links({"a", "b"}) + "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
              "<axis xyz=\"" + xyz + "\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"),
        "ok.urdf");
    return tree.links.at(1).axis_J;
  };
  EXPECT_NEAR((axis_of("1e308 0 0") - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((axis_of("0 -1.5e308 1.5e308") - Eigen::Vector3d(0, -1, 1).normalized()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((axis_of("0 0 2") - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  ExpectNotATree(Robot(Links({"a", "b"}) + "<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/>"
                       "<child link=\"b\"/><axis xyz=\"1e-300 0 0\"/></joint>"),
                 "joint[j].axis", {"finite non-zero"});
}

}  // namespace
}  // namespace topay
