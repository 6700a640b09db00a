#include "tools/topay_plan/plan_tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "tools/topay_plan/target_pose.h"
#include "tools/topay_plan/trajectory_json.h"
#include "tools/common/usage_error.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_json.h"
#include "tools/viz/png_io.h"
#include "tools/viz/scene_renderer.h"
#include "tools/viz/time_plot.h"
#include "tests/common/make_box.h"
#include "tests/common/temp_path.h"

namespace topay::plan {
namespace {

namespace fs = std::filesystem;

// The planner test's room: 10 x 10 m, a pillar between start and goal, a floating box.
class PlanToolTest : public ::testing::Test {
 protected:
  PlanToolTest() : model_(LoadRobotModel(kUrdf, kYaml)), kinematics_(model_) {
    Scene scene;
    scene.kind = "pillar room";
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, 0, 0.75), Eigen::Vector3d(1.0, 1.0, 1.5)));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(-1.5, 2.5, 1.2), Eigen::Vector3d(0.5, 0.5, 0.4)));
    scene_file_ = UniqueTempPath("scene.json");
    WriteSceneJson(scene_file_, scene);
    goal_.x_m = 3.0;
    goal_.y_m = 0.5;
    goal_.yaw_rad = 1.0;
    goal_.q_rad.resize(7);
    goal_.q_rad << 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1;
  }
  ~PlanToolTest() override {
    for (const std::string& path : written_) fs::remove(path);
    fs::remove(scene_file_);
  }

  std::string Output(const std::string& name) {
    written_.push_back(UniqueTempPath(name));
    return written_.back();
  }

  // A command-line task from (-3, 0, 0) to the end-effector pose of goal_, with generous
  // time bounds (ctest runs tests in parallel on loaded cores).
  PlanToolOptions Options() const {
    PlanToolOptions o;
    o.scene_file = scene_file_;
    o.start = {-3.0, 0.0, 0.0, 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1};
    const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal_);
    const Eigen::Vector3d rpy = RollPitchYaw(X_WE.linear());
    o.target_rpy = {X_WE.translation().x(),
                    X_WE.translation().y(),
                    X_WE.translation().z(),
                    rpy.x(),
                    rpy.y(),
                    rpy.z()};
    o.overrides.num_threads = 2;
    o.overrides.time_limit_s = 20.0;
    o.overrides.optimizer_time_limit_s = 10.0;
    o.overrides.acquisition_budget_s = 5.0;
    o.robot_urdf = kUrdf;
    o.robot_yaml = kYaml;
    return o;
  }

  static constexpr const char* kUrdf = TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf";
  static constexpr const char* kYaml = TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml";
  RobotModel model_;
  Kinematics kinematics_;
  std::string scene_file_;
  WholeBodyState goal_;
  std::vector<std::string> written_;
};

