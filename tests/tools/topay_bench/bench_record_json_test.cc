#include "tools/topay_bench/bench_record_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace topay::bench {
namespace {

BenchRecord HandRecord() {
  BenchRecord r;
  r.task = 7;
  r.task_seed = 18446744073709551615ull;  // the largest seed survives as an unsigned integer
  r.scene_seed = 12;
  r.scene = "tables";
  r.range = "small";
  r.method = "flatness";
  r.order = 1;
  r.start.x_m = 1.0;
  r.start.y_m = 2.0;
  r.start.yaw_rad = 0.5;
  r.start.q_rad = Eigen::Vector2d(0.1, -0.2);
  r.goal_hint.x_m = 4.0;
  r.goal_hint.y_m = 6.0;
  r.goal_hint.q_rad = Eigen::Vector2d(0.3, 0.4);
  r.used_hint = true;
  r.X_WE_goal = Eigen::Isometry3d::Identity();
  r.X_WE_goal.translation() = Eigen::Vector3d(4.5, 6.5, 0.8);
  r.X_WE_goal.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  r.base_distance_m = 5.0;
  r.base_unreachable = true;
  r.success = true;
  r.status = "success";
  r.timings.search_ms = 1.5;
  r.timings.sampling_ms = 2.5;
  r.timings.front_end_ms = 4.0;
  r.timings.optimization_ms = 30.0;
  r.timings.wait_ms = 6.0;
  r.timings.total_ms = 40.0;
  r.map_ms = 80.0;
  r.duration_s = 9.25;
  r.num_candidates = 1;
  r.num_paths = 2;
  r.num_classes = 3;
  r.num_base_paths = 4;
  r.plan_rounds = 2;
  plan::TrajectoryValidationFigures v;
  v.ok = true;
  v.min_clearance_m = 0.05;
  v.min_clearance_part = "base cylinder";
  v.min_self_clearance_m = std::numeric_limits<double>::infinity();
  v.worst_limit_ratio = 0.98;
  v.worst_limit = "yaw rate";
  v.worst_limit_t_s = 3.0;
  v.end_position_error_m = 0.001;
  v.end_orientation_error_rad = 0.002;
  r.validation = v;
  return r;
}

TEST(BenchRecordJsonTest, HoldsEveryFieldOfTheTask) {
  const nlohmann::json j = nlohmann::json::parse(RecordJsonLine(HandRecord()));
  EXPECT_EQ(j["task"], 7);
  EXPECT_EQ(j["task_seed"].get<std::uint64_t>(), 18446744073709551615ull);
  EXPECT_EQ(j["scene_seed"], 12);
  EXPECT_EQ(j["scene"], "tables");
  EXPECT_EQ(j["range"], "small");
  EXPECT_EQ(j["method"], "flatness");
  EXPECT_EQ(j["order"], 1);
  EXPECT_EQ(j["start"]["x_m"], 1.0);
  EXPECT_EQ(j["start"]["yaw_rad"], 0.5);
  EXPECT_EQ(j["start"]["q_rad"], nlohmann::json({0.1, -0.2}));
  EXPECT_EQ(j["goal_hint"]["y_m"], 6.0);
  EXPECT_EQ(j["goal_hint"]["q_rad"], nlohmann::json({0.3, 0.4}));
  EXPECT_EQ(j["used_hint"], true);
  EXPECT_EQ(j["target"]["position_m"], nlohmann::json({4.5, 6.5, 0.8}));
  // 90 degrees about z: w = x... = (cos 45, 0, 0, sin 45).
  const nlohmann::json& q = j["target"]["quaternion_wxyz"];
  EXPECT_NEAR(q[0].get<double>(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(q[1].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(q[2].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(q[3].get<double>(), std::sqrt(0.5), 1e-12);
  EXPECT_EQ(j["base_distance_m"], 5.0);
  EXPECT_EQ(j["base_unreachable"], true);
  EXPECT_EQ(j["success"], true);
  EXPECT_EQ(j["status"], "success");
  EXPECT_EQ(j["failure_reason"], "");
  EXPECT_EQ(j["failure_category"], "");
  EXPECT_EQ(j["cell"], "tables small");
  EXPECT_TRUE(j["tight"].is_null());  // an open task
}

TEST(BenchRecordJsonTest, ATightTaskNamesItsCellAndItsEnds) {
  BenchRecord r = HandRecord();
  r.tight = true;
  TightTaskInfo info;
  info.start = {0.012, 33, TightBody::kBase};
  info.goal = {0.004, 41, TightBody::kArm};
  info.goal_kind = TightGoalKind::kOnTable;
  info.goal_table_top = 41;
  r.tight_info = info;
  r.success = false;
  r.failure = FailureCategory::kStartRefused;
  const nlohmann::json j = nlohmann::json::parse(RecordJsonLine(r));
  EXPECT_EQ(j["cell"], "tables small tight");
  EXPECT_EQ(j["failure_category"], "start_refused");
  EXPECT_EQ(j["tight"]["start"]["clearance_m"], 0.012);
  EXPECT_EQ(j["tight"]["start"]["box"], 33);
  EXPECT_EQ(j["tight"]["start"]["body"], "base");
  EXPECT_EQ(j["tight"]["goal"]["body"], "arm");
  EXPECT_EQ(j["tight"]["goal_kind"], "on_table");
  EXPECT_EQ(j["tight"]["goal_table_top"], 41);
  // A tight cell's task that could not be generated has no ends, but its cell says tight.
  r.tight_info.reset();
  EXPECT_TRUE(nlohmann::json::parse(RecordJsonLine(r))["tight"].is_null());
  EXPECT_EQ(nlohmann::json::parse(RecordJsonLine(r))["cell"], "tables small tight");
}

TEST(BenchRecordJsonTest, TimingsAreUnderOneKeyAndFiguresAreThere) {
  const nlohmann::json j = nlohmann::json::parse(RecordJsonLine(HandRecord()));
  const nlohmann::json& t = j["timings_ms"];
  EXPECT_EQ(t["search"], 1.5);
  EXPECT_EQ(t["sampling"], 2.5);
  EXPECT_EQ(t["front_end"], 4.0);
  EXPECT_EQ(t["optimization"], 30.0);
  EXPECT_EQ(t["wait"], 6.0);
  EXPECT_EQ(t["total"], 40.0);
  EXPECT_EQ(j["map_ms"], 80.0);
  EXPECT_EQ(j["duration_s"], 9.25);
  EXPECT_EQ(j["num_candidates"], 1);
  EXPECT_EQ(j["num_paths"], 2);
  EXPECT_EQ(j["num_classes"], 3);
  EXPECT_EQ(j["num_base_paths"], 4);
  EXPECT_EQ(j["plan_rounds"], 2);
  const nlohmann::json& v = j["validation"];
  EXPECT_EQ(v["ok"], true);
  EXPECT_EQ(v["min_clearance_m"], 0.05);
  EXPECT_EQ(v["min_clearance_part"], "base cylinder");
  EXPECT_TRUE(v["min_self_clearance_m"].is_null());  // infinite: nothing near
  EXPECT_EQ(v["worst_limit_ratio"], 0.98);
  EXPECT_EQ(v["worst_limit"], "yaw rate");
  // No other key holds a wall-clock figure: the top-level keys are exactly these.
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys.size(), 30u);
  EXPECT_TRUE(j["sensed_map"].is_null());  // a run on the exact scene
}

TEST(BenchRecordJsonTest, ASensedMapRunCarriesItsMapFigures) {
  BenchRecord r = HandRecord();
  SensedMapFigures f;
  f.scans = 6;
  f.points = 120000;
  f.points_mapped = 40000;
  f.self_points = 900;
  f.voxels = {.occupied = 5000, .free = 200000, .unknown = 4915000};
  f.voxel_boxes = 700;
  f.lidar_ms = 25.0;
  f.mapping_ms = 60.0;
  f.fields_ms = 300.0;
  f.boxes_ms = 12.0;
  r.sensed = f;
  const nlohmann::json s = nlohmann::json::parse(RecordJsonLine(r))["sensed_map"];
  EXPECT_EQ(s["scans"], 6);
  EXPECT_EQ(s["points"], 120000);
  EXPECT_EQ(s["points_mapped"], 40000);
  EXPECT_EQ(s["self_points"], 900);
  EXPECT_EQ(s["voxels_occupied"], 5000);
  EXPECT_EQ(s["voxels_free"], 200000);
  EXPECT_EQ(s["voxels_unknown"], 4915000);
  EXPECT_EQ(s["voxel_boxes"], 700);
  EXPECT_EQ(s["mapping_ms"], 60.0);
  EXPECT_EQ(s["fields_ms"], 300.0);
}

TEST(BenchRecordJsonTest, AFailureHasNullDurationAndValidation) {
  BenchRecord r = HandRecord();
  r.success = false;
  r.status = "front_end_failed";
  r.failure_reason = "no goal";
  r.duration_s = std::nan("");
  r.validation.reset();
  const std::string line = RecordJsonLine(r);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(line);
  EXPECT_TRUE(j["duration_s"].is_null());
  EXPECT_TRUE(j["validation"].is_null());
  EXPECT_TRUE(j["optimizer"].is_null());
  EXPECT_EQ(j["failure_reason"], "no goal");
}

TEST(BenchRecordTest, LateSuccessCountsAsTimeLimitFailure) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kSuccess;
  plan.timings.total_ms = 3500.0;
  BenchRecord r;
  FillOutcome(plan, 3000.0, &r);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.status, "time_limit");
  EXPECT_EQ(r.failure, FailureCategory::kTimeLimit);
  EXPECT_NE(r.failure_reason.find("time limit"), std::string::npos) << r.failure_reason;
  EXPECT_DOUBLE_EQ(r.tp_ms(), 3500.0);

  BenchRecord in_time;
  plan.timings.total_ms = 2999.0;
  FillOutcome(plan, 3000.0, &in_time);
  EXPECT_TRUE(in_time.success);
  EXPECT_EQ(in_time.status, "success");
  EXPECT_EQ(in_time.failure, FailureCategory::kNone);
}

TEST(BenchRecordTest, CopiesCountsAndTheChosenValidation) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kSuccess;
  plan.front_end.paths.resize(3);
  plan.front_end.stats.num_classes_kept = 2;
  plan.front_end.stats.num_base_paths = 3;
  plan.candidates.resize(2);
  ValidationReport report;
  report.ok = true;
  report.min_obstacle.clearance_m = 0.07;
  report.worst_limit.ratio = 0.9;
  report.worst_limit.limit = Limit::kYawRate;
  plan.candidates[1].validation = report;
  plan.candidates[1].optimization.num_pieces = 7;
  plan.candidates[1].optimization.stage2_iterations = 140;
  plan.candidates[1].optimization.outer_iterations = 3;
  plan.candidates[0].optimization.outer_iterations = 5;
  plan.chosen = 1;
  SampledTrajectory sampled;
  sampled.duration_s = 8.5;
  plan.sampled = sampled;
  BenchRecord r;
  FillOutcome(plan, 3000.0, &r);
  EXPECT_TRUE(r.success);
  EXPECT_EQ(r.num_paths, 3);
  EXPECT_EQ(r.num_candidates, 2);
  EXPECT_EQ(r.num_classes, 2);
  EXPECT_EQ(r.num_base_paths, 3);
  EXPECT_DOUBLE_EQ(r.duration_s, 8.5);
  ASSERT_TRUE(r.validation.has_value());
  EXPECT_DOUBLE_EQ(r.validation->min_clearance_m, 0.07);
  EXPECT_DOUBLE_EQ(r.validation->worst_limit_ratio, 0.9);
  ASSERT_TRUE(r.optimizer.has_value());
  EXPECT_EQ(r.optimizer->num_pieces, 7);
  EXPECT_EQ(r.optimizer->stage2_iterations, 140);
  EXPECT_EQ(r.optimizer->outer_iterations, 3);  // the chosen candidate's, not the first's
  const nlohmann::json j = RecordToJson(r);
  EXPECT_EQ(j["failure_category"], "");
  EXPECT_EQ(j["optimizer"]["pieces"], 7);
  EXPECT_EQ(j["optimizer"]["outer_iterations"], 3);
}

TEST(BenchRecordTest, AFrontEndRefusalIsCategorised) {
  WholeBodyPlanResult plan;
  plan.status = PlanStatus::kFrontEndFailed;
  plan.front_end.status = FrontEndStatus::kStartInvalid;
  plan.failure_reason = "front end: start state: base collision";
  BenchRecord r;
  FillOutcome(plan, 3000.0, &r);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.failure, FailureCategory::kStartRefused);
  EXPECT_EQ(RecordToJson(r)["failure_category"], "start_refused");
}

}  // namespace
}  // namespace topay::bench
