// The pipeline from LCM messages to the viewer's channels (procs/viz/viz_pipeline.h): rates,
// the latest message winning, a trajectory once per id and the planned values in the plots, the
// map as changed blocks, scans downsampled into W, contacts placed, malformed messages.

#include "procs/viz/viz_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>

#include "procs/viz/base64.h"
#include "tests/tools/report/crafted_run_log.h"
#include "topay/point_cloud_t.hpp"
#include "viz_test_support.h"

namespace topay::viz {
namespace {

using report::test::At;
using test::Encode;

class PipelineTest : public ::testing::Test {
 protected:
  PipelineTest() : robot_(test::ShippedRobot()), pipeline_(robot_, {}, std::ref(recorder_)) {}

  template <class Msg>
  void Feed(const char* channel, const Msg& msg, std::int64_t utime) {
    const std::vector<std::uint8_t> bytes = Encode(msg);
    pipeline_.Handle(channel, bytes.data(), bytes.size(), utime);
  }

  RobotView robot_;
  test::Recorder recorder_;
  VizPipeline pipeline_;
};

TEST_F(PipelineTest, ForwardsTheRobotStateAtThirtyHertzAndPlotsAtTwenty) {
  for (int k = 0; k < 100; ++k) {  // 100 Hz for one second
    robot_state_t msg = report::test::RobotState(k % 21);
    msg.utime = At(0.01 * k);
    Feed("ROBOT_STATE", msg, At(0.01 * k));
  }
  // 30 Hz: every 40 ms (the first message at or after 33.3 ms); 20 Hz: every 50 ms.
  EXPECT_EQ(recorder_.Of(Topic::kRobotState).size(), 25u);
  EXPECT_EQ(recorder_.Of(Topic::kPlotSample).size(), 20u);
  const nlohmann::json state = recorder_.Of(Topic::kRobotState).back().payload;
  EXPECT_EQ(state["links"].size(), robot_.model().links.size());
  const nlohmann::json plot = recorder_.Of(Topic::kPlotSample).front().payload;
  EXPECT_TRUE(plot["v_plan_mps"].is_null());  // no trajectory yet
  EXPECT_EQ(plot["trajectory_id"], 0);
}

TEST_F(PipelineTest, ForwardsTheLatestStatusOnceItsIntervalHasPassed) {
  planner_status_t status = report::test::Planner(planner_status_t::PLANNING, 11, 0, 0, 0);
  Feed("PLANNER_STATUS", status, At(0.0));  // first: at once
  status.state = planner_status_t::SUCCEEDED;
  Feed("PLANNER_STATUS", status, At(0.02));  // within 100 ms: waits
  status.state = planner_status_t::FAILED;
  Feed("PLANNER_STATUS", status, At(0.03));  // replaces the waiting one
  pipeline_.Flush(At(0.05));
  ASSERT_EQ(recorder_.Of(Topic::kPlannerStatus).size(), 1u);
  pipeline_.Flush(At(0.11));
  const std::vector<test::Forwarded> out = recorder_.Of(Topic::kPlannerStatus);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].payload["state_name"], "FAILED");
  EXPECT_EQ(out[1].log_utime, At(0.03));  // stamped with its own time
  EXPECT_EQ(*pipeline_.Latched(Topic::kPlannerStatus), out[1].payload.dump());
}

// Found by tests/fuzz/viz_inputs_fuzz.cc: a status string that is not UTF-8 made the JSON
// text throw (nlohmann type_error 316), ending topay-viz. Such bytes now become U+FFFD.
TEST_F(PipelineTest, AStatusThatIsNotUtf8IsForwardedWithReplacementCharacters) {
  planner_status_t status = report::test::Planner(planner_status_t::FAILED, 11, 0, 0, 0);
  status.failure_reason = "bad \xff\xfe byte";
  EXPECT_NO_THROW(Feed("PLANNER_STATUS", status, At(0.0)));
  pipeline_.Flush(At(0.2));
  const std::vector<test::Forwarded> out = recorder_.Of(Topic::kPlannerStatus);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].payload["failure_reason"], "bad \xef\xbf\xbd\xef\xbf\xbd byte");
}