TEST_F(PlanToolTest, PlansAndWritesTheTrajectoryAndBothPlots) {
  PlanToolOptions o = Options();
  o.trajectory_json_out = Output("trajectory.json");
  o.path_png_out = Output("path.png");
  o.time_png_out = Output("time.png");
  const PlanToolSummary summary = RunPlanTool(o);
  ASSERT_TRUE(summary.plan.success()) << summary.Report();
  ASSERT_TRUE(summary.plan.trajectory.has_value());
  EXPECT_EQ(summary.ExitCode(), kExitSuccess);
  const ArcYawTrajectory& trajectory = *summary.plan.trajectory;

  // The top-down PNG: the 10 x 10 m room plus 0.25 m margins at 40 px/m beside the y axis,
  // legends below.
  const viz::Image path = viz::ReadPng(o.path_png_out);
  EXPECT_EQ(path.width(), viz::SceneImageWidth(420));
  EXPECT_GT(path.height(), 420);
  EXPECT_EQ(summary.path_png_width_px, path.width());
  EXPECT_EQ(summary.path_png_height_px, path.height());
  // The time plots: five stacked panels under a two-line title.
  viz::TimePlotOptions time_options;
  time_options.title = "scene\nplan";
  const viz::Image time = viz::ReadPng(o.time_png_out);
  EXPECT_EQ(time.width(), time_options.width_px);
  EXPECT_EQ(time.height(), viz::TimePlotPanels(time_options).back().y1 + 4);

  // The JSON: samples 10 ms apart from 0, then the exact end, matching the trajectory.
  const TrajectoryFile file = ReadTrajectoryJson(o.trajectory_json_out);
  ASSERT_GE(file.samples.size(), 2u);
  EXPECT_EQ(static_cast<int>(file.samples.size()), summary.num_samples);
  EXPECT_EQ(file.sample_period_s, 0.01);
  for (std::size_t i = 0; i + 1 < file.samples.size(); ++i) {
    ASSERT_EQ(file.samples[i].t_s, static_cast<double>(i) * 0.01) << i;
  }
  EXPECT_EQ(file.samples.back().t_s, trajectory.duration_s());
  EXPECT_LE(file.samples.back().t_s - file.samples[file.samples.size() - 2].t_s, 0.01 + 1e-12);
  TrajectorySample point = trajectory.MakePoint();
  for (const TrajectorySample& s : file.samples) {
    trajectory.Evaluate(s.t_s, &point);
    ASSERT_EQ(s.state.x_m, point.state.x_m) << s.t_s;
    ASSERT_EQ(s.state.y_m, point.state.y_m) << s.t_s;
    ASSERT_EQ(s.state.yaw_rad, point.state.yaw_rad) << s.t_s;
    ASSERT_EQ(s.v_mps, point.v_mps) << s.t_s;
    ASSERT_EQ(s.omega_radps, point.omega_radps) << s.t_s;
    ASSERT_EQ(s.state.q_rad, point.state.q_rad) << s.t_s;
  }
  ASSERT_TRUE(file.pieces.has_value());
  EXPECT_EQ(file.pieces->coefficients, trajectory.minco().coefficients());
  // Metadata: the query, the limits and the validator's figures.
  EXPECT_EQ(file.metadata.status, "success");
  EXPECT_EQ(file.metadata.scene_kind, "pillar room");
  EXPECT_EQ(file.metadata.scene_file, scene_file_);
  EXPECT_EQ(file.metadata.task_source, "command line");
  EXPECT_EQ(file.metadata.base_limits_source, "benchmark");
  EXPECT_EQ(file.metadata.base_limits.omega_max_radps, 1.25);
  EXPECT_GT(file.metadata.map_build_ms, 0.0);
  ASSERT_TRUE(file.metadata.validation.has_value());
  EXPECT_TRUE(file.metadata.validation->ok);
  EXPECT_GT(file.metadata.validation->min_clearance_m, 0.0);
  EXPECT_LE(file.metadata.validation->worst_limit_ratio, 1.01);
  EXPECT_LE(file.metadata.validation->end_position_error_m, 0.01);

  // The report names every figure the issue asks for.
  const std::string report = summary.Report();
  for (const char* part :
       {"SUCCESS", "search", "sampling", "optimization", "wait", "total", "duration",
        "min clearance", "worst constraint ratio", "map:", "inside the planning time",
        "omega_max 1.25", "benchmark", "(chosen)", "verdict"}) {
    EXPECT_NE(report.find(part), std::string::npos) << part << "\n" << report;
  }
  EXPECT_NE(report.find(o.trajectory_json_out), std::string::npos) << report;
  EXPECT_NE(report.find(o.time_png_out), std::string::npos) << report;
}

