// The kinematic robot model (procs/kinematic_sim/kinematic_model.h): unicycle integration under
// zero-order hold, determinism, refusal of bad commands, and its YAML options.

#include "procs/kinematic_sim/kinematic_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include <yaml-cpp/exceptions.h>

#include "graph_test_support.h"
#include "procs/command_pattern/command_pattern.h"

namespace topay::kinsim {
namespace {

control_command_t Command(std::int64_t utime, double v, double omega) {
  control_command_t cmd;
  cmd.utime = utime;
  cmd.trajectory_id = 1;
  cmd.v_mps = v;
  cmd.omega_radps = omega;
  cmd.num_joints = 7;
  cmd.qdot_radps.assign(7, 0.1);
  cmd.gripper = 0.0;
  return cmd;
}

TEST(KinematicModel, DrivesStraightThenAlongAnArc) {
  KinematicModel model({});
  EXPECT_TRUE(model.Apply(Command(1'000'000, 1.0, 0.0)));
  EXPECT_EQ(model.state().state.x_m, 0.0);  // nothing before the first command
  EXPECT_TRUE(model.Apply(Command(1'050'000, 1.0, M_PI)));  // 0.05 s at 1 m/s
  EXPECT_NEAR(model.state().state.x_m, 0.05, 1e-12);
  EXPECT_NEAR(model.state().state.q_rad(0), 0.005, 1e-12);
  // Half a turn at omega = pi rad/s takes 1 s, in steps of at most max_step_s = 0.1 s.
  for (int i = 1; i <= 10; ++i) model.Apply(Command(1'050'000 + i * 100'000, 1.0, M_PI));
  EXPECT_NEAR(std::abs(model.state().state.yaw_rad), M_PI, 1e-9);
  EXPECT_NEAR(model.state().state.x_m, 0.05, 1e-9);
  EXPECT_NEAR(model.state().state.y_m, 2.0 / M_PI, 1e-9);  // diameter of the half circle
  EXPECT_EQ(model.state().utime, 2'050'000);
  EXPECT_EQ(model.commands_applied(), 12);
}

TEST(KinematicModel, ClampsLongGapsToMaxStep) {
  KinematicModel model({});
  model.Apply(Command(0, 1.0, 0.0));
  model.Apply(Command(10'000'000, 0.0, 0.0));  // 10 s later
  EXPECT_NEAR(model.state().state.x_m, 0.1, 1e-12);
}

TEST(KinematicModel, SameCommandsGiveTheSameStates) {
  pattern::CommandPatternOptions pattern;
  pattern.seed = 11;
  KinematicModel a({}), b({});
  for (int i = 0; i < 50; ++i) {
    const control_command_t cmd = pattern::PatternCommand(pattern, i, 1'000'000 + 25'000 * i);
    a.Apply(cmd);
    b.Apply(cmd);
  }
  EXPECT_EQ(a.state().state.x_m, b.state().state.x_m);
  EXPECT_EQ(a.state().state.q_rad, b.state().state.q_rad);
  EXPECT_NE(a.state().state.x_m, 0.0);
}

TEST(KinematicModel, RefusesWrongJointCountsAndNonFiniteCommands) {
  KinematicModel model({});
  control_command_t cmd = Command(1, 1.0, 0.0);
  cmd.num_joints = 6;
  cmd.qdot_radps.resize(6);
  EXPECT_FALSE(model.Apply(cmd));
  cmd = Command(1, NAN, 0.0);
  EXPECT_FALSE(model.Apply(cmd));
  EXPECT_EQ(model.commands_applied(), 0);
}

// Found by tests/fuzz/sim_inputs_fuzz.cc (regressions/sim_inputs/, sixteenth session): finite
// but absurd rates (1e308) integrated to an infinite state. They are refused; the state stays
// finite and where the last plausible command left it.
TEST(KinematicModel, RefusesRatesNoRobotHas) {
  KinematicModel model({});
  ASSERT_TRUE(model.Apply(Command(1'000'000, 1.0, 0.5)));
  EXPECT_FALSE(model.Apply(Command(1'100'000, 1e308, 0.0)));
  EXPECT_FALSE(model.Apply(Command(1'100'000, 0.0, -2e3)));
  control_command_t joints = Command(1'100'000, 0.0, 0.0);
  joints.qdot_radps[3] = 1e300;
  EXPECT_FALSE(model.Apply(joints));
  ASSERT_TRUE(model.Apply(Command(1'200'000, KinematicModel::kMaxRate, KinematicModel::kMaxRate)));
  for (int k = 3; k < 100; ++k) ASSERT_TRUE(model.Apply(Command(k * 100'000, KinematicModel::kMaxRate, 0.0)));
  const WholeBodyState& s = model.state().state;
  EXPECT_TRUE(std::isfinite(s.x_m) && std::isfinite(s.y_m) && std::isfinite(s.yaw_rad) && s.q_rad.allFinite());
  EXPECT_EQ(model.commands_applied(), 99);
}

TEST(KinematicModelOptions, LoadsTheShippedConfigAndNamesBadKeys) {
  const KinematicModelOptions o =
      LoadKinematicModelOptions(std::string(TOPAY_SOURCE_DIR) + "/config/sim/kinematic_sim.yaml");
  EXPECT_EQ(o.q_rad.size(), 7u);
  EXPECT_EQ(o.joint_names.size(), 7u);
  EXPECT_EQ(o.state_rate_hz, 10.0);
  const std::string path = test::TestDir("kinematic_model") + "/bad.yaml";
  test::WriteText(path, "x_m: 1\nspeed: 2\n");
  try {
    LoadKinematicModelOptions(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": unknown key 'speed'"), std::string::npos) << e.what();
  }
  test::WriteText(path, "joint_names: [a]\n");
  EXPECT_THROW(LoadKinematicModelOptions(path), std::runtime_error);
}

TEST(KinematicModelOptions, AKeyThatIsNotANameIsNamedWithTheFile) {
  // `[k]: 1` used to escape as yaml-cpp's bad conversion, without the file's name (config_yaml
  // fuzz target, tests/fuzz/regressions/config_yaml/kinematic_key_not_a_name).
  const std::string path = test::TestDir("kinematic_model") + "/key.yaml";
  test::WriteText(path, "x_m: 1\n[k]: 1\n");
  try {
    LoadKinematicModelOptions(path);
    FAIL() << "accepted a list as a key";
  } catch (const YAML::Exception& e) {
    FAIL() << "yaml-cpp's exception passed through: " << e.what();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":2: a key must be a name"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::kinsim
