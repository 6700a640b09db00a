// Every number of the summary of the crafted run log (crafted_run_log.h), worked out by hand.

#include "tools/report/run_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

class RunSummaryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = test::FreshTestDir("run_summary") + "/graph.lcmlog";
    test::WriteCraftedRunLog(path_);
    summary_ = Summarize(path_);
  }
  std::string path_;
  RunSummary summary_;
};

TEST_F(RunSummaryTest, MissionResultTimeAndStepsFromTheStatusTransitions) {
  const MissionSummary& m = summary_.mission;
  EXPECT_EQ(m.name, "two_goals");
  EXPECT_EQ(m.result, MissionResult::kSucceeded);
  EXPECT_TRUE(summary_.succeeded());
  EXPECT_EQ(m.detail, "every step done");
  EXPECT_DOUBLE_EQ(m.elapsed_s, 9.0);
  EXPECT_EQ(m.num_steps, 3);
  ASSERT_EQ(m.steps.size(), 3u);  // the IDLE status is before the start
  EXPECT_EQ(m.steps[0].description, "goto pickup");
  EXPECT_DOUBLE_EQ(m.steps[0].start_s, 0.5);
  EXPECT_DOUBLE_EQ(m.steps[0].time_s, 4.0);  // 0.5 -> 4.5 (step 1's first status)
  EXPECT_EQ(m.steps[0].attempts, 2);
  EXPECT_EQ(m.steps[0].end_utime, test::At(1.0));
  EXPECT_EQ(m.steps[1].description, "gripper close");
  EXPECT_DOUBLE_EQ(m.steps[1].time_s, 0.5);  // 4.5 -> 5.0
  EXPECT_FALSE(m.steps[1].moving);
  EXPECT_EQ(m.steps[1].attempts, 0);  // the status's 2 is the goto's, left over
  EXPECT_TRUE(m.steps[0].moving);
  EXPECT_TRUE(m.steps[2].moving);
  EXPECT_DOUBLE_EQ(m.steps[2].time_s, 4.0);  // 5.0 -> 9.0 (the final status)
  EXPECT_EQ(m.steps[2].attempts, 1);
  EXPECT_EQ(m.steps[2].end_utime, test::At(2.0));
}

TEST_F(RunSummaryTest, ReplansStoppingAndTrajectoriesCountEachPlanOnce) {
  const PlannerSummary& p = summary_.planner;
  EXPECT_EQ(p.replans, 3);  // max per goal: 11 -> 2, 12 -> 0, 13 -> 1, 14 -> 0
  EXPECT_EQ(p.goals, 4);
  EXPECT_EQ(p.stopping, 1);  // trajectory 102 reported twice
  EXPECT_EQ(summary_.trajectory_messages, 3);
  EXPECT_EQ(summary_.trajectories_rebuilt, 2);  // 102's coefficients are not a MINCO solution
}

TEST_F(RunSummaryTest, PlanningTimesOfSucceededPlansAndFailuresByReason) {
  const PlannerSummary& p = summary_.planner;
  EXPECT_EQ(p.planning_ms.count, 3);  // 101 (twice), 103 (twice), 104: 100, 300, 200 ms
  EXPECT_DOUBLE_EQ(p.planning_ms.median, 200.0);
  EXPECT_DOUBLE_EQ(p.planning_ms.p95, 290.0);
  EXPECT_DOUBLE_EQ(p.planning_ms.max, 300.0);
  EXPECT_EQ(p.failures, 2);  // goals 12 (twice) and 14
  const std::map<std::string, std::int64_t> reasons = {{"no goal", 1}, {"target unreachable", 1}};
  EXPECT_EQ(p.failure_reasons, reasons);
}

TEST_F(RunSummaryTest, CollisionsFromTheLastSimStatusAndTheContactMessages) {
  const CollisionSummary& c = summary_.collisions;
  EXPECT_TRUE(c.has_sim_status);
  EXPECT_EQ(c.contact_events, 2);
  EXPECT_EQ(c.contact_steps, 7);
  EXPECT_DOUBLE_EQ(c.max_depth_m, 0.012);
  EXPECT_EQ(c.contact_messages, 2);
}