TEST_F(PlanToolTest, AFailedPlanIsAResultWithItsReason) {
  PlanToolOptions o = Options();
  o.target_rpy[2] = 3.0;  // 3 m up: out of the arm's reach
  o.robot_urdf = kUrdf;
  o.base_limits = "robot";
  o.trajectory_json_out = Output("failed.json");
  o.path_png_out = Output("failed.png");
  o.time_png_out = Output("failed_time.png");
  const PlanToolSummary summary = RunPlanTool(o);
  EXPECT_FALSE(summary.plan.success());
  EXPECT_EQ(summary.ExitCode(), kExitPlanFailed);
  EXPECT_FALSE(summary.plan.failure_reason.empty());
  // The robot config's limits (the real robot's omega_max 0.9 rad/s).
  EXPECT_EQ(summary.base_limits.omega_max_radps, model_.base_limits.omega_max_radps);
  const std::string report = summary.Report();
  EXPECT_NE(report.find("FAILED"), std::string::npos) << report;
  EXPECT_NE(report.find(summary.plan.failure_reason), std::string::npos) << report;
  EXPECT_NE(report.find("robot config"), std::string::npos) << report;
  // The JSON says why; no trajectory, no samples. The top-down view is drawn, the time plots
  // are not (nothing to plot), and the report says so.
  const TrajectoryFile file = ReadTrajectoryJson(o.trajectory_json_out);
  EXPECT_EQ(file.metadata.status, std::string(ToString(summary.plan.status)));
  EXPECT_EQ(file.metadata.failure_reason, summary.plan.failure_reason);
  EXPECT_EQ(file.metadata.base_limits_source, "robot");
  EXPECT_FALSE(file.pieces.has_value());
  EXPECT_TRUE(file.samples.empty());
  EXPECT_EQ(viz::ReadPng(o.path_png_out).width(), viz::SceneImageWidth(420));
  EXPECT_FALSE(fs::exists(o.time_png_out));
  EXPECT_NE(report.find("not written: time plots"), std::string::npos) << report;
}

TEST_F(PlanToolTest, ATaskFileGivesStartTargetAndHint) {
  PlanningTask task;
  task.start = WholeBodyState::FromVector(
      (Eigen::VectorXd(10) << -3.0, 0.0, 0.0, 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1).finished());
  task.goal = goal_;
  task.X_WE_goal = kinematics_.EndEffectorPose(goal_);
  task.X_WE_goal.translation().z() = 3.0;  // out of reach: the plan fails fast
  task.range = DistanceRange::kSmall;
  task.seed = 42;
  task.base_distance_m = std::hypot(goal_.x_m + 3.0, goal_.y_m);
  PlanToolOptions o = Options();
  o.start.clear();
  o.target_rpy.clear();
  o.task_file = Output("task.json");
  WriteTaskJson(o.task_file, task);
  o.use_goal_hint = true;
  o.trajectory_json_out = Output("task_plan.json");
  const PlanToolSummary summary = RunPlanTool(o);
  EXPECT_EQ(summary.task_source, "task file " + o.task_file);
  EXPECT_EQ(summary.task_seed, 42u);
  EXPECT_EQ(summary.task_range, "small");
  EXPECT_TRUE(summary.used_goal_hint);
  EXPECT_EQ(summary.start.ToVector(), task.start.ToVector());
  EXPECT_TRUE(summary.X_WE_goal.isApprox(task.X_WE_goal, 1e-12));
  EXPECT_NEAR(summary.base_distance_m, task.base_distance_m, 1e-12);
  EXPECT_EQ(summary.ExitCode(), kExitPlanFailed);
  const TrajectoryFile file = ReadTrajectoryJson(o.trajectory_json_out);
  EXPECT_EQ(file.metadata.task_source, "task file");
  EXPECT_EQ(file.metadata.task_file, o.task_file);
  EXPECT_EQ(file.metadata.task_seed, 42u);
  EXPECT_NE(summary.Report().find("goal state given as hint"), std::string::npos);
}

// Runs the tool and returns what it threw ("no error" if nothing), requiring type E.
template <typename E>
std::string ErrorOf(const PlanToolOptions& options) {
  try {
    RunPlanTool(options);
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception type: ") + e.what();
  }
  return "no error";
}