TEST_F(PipelineTest, SamplesATrajectoryOncePerIdAndPlotsItsPlan) {
  Feed("TRAJECTORY", report::test::TrajectoryMessage(101, 0.25, 0.3), At(0.25));
  Feed("TRAJECTORY", report::test::TrajectoryMessage(101, 0.25, 0.3), At(0.26));  // same id
  const std::vector<test::Forwarded> out = recorder_.Of(Topic::kTrajectory);
  ASSERT_EQ(out.size(), 1u);
  const nlohmann::json& t = out[0].payload;
  EXPECT_EQ(t["trajectory_id"], 101);
  EXPECT_NEAR(t["duration_s"].get<double>(), 6.0, 1e-9);
  EXPECT_EQ(t["base_path_m"].size(), 121u);  // 6 s every 50 ms
  EXPECT_EQ(t["ee_path_m"].size(), 121u);
  EXPECT_NEAR(t["base_path_m"][0][1].get<double>(), 1.0, 1e-9);  // from (0, 1)
  EXPECT_EQ(t["samples"]["q_rad"][120].size(), 7u);
  EXPECT_NEAR(t["samples"]["q_rad"][120][0].get<double>(), 0.4, 1e-9);
  EXPECT_NEAR(t["samples"]["v_mps"][0].get<double>(), 0.0, 1e-12);  // from rest
  robot_state_t msg = report::test::RobotState(3);
  msg.utime = At(3.3);  // 3 s into the trajectory: its middle
  Feed("ROBOT_STATE", msg, At(3.3));
  const nlohmann::json plot = recorder_.Of(Topic::kPlotSample).back().payload;
  EXPECT_EQ(plot["trajectory_id"], 101);
  EXPECT_GT(plot["v_plan_mps"].get<double>(), 0.1);
  EXPECT_NEAR(plot["q_plan_rad"][6].get<double>(), 0.2, 1e-6);  // halfway by symmetry
  EXPECT_NEAR(plot["q_rad"][0].get<double>(), 0.15, 1e-12);      // measured
}

TEST_F(PipelineTest, SendsTheMapAsTheBlocksThatChanged) {
  const GridGeometry3 g = report::test::MapGeometry();
  std::vector<std::uint8_t> states(g.NumCells(), static_cast<std::uint8_t>(VoxelState::kFree));
  states[g.Index(1, 25, 4)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
  Feed("MAP_UPDATE", msgs::EncodeFullMap(g, states, At(0.5), 1), At(0.5));
  pipeline_.Flush(At(0.5));
  std::vector<test::Forwarded> out = recorder_.Of(Topic::kMapBlocks);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].payload["reset"]);
  EXPECT_EQ(out[0].payload["occupied_total"], 1);
  ASSERT_EQ(out[0].payload["blocks"].size(), 1u);  // empty blocks are not sent
  const nlohmann::json& block = out[0].payload["blocks"][0];
  EXPECT_EQ(block["key"], nlohmann::json::array({0, 1, 0}));  // voxel (1, 25, 4): block (0, 1, 0)
  const std::vector<std::uint8_t> bytes = *Base64Decode(block["occupied"].get<std::string>());
  ASSERT_EQ(bytes.size(), 2u);
  EXPECT_EQ(bytes[0] | (bytes[1] << 8), 1 + 16 * (9 + 16 * 4));  // local (1, 9, 4)
  const std::vector<VoxelChange> changes = {{Eigen::Vector3i(1, 25, 7), VoxelState::kOccupied},
                                            {Eigen::Vector3i(30, 2, 1), VoxelState::kOccupied}};
  Feed("MAP_UPDATE", msgs::EncodeMapDelta(g, changes, At(0.6), 2), At(0.6));
  pipeline_.Flush(At(0.7));  // within 500 ms of the last: waits
  EXPECT_EQ(recorder_.Of(Topic::kMapBlocks).size(), 1u);
  pipeline_.Flush(At(1.0));
  out = recorder_.Of(Topic::kMapBlocks);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_FALSE(out[1].payload["reset"]);
  EXPECT_EQ(out[1].payload["blocks"].size(), 2u);  // the two blocks touched, nothing else
  EXPECT_EQ(out[1].payload["occupied_total"], 3);
  const nlohmann::json full = nlohmann::json::parse(*pipeline_.Latched(Topic::kMapBlocks));
  EXPECT_TRUE(full["reset"]);
  EXPECT_EQ(full["blocks"].size(), 2u);
}

