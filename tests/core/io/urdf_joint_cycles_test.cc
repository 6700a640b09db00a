// CheckNoJointCycle (core/io/urdf_joint_cycles.h): cycles of joints found in the XML before
// urdfdom builds (and leaks) them; everything else is left to urdfdom.

#include "core/io/urdf_joint_cycles.h"

#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"

namespace topay {
namespace {

std::string Joint(const std::string& name, const std::string& parent, const std::string& child) {
  return "<joint name=\"" + name + "\" type=\"revolute\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/></joint>";
}

std::string Robot(const std::string& body) { return "<robot name=\"r\">" + body + "</robot>"; }

TEST(UrdfJointCycles, ATreeAndTextThatIsNoUrdfPass) {
  EXPECT_NO_THROW(CheckNoJointCycle(Robot(Joint("j1", "a", "b") + Joint("j2", "b", "c") + Joint("j3", "a", "d")), "t"));
  EXPECT_NO_THROW(CheckNoJointCycle("not xml <", "t"));
  EXPECT_NO_THROW(CheckNoJointCycle("<other/>", "t"));
  EXPECT_NO_THROW(CheckNoJointCycle(Robot("<joint name=\"j\"><parent/></joint>"), "t"));  // urdfdom's to reject
}

TEST(UrdfJointCycles, ACycleIsAnErrorNamingItsJoints) {
  try {
    CheckNoJointCycle(Robot(Joint("j0", "a", "d") + Joint("j1", "b", "c") + Joint("j2", "c", "b")), "r.urdf");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "r.urdf");
    EXPECT_EQ(e.field(), "joint[j2].child");
    EXPECT_NE(std::string(e.what()).find("'j1' -> 'j2'"), std::string::npos) << e.what();
  }
  // A second parent joint that closes a ring, and one that is its own link's parent (the
  // robot_model fuzz target's second leak: urdfdom then found two roots).
  EXPECT_THROW(CheckNoJointCycle(Robot(Joint("j1", "a", "b") + Joint("j2", "b", "c") + Joint("j3", "c", "b")), "t"),
               ConfigError);
  EXPECT_THROW(CheckNoJointCycle(Robot(Joint("j1", "a", "b") + Joint("j2", "b", "c") + Joint("j3", "c", "c")), "t"),
               ConfigError);
  EXPECT_THROW(CheckNoJointCycle(Robot(Joint("j1", "a", "a")), "r.urdf"), ConfigError);
}

// A chain of 5,000 joints is walked once (the links already cleared are not walked again).
TEST(UrdfJointCycles, ALongChainPasses) {
  std::string body;
  for (int i = 0; i < 5000; ++i) body += Joint("j" + std::to_string(i), "l" + std::to_string(i), "l" + std::to_string(i + 1));
  EXPECT_NO_THROW(CheckNoJointCycle(Robot(body), "t"));
}

}  // namespace
}  // namespace topay