TEST_F(PlanToolTest, UsageErrorsNameTheOption) {
  auto expect_usage = [&](const PlanToolOptions& o, const std::string& part) {
    const std::string error = ErrorOf<UsageError>(o);
    EXPECT_NE(error.find(part), std::string::npos) << "expected '" << part << "' in: " << error;
  };
  PlanToolOptions o = Options();
  o.start[2] = std::numeric_limits<double>::quiet_NaN();
  expect_usage(o, "--start: value 3");
  o = Options();
  o.start.pop_back();
  expect_usage(o, "--start: expected 10 numbers");
  o = Options();
  o.target_rpy.pop_back();
  expect_usage(o, "--target: expected 6 numbers");
  o = Options();
  o.target_quaternion = {1, 2, 0.5, 1.1, 0, 0, 0};
  o.target_rpy.clear();
  expect_usage(o, "--target-quat");
  o = Options();
  o.target_quaternion = {1, 2, 0.5, 1, 0, 0, 0};
  expect_usage(o, "exactly one of --target");
  o = Options();
  o.target_rpy.clear();
  expect_usage(o, "exactly one of --target");
  o = Options();
  o.range = "huge";
  o.start.clear();
  o.target_rpy.clear();
  expect_usage(o, "huge");
  o = Options();
  o.range = "small";
  expect_usage(o, "exactly one task");
  o = Options();
  o.scene_kind = "forest";
  expect_usage(o, "--scene");
  o = Options();
  o.scene_file.clear();
  o.scene_kind = "forest";
  expect_usage(o, "unknown kind 'forest'");
  o = Options();
  o.base_limits = "fast";
  expect_usage(o, "--base-limits: unknown choice 'fast'");
  o = Options();
  o.overrides.time_limit_s = 0.0;
  expect_usage(o, "--time-limit");
  o = Options();
  o.overrides.time_limit_s = -1.0;  // negative limits are refused as 0 is
  expect_usage(o, "--time-limit");
  o = Options();
  o.overrides.acquisition_budget_s = -0.5;
  expect_usage(o, "--acquisition-budget");
  o = Options();
  o.overrides.num_threads = -1;
  expect_usage(o, "--threads");
  o = Options();
  o.overrides.optimizer_time_limit_s = std::numeric_limits<double>::quiet_NaN();
  expect_usage(o, "--optimizer-time-limit");
  o = Options();
  o.use_goal_hint = true;
  expect_usage(o, "--use-goal-hint");
}

TEST_F(PlanToolTest, FileErrorsNameTheFile) {
  PlanToolOptions o = Options();
  o.scene_file = UniqueTempPath("no_such_scene.json");
  std::string error = ErrorOf<ConfigError>(o);
  EXPECT_NE(error.find(o.scene_file), std::string::npos) << error;

  o = Options();
  o.scene_file = Output("bad_scene.json");
  std::ofstream(o.scene_file) << "{\"boxes\": [ {\"center\": [1, 2, 3], ";
  error = ErrorOf<ConfigError>(o);
  EXPECT_NE(error.find(o.scene_file), std::string::npos) << error;

  // A task file for a 6-joint robot.
  PlanningTask task;
  task.start.q_rad = Eigen::VectorXd::Zero(6);
  task.goal = task.start;
  o = Options();
  o.start.clear();
  o.target_rpy.clear();
  o.task_file = Output("six_joint_task.json");
  WriteTaskJson(o.task_file, task);
  error = ErrorOf<ConfigError>(o);
  EXPECT_NE(error.find(o.task_file), std::string::npos) << error;
  EXPECT_NE(error.find("joints"), std::string::npos) << error;

  o = Options();
  o.robot_yaml = UniqueTempPath("missing_robot.yaml");
  error = ErrorOf<ConfigError>(o);
  EXPECT_NE(error.find(o.robot_yaml), std::string::npos) << error;
}

TEST_F(PlanToolTest, AnUnwritableOutputIsReportedBeforePlanning) {
  PlanToolOptions o = Options();
  o.path_png_out = UniqueTempPath("no_such_folder/path.png");
  const std::string error = ErrorOf<std::runtime_error>(o);
  EXPECT_NE(error.find("--png"), std::string::npos) << error;
  EXPECT_NE(error.find(o.path_png_out), std::string::npos) << error;
  EXPECT_EQ(error.find("wrong exception"), std::string::npos) << error;
}

}  // namespace
}  // namespace topay::plan