TEST_F(RunSummaryTest, TrackingErrorsAndSolveTimesWhileTracking) {
  const TrackingSummary& t = summary_.tracking;  // the 4 TRACKING statuses only
  EXPECT_EQ(t.position_m.count, 4);
  EXPECT_NEAR(t.position_m.rms, 0.025, 1e-15);  // (1 + 4 + 4 + 16) e-4 / 4 = 6.25e-4
  EXPECT_DOUBLE_EQ(t.position_m.max, 0.04);
  EXPECT_NEAR(t.yaw_rad.rms, std::sqrt(6e-4), 1e-15);  // (4 + 16 + 0 + 4) e-4 / 4
  EXPECT_DOUBLE_EQ(t.yaw_rad.max, 0.04);                // |-0.04|
  EXPECT_NEAR(t.joint_rad.rms, 0.0025, 1e-15);         // (1 + 4 + 4 + 16) e-6 / 4
  EXPECT_DOUBLE_EQ(t.joint_rad.max, 0.004);
  EXPECT_EQ(t.solve_ms.count, 4);
  EXPECT_DOUBLE_EQ(t.solve_ms.median, 2.5);
  EXPECT_DOUBLE_EQ(t.solve_ms.p99, 3.97);
  EXPECT_DOUBLE_EQ(t.solve_ms.max, 4.0);
}

TEST_F(RunSummaryTest, DistanceDrivenAndAppearedBoxes) {
  EXPECT_NEAR(summary_.distance_driven_m, 7.0, 1e-12);  // 3 m along x, then 4 m along y
  ASSERT_EQ(summary_.appeared_boxes.size(), 2u);          // the DISAPPEAR is not counted
  const AppearedBox& crate = summary_.appeared_boxes[0];
  EXPECT_EQ(crate.box_id, 40);
  EXPECT_EQ(crate.name, "crate");
  EXPECT_TRUE(crate.has_box);
  EXPECT_EQ(crate.center_W_m, Eigen::Vector3d(1.5, 2.5, 0.4));
  EXPECT_EQ(summary_.appeared_boxes[1].box_id, 5);
  EXPECT_FALSE(summary_.appeared_boxes[1].has_box);
}

TEST_F(RunSummaryTest, MessagesPerChannelAndMalformedOnesCounted) {
  const auto& ch = summary_.channels;
  EXPECT_EQ(ch.at("ROBOT_STATE").messages, test::kRobotStates + 1);
  EXPECT_EQ(ch.at("ROBOT_STATE").decode_failures, 1);  // 5 bytes of garbage
  EXPECT_EQ(ch.at("PLANNER_STATUS").messages, 12);
  EXPECT_EQ(ch.at("PLANNER_STATUS").decode_failures, 1);  // a tracker status on it
  EXPECT_EQ(ch.at("MYSTERY").decode_failures, 1);         // unknown fingerprint
  EXPECT_EQ(ch.at("LCM_SELF_TEST").decode_failures, 0);
  EXPECT_EQ(ch.at("MISSION_STATUS").messages, 6);
  EXPECT_EQ(ch.at("TRACKER_STATUS").messages, 7);
  EXPECT_EQ(ch.at("TRAJECTORY").messages, 3);
  EXPECT_EQ(ch.at("TRAJECTORY").decode_failures, 0);
  EXPECT_EQ(ch.at("MAP_UPDATE").decode_failures, 0);
  EXPECT_EQ(ch.at("SIM_EVENT").messages, 3);
  EXPECT_EQ(summary_.decode_failures, 3);
  EXPECT_EQ(summary_.log_path, path_);
  EXPECT_DOUBLE_EQ(summary_.log_span_s, 2.0);  // t = 0 .. 2 s
}

TEST(RunSummary, AnEmptyLogGivesAnEmptySummary) {
  const std::string path = test::FreshTestDir("run_summary") + "/empty.lcmlog";
  { test::CraftedLogWriter log(path); }
  const RunSummary s = Summarize(path);
  EXPECT_EQ(s.mission.result, MissionResult::kNone);
  EXPECT_FALSE(s.succeeded());
  EXPECT_FALSE(s.collisions.has_sim_status);
  EXPECT_TRUE(s.channels.empty());
}

TEST(RunSummary, AMissingOrForeignFileThrowsNamingIt) {
  const std::string dir = test::FreshTestDir("run_summary");
  try {
    Summarize(dir + "/missing.lcmlog");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/missing.lcmlog"), std::string::npos) << e.what();
  }
  const std::string text = dir + "/not_a_log.txt";
  std::ofstream(text) << "this is not an LCM log at all\n";
  try {
    Summarize(text);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_log.txt: not an LCM log"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::report
