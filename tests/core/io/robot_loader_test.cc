#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/robot_loader.h"
#include "core/collision/scene_clearance.h"
#include "core/robot/kinematics.h"

namespace topay {
namespace {

const std::string kConfigDir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
const std::string kDataDir = std::string(TOPAY_SOURCE_DIR) + "/tests/data/robot/";

std::string ReadText(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// Replaces the one occurrence of `from` in `text` (fails the test if there is none).
std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "fixture text not found: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(RobotLoaderTest, LoadsTheTopayRobot) {
  const RobotModel model =
      LoadRobotModel(kConfigDir + "topay_mm.urdf", kConfigDir + "topay_mm.yaml");
  EXPECT_EQ(model.name, "topay_mm");
  ASSERT_EQ(model.num_joints(), 7);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(model.joint_names[i], "joint" + std::to_string(i + 1));
  EXPECT_EQ(model.links.front().name, "base_link");
  for (int l = 1; l < static_cast<int>(model.links.size()); ++l) {
    EXPECT_LT(model.links[l].parent, l) << model.links[l].name;
  }
  EXPECT_EQ(model.links[model.FindLink("chassis")].q_index, -1);
  EXPECT_EQ(model.links[model.FindLink("link3")].q_index, 2);
  // Facts sheet: position limits (from the URDF), velocity, acceleration (from the YAML).
  const Eigen::VectorXd q_max =
      (Eigen::VectorXd(7) << 3.1, 2.26, 3.1, 2.355, 3.1, 2.23, 6.28).finished();
  EXPECT_TRUE(model.joint_limits.q_max_rad.isApprox(q_max));
  EXPECT_TRUE(model.joint_limits.q_min_rad.isApprox(-q_max));
  EXPECT_TRUE(model.joint_limits.qd_max_radps.isApprox(Eigen::VectorXd::Constant(7, 2.35)));
  EXPECT_TRUE(model.joint_limits.qdd_max_radps2.isApprox(Eigen::VectorXd::Constant(7, 6.28)));
  EXPECT_EQ(model.base_cylinder.radius_m, 0.40);
  EXPECT_EQ(model.base_cylinder.height_m, 0.155);
  EXPECT_EQ(model.base_limits.omega_max_radps, 0.9);
  ASSERT_EQ(model.spheres.size(), 12u);
  EXPECT_EQ(model.spheres[11].radius_m, 0.08);
  EXPECT_EQ(model.end_effector_link, model.FindLink("link7"));
  EXPECT_TRUE(model.X_LE.translation().isApprox(Eigen::Vector3d(0, 0, 0.144)));
  EXPECT_FALSE(model.self_collision_pairs.empty());
  EXPECT_EQ(model.stow_q_rad.size(), 7);
}

// The stowed configuration is what config/robot/README.md says: self clearance >= 1 cm, clear of
// the chassis, no higher than the shoulder sphere's top and inside the base cylinder.
TEST(RobotLoaderTest, TopayStowConfigurationIsFoldedAndClear) {
  const RobotModel model =
      LoadRobotModel(kConfigDir + "topay_mm.urdf", kConfigDir + "topay_mm.yaml");
  const Kinematics kinematics(model);
  WholeBodyState state;
  state.q_rad = model.stow_q_rad;
  Scene empty;
  empty.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 2));
  const SceneClearance clearance = SceneClearanceChecker(kinematics, empty).Compute(state);
  EXPECT_GE(clearance.self_m, 0.01);
  EXPECT_GE(clearance.chassis_m, 0.0);
  KinematicsCache cache = kinematics.MakeCache();
  kinematics.Update(state, &cache);
  double top_m = 0.0, reach_m = 0.0;
  for (std::size_t s = 0; s < model.spheres.size(); ++s) {
    top_m = std::max(top_m, cache.p_WS[s].z() + model.spheres[s].radius_m);
    reach_m = std::max(reach_m, cache.p_WS[s].head<2>().norm() + model.spheres[s].radius_m);
  }
  EXPECT_LE(top_m, 0.4915 + 1e-9);
  EXPECT_LE(reach_m, 0.34);
  EXPECT_LT(reach_m, model.base_cylinder.radius_m);
}

