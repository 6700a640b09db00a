#include "tools/topay_plan/trajectory_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/error.h"
#include "tests/common/temp_path.h"

namespace topay::plan {
namespace {

ArcYawTrajectory MakeTrajectory() {
  ArcYawTrajectory trajectory(2, 2, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(4, 3);
  head.col(0) << 0.0, 0.3, 0.1, -0.2;
  Eigen::MatrixXd tail = Eigen::MatrixXd::Zero(4, 3);
  tail.col(0) << 2.5, 1.1, 0.7, 0.5;
  Eigen::MatrixXd waypoints(4, 1);
  waypoints << 1.1, 0.6, 0.3, 0.0;
  trajectory.Update(Eigen::Vector2d(1.5, -2.0), head, tail, waypoints,
                    Eigen::Vector2d(1.7, 1.3337));
  return trajectory;
}

TrajectoryFile MakeFile(bool planned) {
  TrajectoryFile file;
  TrajectoryMetadata& m = file.metadata;
  m.scene_kind = "tables";
  m.scene_seed = 18446744073709551557ull;  // needs all 64 bits
  m.scene_file = "";
  m.num_boxes = 301;
  m.task_source = "task file";
  m.task_file = "/tmp/some task.json";
  m.task_range = "medium";
  m.task_seed = 7;
  m.start.x_m = 1.5;
  m.start.y_m = -2.0;
  m.start.yaw_rad = 0.3;
  m.start.q_rad = Eigen::Vector2d(0.1, -0.2);
  m.X_WE_goal.translation() = Eigen::Vector3d(3.0, 1.0, 0.8);
  m.X_WE_goal.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m.base_limits_source = "benchmark";
  m.base_limits.omega_max_radps = 1.25;
  m.status = planned ? "success" : "front_end_failed";
  m.failure_reason = planned ? "" : "front end: no base path (\"quoted\")";
  m.timings.search_ms = 12.25;
  m.timings.sampling_ms = 1.0 / 3.0;
  m.timings.front_end_ms = 14.0;
  m.timings.optimization_ms = 150.125;
  m.timings.wait_ms = 0.0;
  m.timings.total_ms = 170.5;
  m.map_build_ms = 812.3;
  if (planned) {
    const ArcYawTrajectory trajectory = MakeTrajectory();
    TrajectoryValidationFigures v;
    v.ok = true;
    v.duration_s = trajectory.duration_s();
    v.num_samples = 305;
    v.min_clearance_m = std::numeric_limits<double>::infinity();  // nothing near: null
    v.min_clearance_part = "";
    v.min_self_clearance_m = 0.0625;
    v.worst_limit_ratio = 0.987654321;
    v.worst_limit = "yaw rate";
    v.worst_limit_t_s = 1.23;
    v.end_position_error_m = 0.002;  // end_orientation_error_rad stays NaN: null
    m.validation = v;
    file.pieces = PiecesOf(trajectory);
    file.samples = SampleTrajectory(trajectory, 0.01);
  }
  return file;
}

void ExpectSameDouble(double a, double b, const std::string& what) {
  if (std::isnan(a)) {
    EXPECT_TRUE(std::isnan(b)) << what;
  } else {
    EXPECT_EQ(a, b) << what;
  }
}

void ExpectSameFile(const TrajectoryFile& a, const TrajectoryFile& b) {
  const TrajectoryMetadata &x = a.metadata, &y = b.metadata;
  EXPECT_EQ(x.scene_kind, y.scene_kind);
  EXPECT_EQ(x.scene_seed, y.scene_seed);
  EXPECT_EQ(x.scene_file, y.scene_file);
  EXPECT_EQ(x.num_boxes, y.num_boxes);
  EXPECT_EQ(x.task_source, y.task_source);
  EXPECT_EQ(x.task_file, y.task_file);
  EXPECT_EQ(x.task_range, y.task_range);
  EXPECT_EQ(x.task_seed, y.task_seed);
  EXPECT_EQ(x.start.ToVector(), y.start.ToVector());
  EXPECT_TRUE(x.X_WE_goal.isApprox(y.X_WE_goal, 1e-15));
  EXPECT_EQ(x.base_limits_source, y.base_limits_source);
  EXPECT_EQ(x.base_limits.v_max_mps, y.base_limits.v_max_mps);
  EXPECT_EQ(x.base_limits.a_max_mps2, y.base_limits.a_max_mps2);
  EXPECT_EQ(x.base_limits.omega_max_radps, y.base_limits.omega_max_radps);
  EXPECT_EQ(x.base_limits.beta_max_radps2, y.base_limits.beta_max_radps2);
  EXPECT_EQ(x.status, y.status);
  EXPECT_EQ(x.failure_reason, y.failure_reason);
  EXPECT_EQ(x.timings.search_ms, y.timings.search_ms);
  EXPECT_EQ(x.timings.sampling_ms, y.timings.sampling_ms);
  EXPECT_EQ(x.timings.front_end_ms, y.timings.front_end_ms);
  EXPECT_EQ(x.timings.optimization_ms, y.timings.optimization_ms);
  EXPECT_EQ(x.timings.wait_ms, y.timings.wait_ms);
  EXPECT_EQ(x.timings.total_ms, y.timings.total_ms);
  EXPECT_EQ(x.map_build_ms, y.map_build_ms);
  ASSERT_EQ(x.validation.has_value(), y.validation.has_value());
  if (x.validation) {
    const TrajectoryValidationFigures &v = *x.validation, &w = *y.validation;
    EXPECT_EQ(v.ok, w.ok);
    EXPECT_EQ(v.duration_s, w.duration_s);
    EXPECT_EQ(v.num_samples, w.num_samples);
    EXPECT_EQ(v.min_clearance_m, w.min_clearance_m);
    EXPECT_EQ(v.min_clearance_part, w.min_clearance_part);
    EXPECT_EQ(v.min_self_clearance_m, w.min_self_clearance_m);
    EXPECT_EQ(v.worst_limit_ratio, w.worst_limit_ratio);
    EXPECT_EQ(v.worst_limit, w.worst_limit);
    ExpectSameDouble(v.worst_limit_t_s, w.worst_limit_t_s, "worst_limit_t_s");
    ExpectSameDouble(v.end_position_error_m, w.end_position_error_m, "end_position_error_m");
    ExpectSameDouble(v.end_orientation_error_rad, w.end_orientation_error_rad,
                     "end_orientation_error_rad");
  }
  ASSERT_EQ(a.pieces.has_value(), b.pieces.has_value());
  if (a.pieces) {
    EXPECT_EQ(a.pieces->p0_W_m, b.pieces->p0_W_m);
    EXPECT_EQ(a.pieces->panels_per_piece, b.pieces->panels_per_piece);
    EXPECT_EQ(a.pieces->durations_s, b.pieces->durations_s);
    EXPECT_EQ(a.pieces->coefficients, b.pieces->coefficients);
  }
  EXPECT_EQ(a.sample_period_s, b.sample_period_s);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const TrajectorySample &s = a.samples[i], &t = b.samples[i];
    ASSERT_EQ(s.t_s, t.t_s) << i;
    ASSERT_EQ(s.state.x_m, t.state.x_m) << i;
    ASSERT_EQ(s.state.y_m, t.state.y_m) << i;
    ASSERT_EQ(s.state.yaw_rad, t.state.yaw_rad) << i;
    ASSERT_EQ(s.s_m, t.s_m) << i;
    ASSERT_EQ(s.v_mps, t.v_mps) << i;
    ASSERT_EQ(s.omega_radps, t.omega_radps) << i;
    ASSERT_EQ(s.a_mps2, t.a_mps2) << i;
    ASSERT_EQ(s.beta_radps2, t.beta_radps2) << i;
    ASSERT_EQ(s.state.q_rad, t.state.q_rad) << i;
  }
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TrajectoryJsonTest, PlannedTrajectoryRoundTripsExactly) {
  const TrajectoryFile file = MakeFile(true);
  ASSERT_EQ(file.samples.size(), 305u);
  const std::string path = UniqueTempPath("trajectory.json");
  WriteTrajectoryJson(path, file);
  const TrajectoryFile read = ReadTrajectoryJson(path);
  ExpectSameFile(file, read);
  EXPECT_EQ(read.metadata.validation->min_clearance_m, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(read.metadata.validation->end_orientation_error_rad));
  // Same file, same bytes.
  EXPECT_EQ(TrajectoryToJson(read), ReadText(path));
  // The pieces read back rebuild the trajectory whose samples were written.
  const ArcYawTrajectory rebuilt = RebuildTrajectory(*read.pieces);
  TrajectorySample point = rebuilt.MakePoint();
  for (const TrajectorySample& s : read.samples) {
    rebuilt.Evaluate(s.t_s, &point);
    ASSERT_NEAR(point.state.x_m, s.state.x_m, 1e-9) << s.t_s;
    ASSERT_NEAR(point.state.y_m, s.state.y_m, 1e-9) << s.t_s;
    ASSERT_NEAR(point.v_mps, s.v_mps, 1e-9) << s.t_s;
    ASSERT_LT((point.state.q_rad - s.state.q_rad).cwiseAbs().maxCoeff(), 1e-9) << s.t_s;
  }
  std::remove(path.c_str());
}

TEST(TrajectoryJsonTest, LayoutHasOnePieceAndOneSamplePerLine) {
  const TrajectoryFile file = MakeFile(true);
  const std::string text = TrajectoryToJson(file);
  std::istringstream lines(text);
  std::string line;
  int sample_lines = 0, piece_lines = 0;
  while (std::getline(lines, line)) {
    sample_lines += line.find("{\"t\":") != std::string::npos;
    piece_lines += line.find("{\"duration_s\":") != std::string::npos;
  }
  EXPECT_EQ(sample_lines, static_cast<int>(file.samples.size()));
  EXPECT_EQ(piece_lines, 2);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json["format"], "topay-trajectory");
  EXPECT_EQ(json["trajectory"]["dimensions"], nlohmann::json::array({"s", "yaw", "q1", "q2"}));
  EXPECT_EQ(json["trajectory"]["pieces"][1]["coefficients"].size(), 4u);
  EXPECT_EQ(json["trajectory"]["pieces"][1]["coefficients"][0].size(), 6u);
  EXPECT_TRUE(json["metadata"]["validation"]["min_clearance_m"].is_null());
  EXPECT_EQ(json["samples"]["count"], file.samples.size());
}

TEST(TrajectoryJsonTest, FailedPlanRoundTripsWithoutTrajectory) {
  const TrajectoryFile file = MakeFile(false);
  const std::string text = TrajectoryToJson(file);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_TRUE(json["trajectory"].is_null());
  EXPECT_TRUE(json["metadata"]["validation"].is_null());
  EXPECT_TRUE(json["samples"]["rows"].empty());
  const TrajectoryFile read = TrajectoryFromJson(text, "failed.json");
  ExpectSameFile(file, read);
}

// Parses the planned file's JSON, lets `edit` change it, and returns the reader's error.
std::string ErrorAfter(const std::function<void(nlohmann::json*)>& edit) {
  nlohmann::json json = nlohmann::json::parse(TrajectoryToJson(MakeFile(true)));
  edit(&json);
  try {
    TrajectoryFromJson(json.dump(), "edited.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TrajectoryJsonTest, BadFilesAreRejectedNamingFileAndField) {
  const std::string missing = UniqueTempPath("no_such_trajectory.json");
  try {
    ReadTrajectoryJson(missing);
    FAIL() << "no exception";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), missing);
  }
  EXPECT_THROW(TrajectoryFromJson("{\"format\": ", "cut.json"), ConfigError);
  auto has = [](const std::string& error, const std::string& part) {
    return error.find(part) != std::string::npos;
  };
  std::string e = ErrorAfter([](nlohmann::json* j) { (*j)["format"] = "other"; });
  EXPECT_TRUE(has(e, "edited.json: format")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["version"] = 2; });
  EXPECT_TRUE(has(e, "version")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["samples"]["rows"][3]["q"].push_back(0.0); });
  EXPECT_TRUE(has(e, "samples.rows[3].q")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["samples"]["rows"][5]["t"] = 0.0; });
  EXPECT_TRUE(has(e, "samples.rows[5].t")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["samples"]["rows"][2].erase("v"); });
  EXPECT_TRUE(has(e, "samples.rows[2].v: missing")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["samples"]["count"] = 3; });
  EXPECT_TRUE(has(e, "samples.count")) << e;
  e = ErrorAfter(
      [](nlohmann::json* j) { (*j)["trajectory"]["pieces"][1]["coefficients"].erase(0); });
  EXPECT_TRUE(has(e, "trajectory.pieces[1].coefficients")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["trajectory"]["pieces"][0]["duration_s"] = -1; });
  EXPECT_TRUE(has(e, "trajectory.pieces[0].duration_s")) << e;
  e = ErrorAfter([](nlohmann::json* j) { (*j)["metadata"]["plan"]["timings_ms"]["wait"] = "x"; });
  EXPECT_TRUE(has(e, "metadata.plan.timings_ms.wait")) << e;
  e = ErrorAfter([](nlohmann::json* j) {
    (*j)["metadata"]["task"]["goal_end_effector"]["quaternion_wxyz"] = {2, 0, 0, 0};
  });
  EXPECT_TRUE(has(e, "metadata.task.goal_end_effector.quaternion_wxyz")) << e;
}

TEST(TrajectoryJsonTest, UnwritablePathIsNamed) {
  const std::string path = UniqueTempPath("no_such_folder/trajectory.json");
  try {
    WriteTrajectoryJson(path, MakeFile(false));
    FAIL() << "no exception";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), path);
  }
}

}  // namespace
}  // namespace topay::plan
