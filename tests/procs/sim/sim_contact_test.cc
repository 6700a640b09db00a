// The core with the real collision monitor (procs/sim/monitor_adapter.h): a straight drive into
// a box is reported once, at the first plant step the base cylinder enters it, with the box's
// stable id and a depth of at most one step's travel; a clear drive reports none; the ideal
// follower (--follow) driving the base into a box is judged at every step too.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "follow_test_trajectory.h"
#include "procs/sim/sim_messages.h"
#include "procs/sim/sim_setup.h"
#include "procs/sim/trajectory_follower.h"

namespace topay::simproc {
namespace {

struct Contacts : SimListener {
  std::vector<std::pair<ContactResult, int>> list;
  void OnContact(const ContactResult& c, int id) override { list.emplace_back(c, id); }
};

SimOptions Options(const std::string& scene_json) {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/procs/sim_contact";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/scene_" + std::to_string(std::hash<std::string>{}(scene_json)) + ".json";
  std::ofstream(path) << scene_json;
  SimOptions o;
  o.robot_urdf = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf";
  o.robot_yaml = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml";
  o.scene = path;
  o.lidar_enabled = false;
  return o;
}

// Drives at 0.5 m/s along x for `seconds`; returns the contacts.
Contacts Drive(SimAssembly* sim, double seconds) {
  Contacts contacts;
  sim->core->SetListener(&contacts);
  sim::ActuatorCommand forward;
  forward.v_mps = 0.5;
  forward.qdot_radps = Eigen::VectorXd::Zero(sim->model->num_joints());
  const int steps = static_cast<int>(seconds / 0.002);
  for (int k = 0; k < steps; ++k) {
    if (k % 10 == 0) sim->core->Command(forward);
    sim->core->Step();
  }
  return contacts;
}

TEST(SimContact, DriveIntoABoxIsReportedAtTheRightStepAndDepth) {
  // Box 0 far away, box 1 a wall whose near face is at x = 2.0 m, the stowed arm stays above
  // the chassis and behind the base's front.
  SimAssembly sim = AssembleSim(Options(R"({"boxes": [
      {"center": [0, 8, 0.5], "size": [1, 1, 1], "yaw": 0},
      {"center": [2.25, 0, 0.5], "size": [0.5, 3, 1], "yaw": 0}]})"));
  const double radius = sim.model->base_cylinder.radius_m;
  // The same plant alone: the first step at which the base's front passes x = 2.0.
  sim::Plant plant(*sim.model, sim::PlantOptions{}, 0);
  sim::ActuatorCommand forward;
  forward.v_mps = 0.5;
  forward.qdot_radps = Eigen::VectorXd::Zero(sim.model->num_joints());
  double expected_t = -1.0, expected_depth = 0.0;
  for (int k = 0; k < 5000 && expected_t < 0.0; ++k) {
    if (k % 10 == 0) plant.Command(forward);
    plant.Step();
    if (plant.state().state.x_m + radius > 2.0) {
      expected_t = plant.time_s();
      expected_depth = plant.state().state.x_m + radius - 2.0;
    }
  }
  ASSERT_GT(expected_t, 0.0);
  const Contacts contacts = Drive(&sim, expected_t + 1.0);
  ASSERT_FALSE(contacts.list.empty());
  const auto& [first, box_id] = contacts.list.front();
  EXPECT_EQ(first.body, "base");
  EXPECT_EQ(box_id, 1);
  EXPECT_NEAR(first.t_s, expected_t, 1e-9);
  EXPECT_NEAR(first.depth_m, expected_depth, 1e-6);
  EXPECT_LE(first.depth_m, 0.5 * 0.002 + 1e-9);
  int base_contacts = 0;
  for (const auto& c : contacts.list) base_contacts += c.first.body == "base";
  EXPECT_EQ(base_contacts, 1) << "one event while the base stays in the box";
  const ContactCounts counts = sim.core->contact_sensor()->counts();
  EXPECT_GT(counts.steps_in_contact, 400);
  EXPECT_GT(counts.max_depth_m, 0.2);
}

TEST(SimContact, ClearDriveReportsNone) {
  SimAssembly sim = AssembleSim(Options(R"({"boxes": [{"center": [2.25, 3, 0.5], "size": [0.5, 3, 1], "yaw": 0}]})"));
  const Contacts contacts = Drive(&sim, 8.0);
  EXPECT_TRUE(contacts.list.empty());
  EXPECT_EQ(sim.core->contact_sensor()->counts().events, 0);
  EXPECT_EQ(sim.core->contact_sensor()->counts().steps, 4000);
  EXPECT_GT(sim.core->plant().state().state.x_m, 3.5);  // it drove past the box
}

TEST(SimContact, FollowingATrajectoryIntoABoxIsReportedAtTheFirstStepInside) {
  SimAssembly sim = AssembleSim(Options(R"({"boxes": [{"center": [0.85, 0, 0.5], "size": [0.5, 3, 1], "yaw": 0}]})"));
  const double radius = sim.model->base_cylinder.radius_m;
  const double face_m = 0.6;
  const sim::PlantState start = sim.core->plant().state();
  const ArcYawTrajectory straight = test::FollowTestTrajectory({0.0, 0.0}, 0.0, start.state.q_rad, 0.0, 0.0);
  ASSERT_GT(1.0 + radius, face_m);
  constexpr std::int64_t kStartUtime = 1'800'000'000'000'000;
  TrajectoryFollower follower(sim.model->num_joints(), {});
  ASSERT_EQ(follower.Accept(test::FollowTestMessage(straight, {0.0, 0.0}, kStartUtime + 100'000, 1), kStartUtime, start),
            "");
  Contacts contacts;
  sim.core->SetListener(&contacts);
  double expected_t = -1.0;
  for (int k = 0; k < 1500; ++k) {  // 3 s: 0.1 s held, 2 s followed, then held at the end
    const std::int64_t utime = SimUtime(kStartUtime, sim.core->next_time_s());
    sim.core->StepTo(follower.StateAt(utime, sim.core->plant().state()));
    if (expected_t < 0.0 && sim.core->plant().state().state.x_m + radius > face_m) expected_t = sim.core->time_s();
  }
  ASSERT_GT(expected_t, 0.1);
  ASSERT_FALSE(contacts.list.empty());
  EXPECT_EQ(contacts.list.front().first.body, "base");
  EXPECT_EQ(contacts.list.front().second, 0);
  EXPECT_NEAR(contacts.list.front().first.t_s, expected_t, 1e-9);
  EXPECT_EQ(sim.core->contact_sensor()->counts().steps, 1500);
  EXPECT_NEAR(sim.core->plant().state().state.x_m, 1.0, 1e-5);  // the end, held (Simpson: s' is quartic)
}

}  // namespace
}  // namespace topay::simproc