TEST(RobotLoaderTest, LoadsASixJointArmWithoutCodeChanges) {
  const RobotModel model =
      LoadRobotModel(kDataDir + "six_joint_arm.urdf", kDataDir + "six_joint_arm.yaml");
  ASSERT_EQ(model.num_joints(), 6);
  EXPECT_EQ(model.links.front().name, "base_footprint");
  // The continuous j6 takes its range from the YAML.
  EXPECT_EQ(model.joint_limits.q_min_rad(5), -6.0);
  EXPECT_EQ(model.joint_limits.q_max_rad(5), 6.0);
  const Kinematics kinematics(model);
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(6);
  // At q = 0 (see the URDF's comment): E = tool0 + 0.05 m along the tool's x, pointing down.
  Eigen::Isometry3d X_WE = kinematics.EndEffectorPose(state);
  EXPECT_TRUE(X_WE.translation().isApprox(Eigen::Vector3d(0.1, 0.13, 1.30), 1e-12));
  EXPECT_TRUE(
      (X_WE.linear() * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
  // Turning j1 by 90 deg swings the arm's offset about the j1 axis (x = 0.1, y = 0).
  state.q_rad(0) = std::numbers::pi / 2;
  X_WE = kinematics.EndEffectorPose(state);
  EXPECT_TRUE(X_WE.translation().isApprox(Eigen::Vector3d(0.1 - 0.13, 0.0, 1.30), 1e-12));
}

// Expects ConfigError naming `file` and `field` in what().
template <typename Fn>
void ExpectConfigError(Fn load, const std::string& file, const std::string& field) {
  try {
    load();
    ADD_FAILURE() << "no ConfigError for " << file << ": " << field;
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
    EXPECT_EQ(e.file(), file);
  }
}

class RobotLoaderBadInputTest : public ::testing::Test {
 protected:
  void ExpectYamlError(const std::string& yaml, const std::string& field) {
    ExpectConfigError([&] { LoadRobotModelFromStrings(urdf_, "robot.urdf", yaml, "robot.yaml"); },
                      "robot.yaml", field);
  }
  void ExpectUrdfError(const std::string& urdf, const std::string& field) {
    ExpectConfigError([&] { LoadRobotModelFromStrings(urdf, "robot.urdf", yaml_, "robot.yaml"); },
                      "robot.urdf", field);
  }
  const std::string urdf_ = ReadText(kConfigDir + "topay_mm.urdf");
  const std::string yaml_ = ReadText(kConfigDir + "topay_mm.yaml");
};

TEST_F(RobotLoaderBadInputTest, FixturesLoad) {
  EXPECT_EQ(LoadRobotModelFromStrings(urdf_, "robot.urdf", yaml_, "robot.yaml").num_joints(), 7);
}

TEST_F(RobotLoaderBadInputTest, MissingUrdfFile) {
  const std::string missing = kDataDir + "no_such_robot.urdf";
  ExpectConfigError([&] { LoadRobotModel(missing, kConfigDir + "topay_mm.yaml"); }, missing,
                    "cannot open the robot URDF");
}

TEST_F(RobotLoaderBadInputTest, MissingYamlFile) {
  const std::string missing = kDataDir + "no_such_robot.yaml";
  ExpectConfigError([&] { LoadRobotModel(kConfigDir + "topay_mm.urdf", missing); }, missing,
                    "cannot open the robot YAML");
}

TEST_F(RobotLoaderBadInputTest, DirectoriesAndEndlessFilesAreErrors) {
  const std::string yaml = kConfigDir + "topay_mm.yaml";
  const std::string urdf = kConfigDir + "topay_mm.urdf";
  ExpectConfigError([&] { LoadRobotModel(kConfigDir, yaml); }, kConfigDir, "is a directory");
  ExpectConfigError([&] { LoadRobotModel(urdf, kConfigDir); }, kConfigDir, "is a directory");
  ExpectConfigError([&] { LoadRobotModel("/dev/zero", yaml); }, "/dev/zero", "NUL byte");
}

TEST_F(RobotLoaderBadInputTest, MalformedUrdfXml) {
  ExpectUrdfError(Replace(urdf_, "</robot>", "</robt>"), "robot");
}

TEST_F(RobotLoaderBadInputTest, UnsupportedJointType) {
  ExpectUrdfError(
      Replace(urdf_, R"(name="joint3" type="revolute")", R"(name="joint3" type="floating")"),
      "joint[joint3].type");
}

TEST_F(RobotLoaderBadInputTest, MalformedYaml) {
  ExpectYamlError(Replace(yaml_, "base_limits: {v_max", "base_limits: {{v_max"), "malformed YAML");
}

TEST_F(RobotLoaderBadInputTest, MissingField) {
  ExpectYamlError(Replace(yaml_, "{radius: 0.40, height: 0.155}", "{height: 0.155}"),
                  "base_cylinder.radius");
}

TEST_F(RobotLoaderBadInputTest, UnknownField) {
  ExpectYamlError(Replace(yaml_, "{radius: 0.40, height: 0.155}", "{radius: 0.40, hight: 0.155}"),
                  "base_cylinder.hight");
}

TEST_F(RobotLoaderBadInputTest, NegativeRadius) {
  ExpectYamlError(
      Replace(yaml_, "xyz: [0, 0, 0.0725], radius: 0.04", "xyz: [0, 0, 0.0725], radius: -0.04"),
      "spheres[3].radius");
}

TEST_F(RobotLoaderBadInputTest, SphereOnUnknownLink) {
  ExpectYamlError(
      Replace(yaml_, "{link: link3, xyz: [0, 0, 0.0725]", "{link: link33, xyz: [0, 0, 0.0725]"),
      "spheres[3].link");
}

TEST_F(RobotLoaderBadInputTest, VelocityListLengthDiffersFromJointCount) {
  ExpectYamlError(Replace(yaml_, "velocity: [2.35, 2.35, 2.35, 2.35, 2.35, 2.35, 2.35]",
                          "velocity: [2.35, 2.35, 2.35, 2.35, 2.35, 2.35]"),
                  "joint_limits.velocity");
}

TEST_F(RobotLoaderBadInputTest, NaNValue) {
  ExpectYamlError(Replace(yaml_, "a_max: 0.8", "a_max: .nan"), "base_limits.a_max");
}

TEST_F(RobotLoaderBadInputTest, NaNInUrdf) {
  // urdfdom itself rejects a non-number; its reason names the value.
  ExpectUrdfError(Replace(urdf_, R"(xyz="0 0.115 0.171")", R"(xyz="0 nan 0.171")"), "robot");
  ExpectUrdfError(Replace(urdf_, R"(xyz="0 0.115 0.171")", R"(xyz="0 nan 0.171")"), "nan");
}

TEST_F(RobotLoaderBadInputTest, UnknownEndEffectorLink) {
  ExpectYamlError(Replace(yaml_, "end_effector: {link: link7", "end_effector: {link: flange"),
                  "end_effector.link");
}

TEST_F(RobotLoaderBadInputTest, BaseLinkIsNotTheUrdfRoot) {
  ExpectYamlError(Replace(yaml_, "base_link: base_link", "base_link: chassis"), "base_link");
}

TEST_F(RobotLoaderBadInputTest, ContinuousJointWithoutPositionLimits) {
  const std::string urdf =
      Replace(urdf_, R"(name="joint7" type="revolute")", R"(name="joint7" type="continuous")");
  ExpectConfigError([&] { LoadRobotModelFromStrings(urdf, "robot.urdf", yaml_, "robot.yaml"); },
                    "robot.yaml", "joint_limits.position_lower");
}

TEST_F(RobotLoaderBadInputTest, StowConfigurationWithTheWrongJointCount) {
  ExpectYamlError(Replace(yaml_, "stow_q: [2.899, ", "stow_q: ["), "stow_q");
}

TEST_F(RobotLoaderBadInputTest, StowConfigurationOutsideTheJointLimits) {
  ExpectYamlError(Replace(yaml_, "stow_q: [2.899, ", "stow_q: [3.2, "), "stow_q[0]");
}

}  // namespace
}  // namespace topay
