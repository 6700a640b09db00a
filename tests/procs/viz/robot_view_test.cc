// The robot as the viewer draws it (procs/viz/robot_view.h): the shipped URDF's visuals, link
// poses equal to the core's forward kinematics, collision bodies placed by name, bad URDFs.

#include "procs/viz/robot_view.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "viz_test_support.h"

namespace topay::viz {
namespace {

TEST(RobotView, DescribesTheShippedRobotsVisuals) {
  const RobotView robot = test::ShippedRobot();
  const nlohmann::json d = robot.Description();
  EXPECT_EQ(d["name"], "topay_mm");
  EXPECT_EQ(d["joint_names"].size(), 7u);
  ASSERT_EQ(d["links"].size(), robot.model().links.size());
  int boxes = 0, cylinders = 0, spheres = 0;
  for (const auto& link : d["links"]) {
    for (const auto& v : link["visuals"]) {
      const std::string shape = v["shape"];
      boxes += shape == "box";
      cylinders += shape == "cylinder";
      spheres += shape == "sphere";
      for (double s : v["size_m"]) EXPECT_GT(s, 0.0);
    }
    if (link["name"] == "chassis") {  // <box size="0.685 0.57 0.155"/> at z 0.0775
      ASSERT_EQ(link["visuals"].size(), 1u);
      EXPECT_EQ(link["visuals"][0]["shape"], "box");
      EXPECT_DOUBLE_EQ(link["visuals"][0]["size_m"][0], 0.685);
      EXPECT_DOUBLE_EQ(link["visuals"][0]["p_LV_m"][2], 0.0775);
    }
  }
  // config/robot/topay_mm.urdf's <visual> primitives (its collisions are not drawn).
  EXPECT_EQ(boxes, 1);
  EXPECT_EQ(cylinders, 5);
  EXPECT_EQ(spheres, 3);
}

TEST(RobotView, PlacesEveryLinkByTheCoreKinematics) {
  const RobotView robot = test::ShippedRobot();
  WholeBodyState state;
  state.x_m = 1.0;
  state.y_m = -2.0;
  state.yaw_rad = 0.7;
  state.q_rad = Eigen::VectorXd::LinSpaced(7, -0.5, 0.9);
  const nlohmann::json s = robot.State(12.5, state, 0.3, -0.1, std::nan(""));
  KinematicsCache cache = robot.kinematics().MakeCache();
  robot.kinematics().Update(state, &cache);
  ASSERT_EQ(s["links"].size(), cache.X_WL.size());
  for (std::size_t i = 0; i < cache.X_WL.size(); ++i) {
    const Eigen::Vector3d p = cache.X_WL[i].translation();
    const Eigen::Quaterniond q(cache.X_WL[i].linear());
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s["links"][i]["p_WL_m"][k].get<double>(), p[k], 1e-12);
    const Eigen::Quaterniond got(s["links"][i]["quat_WL"][0], s["links"][i]["quat_WL"][1],
                                 s["links"][i]["quat_WL"][2], s["links"][i]["quat_WL"][3]);
    EXPECT_NEAR(got.angularDistance(q), 0.0, 1e-9);
  }
  EXPECT_NEAR(s["p_WE_m"][0].get<double>(), cache.X_WE.translation().x(), 1e-12);
  EXPECT_TRUE(s["gripper"].is_null());
  EXPECT_EQ(s["q_rad"].size(), 7u);
  EXPECT_DOUBLE_EQ(s["t"], 12.5);
}

TEST(RobotView, PlacesTheMonitorsBodiesByName) {
  const RobotView robot = test::ShippedRobot();
  WholeBodyState state;
  state.x_m = 2.0;
  state.q_rad = Eigen::VectorXd::Zero(7);
  Eigen::Vector3d p;
  double r = 0.0;
  ASSERT_TRUE(robot.BodyPlace("base", state, &p, &r));
  EXPECT_DOUBLE_EQ(p.x(), 2.0);
  EXPECT_DOUBLE_EQ(r, robot.model().base_cylinder.radius_m);
  KinematicsCache cache = robot.kinematics().MakeCache();
  robot.kinematics().Update(state, &cache);
  for (const std::string name : {"sphere 3 (link link2)", "self: sphere 3 - sphere 9", "chassis: sphere 3 (link x)"}) {
    ASSERT_TRUE(robot.BodyPlace(name, state, &p, &r)) << name;
    EXPECT_TRUE(p.isApprox(cache.p_WS[3])) << name;
    EXPECT_DOUBLE_EQ(r, robot.model().spheres[3].radius_m);
  }
  EXPECT_FALSE(robot.BodyPlace("sphere 999 (link x)", state, &p, &r));
  EXPECT_FALSE(robot.BodyPlace("wheel", state, &p, &r));
}

TEST(RobotView, RejectsAVisualOfNoSizeNamingTheLink) {
  const RobotView robot = test::ShippedRobot();
  const std::string urdf = R"(<robot name="r"><link name="base_link"><visual><geometry>
      <box size="0 1 1"/></geometry></visual></link></robot>)";
  try {
    ParseLinkVisuals(robot.model(), urdf, "bad.urdf");
    FAIL() << "accepted a box of size 0";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("base_link"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.urdf"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ParseLinkVisuals(robot.model(), "<robot", "broken.urdf"), ConfigError);
}

}  // namespace
}  // namespace topay::viz