TEST_F(PipelineTest, DownsamplesAScanIntoTheWorldsAxesInCentimetres) {
  point_cloud_t cloud;
  cloud.utime = At(1.0);
  cloud.sensor_frame = "lidar";
  cloud.p_WS[0] = 1.0, cloud.p_WS[1] = 2.0, cloud.p_WS[2] = 0.5;
  const Eigen::Quaterniond q_WS(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));  // S's x = W's y
  cloud.quat_WS[0] = q_WS.w(), cloud.quat_WS[1] = q_WS.x(), cloud.quat_WS[2] = q_WS.y(), cloud.quat_WS[3] = q_WS.z();
  for (int i = 0; i < 20000; ++i) {
    cloud.p_SP.push_back(2.0f + 0.0001f * i);
    cloud.p_SP.push_back(0.0f);
    cloud.p_SP.push_back(i == 0 ? NAN : 0.25f);
  }
  cloud.num_coords = static_cast<int>(cloud.p_SP.size());
  Feed("POINT_CLOUD", cloud, At(1.0));
  const std::vector<test::Forwarded> out = recorder_.Of(Topic::kScan);
  ASSERT_EQ(out.size(), 1u);
  const nlohmann::json& scan = out[0].payload;
  EXPECT_EQ(scan["points_total"], 20000);
  EXPECT_EQ(scan["count"], 3999);  // every 5th of 20000, the NaN one left out
  const std::vector<std::uint8_t> b = *Base64Decode(scan["points_cm"].get<std::string>());
  ASSERT_EQ(b.size(), 3999u * 6);
  const auto value = [&](int i) { return static_cast<std::int16_t>(b[2 * i] | (b[2 * i + 1] << 8)); };
  EXPECT_EQ(value(0), 0);    // point 5: S (2.0005, 0, 0.25) -> W offset (0, 200, 25) cm
  EXPECT_EQ(value(1), 200);
  EXPECT_EQ(value(2), 25);
  Feed("POINT_CLOUD", cloud, At(1.1));  // 5 Hz: too soon, not even decoded
  EXPECT_EQ(recorder_.Of(Topic::kScan).size(), 1u);
}

TEST_F(PipelineTest, PlacesContactsWhereTheBodyWas) {
  robot_state_t msg = report::test::RobotState(10);  // base at (3, 0)
  Feed("ROBOT_STATE", msg, At(1.0));
  sim_contact_t contact;
  contact.utime = At(1.0);
  contact.body = "base";
  contact.box_id = 3;
  contact.depth_m = 0.004;
  Feed("SIM_CONTACT", contact, At(1.0));
  contact.body = "something else";
  Feed("SIM_CONTACT", contact, At(1.1));
  const std::vector<test::Forwarded> out = recorder_.Of(Topic::kContacts);
  ASSERT_EQ(out.size(), 2u);
  const nlohmann::json& all = out[1].payload;
  EXPECT_EQ(all["count"], 2);
  EXPECT_NEAR(all["contacts"][0]["p_W_m"][0].get<double>(), 3.0, 1e-9);
  EXPECT_GT(all["contacts"][0]["radius_m"].get<double>(), 0.1);
  EXPECT_TRUE(all["contacts"][1]["p_W_m"].is_null());  // a body it cannot place
}

TEST_F(PipelineTest, CountsMalformedMessagesAndIgnoresOtherChannels) {
  const std::vector<std::uint8_t> garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (const char* channel : {"ROBOT_STATE", "MAP_UPDATE", "POINT_CLOUD", "TRAJECTORY", "PLANNER_STATUS", "GOAL"}) {
    pipeline_.Handle(channel, garbage.data(), garbage.size(), At(0.0));
  }
  pipeline_.Handle("SOMETHING_ELSE", garbage.data(), garbage.size(), At(0.0));
  robot_state_t wrong = report::test::RobotState(1);
  wrong.joints.num_joints = 2;
  wrong.joints.names.resize(2);
  wrong.joints.position_rad.resize(2);
  wrong.joints.velocity_radps.resize(2);
  wrong.joints.effort_Nm.resize(2);
  Feed("ROBOT_STATE", wrong, At(0.0));  // decodes, but not this robot
  poly_trajectory_t bent = report::test::TrajectoryMessage(7, 0.0, 0.0);
  bent.coeffs[5] += 1.0;  // not a MINCO solution
  Feed("TRAJECTORY", bent, At(0.0));
  EXPECT_EQ(pipeline_.counts().malformed, 8);
  EXPECT_EQ(pipeline_.counts().ignored, 1);
  EXPECT_NE(pipeline_.counts().last_error.find("TRAJECTORY"), std::string::npos);
  EXPECT_TRUE(recorder_.all.empty());
}

TEST_F(PipelineTest, KeepsTheLatchedStateUntilReset) {
  EXPECT_TRUE(pipeline_.Latched(Topic::kRobotDescription).has_value());
  EXPECT_FALSE(pipeline_.Latched(Topic::kGoal).has_value());
  goal_t goal{};
  goal.goal_id = 11;
  goal.quat_WE[0] = 1.0;
  Feed("GOAL", goal, At(0.2));
  EXPECT_EQ(nlohmann::json::parse(*pipeline_.Latched(Topic::kGoal))["goal_id"], 11);
  pipeline_.Reset();
  EXPECT_FALSE(pipeline_.Latched(Topic::kGoal).has_value());
  EXPECT_TRUE(pipeline_.Latched(Topic::kRobotDescription).has_value());
}

}  // namespace
}  // namespace topay::viz
