// topay-track-bench: the NMPC tracker in closed loop with the simulated plant, in-process (no
// LCM), over planned trajectories (issue 19's tracking figure; docs/benchmarks.md "NMPC tracker
// (issue 19)"). Each trajectory file (topay-bench --dump-trajectories: *_topay_trajectory.json)
// is rebuilt exactly; the plant (sim/plant: 500 Hz, command latency and first-order actuator lag,
// PlantOptions' defaults = config/sim/sim.yaml) starts at the trajectory's start at rest; the
// tracker (config/tracker/tracker.yaml) steps every control period from the plant's true state,
// its command goes to the plant; the trajectory starts 0.1 s in and the run ends 1 s after its
// end. Errors are the plant's true state against the trajectory at every tracker cycle over the
// trajectory's duration. Exit codes: 0, 1 file or config error, 2 usage error.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/common/angles.h"
#include "core/common/sample_statistics.h"
#include "core/control/nmpc_tracker.h"
#include "core/io/robot_loader.h"
#include "procs/tracker/tracker_options.h"
#include "sim/plant/plant.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_plan/trajectory_json.h"

using namespace topay;

namespace {

struct Errors {
  double position_sq = 0.0, yaw_sq = 0.0, joint_sq = 0.0;  // sums of squares
  long samples = 0, joint_samples = 0;
  double position_max = 0.0, yaw_max = 0.0, joint_max = 0.0;
  void Add(const Errors& o) {
    position_sq += o.position_sq; yaw_sq += o.yaw_sq; joint_sq += o.joint_sq;
    samples += o.samples; joint_samples += o.joint_samples;
    position_max = std::max(position_max, o.position_max); yaw_max = std::max(yaw_max, o.yaw_max);
    joint_max = std::max(joint_max, o.joint_max);
  }
  double PositionRms() const { return std::sqrt(position_sq / std::max(1L, samples)); }
  double YawRms() const { return std::sqrt(yaw_sq / std::max(1L, samples)); }
  double JointRms() const { return std::sqrt(joint_sq / std::max(1L, joint_samples)); }
};

struct RunResult {
  Errors errors;
  double duration_s = 0.0, end_position_m = 0.0;
  std::vector<double> solve_ms;
  int fallbacks = 0;
};

RunResult Track(const RobotModel& model, const NmpcOptions& nmpc, const ArcYawTrajectory& trajectory) {
  constexpr double kStart_s = 0.1, kAfter_s = 1.0;
  TrajectorySample point = trajectory.MakePoint();
  trajectory.Evaluate(0.0, &point);
  sim::PlantOptions plant_options;
  plant_options.initial.x_m = point.state.x_m;
  plant_options.initial.y_m = point.state.y_m;
  plant_options.initial.yaw_rad = point.state.yaw_rad;
  plant_options.initial.q_rad.assign(point.state.q_rad.data(), point.state.q_rad.data() + point.state.q_rad.size());
  sim::Plant plant(model, plant_options, 1);
  NmpcTracker tracker(nmpc, MakeTrackerLimits(model));
  TrajectorySample scratch = trajectory.MakePoint();
  TrackerReference reference;
  reference.trajectory_id = 1;
  reference.start_time_s = kStart_s;
  reference.duration_s = trajectory.duration_s();
  reference.sampler = [&](double t_s, TrajectorySample* out) {
    trajectory.Evaluate(t_s, &scratch);
    out->t_s = scratch.t_s; out->state.x_m = scratch.state.x_m; out->state.y_m = scratch.state.y_m;
    out->state.yaw_rad = scratch.state.yaw_rad; out->state.q_rad = scratch.state.q_rad; out->s_m = scratch.s_m;
    out->v_mps = scratch.v_mps; out->omega_radps = scratch.omega_radps; out->a_mps2 = scratch.a_mps2;
    out->beta_radps2 = scratch.beta_radps2; out->qd_radps = scratch.qd_radps; out->qdd_radps2 = scratch.qdd_radps2;
  };
  const int steps_per_cycle = static_cast<int>(std::lround(nmpc.control_period_s / plant.step_s()));
  sim::ActuatorCommand command;
  command.qdot_radps = Eigen::VectorXd::Zero(model.num_joints());
  RunResult result;
  result.duration_s = trajectory.duration_s();
  for (long k = 0; plant.time_s() < kStart_s + trajectory.duration_s() + kAfter_s; ++k) {
    if (k % steps_per_cycle == 0) {
      const double now_s = plant.time_s();
      TrackerInput input;
      input.now_s = now_s;
      input.state = &plant.state().state;
      input.state_time_s = now_s;
      input.reference = &reference;
      const TrackerOutput& out = tracker.Step(input);
      if (out.mode == TrackerMode::kTrack) result.solve_ms.push_back(out.solve_ms);
      command.v_mps = out.command.v_mps;
      command.omega_radps = out.command.omega_radps;
      command.qdot_radps = out.command.qd_radps;
      plant.Command(command);
      const double t_s = now_s - kStart_s;
      if (t_s >= 0.0 && t_s <= trajectory.duration_s()) {
        trajectory.Evaluate(t_s, &point);
        const WholeBodyState& s = plant.state().state;
        const double p = std::hypot(s.x_m - point.state.x_m, s.y_m - point.state.y_m);
        const double y = std::abs(WrapAngle(s.yaw_rad - point.state.yaw_rad));
        const Eigen::VectorXd dq = s.q_rad - point.state.q_rad;
        Errors& e = result.errors;
        e.position_sq += p * p; e.yaw_sq += y * y; e.joint_sq += dq.squaredNorm();
        ++e.samples; e.joint_samples += dq.size();
        e.position_max = std::max(e.position_max, p); e.yaw_max = std::max(e.yaw_max, y);
        e.joint_max = std::max(e.joint_max, dq.cwiseAbs().maxCoeff());
      }
    }
    plant.Step();
  }
  trajectory.Evaluate(trajectory.duration_s(), &point);
  result.end_position_m = std::hypot(plant.state().state.x_m - point.state.x_m, plant.state().state.y_m - point.state.y_m);
  result.fallbacks = tracker.solver().summary().num_over_budget + tracker.solver().summary().num_failed;
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-track-bench: the NMPC tracker + the simulated plant over planned trajectories (no LCM)"};
  std::vector<std::string> dirs;
  std::string tracker_config = tools::ConfigDir(TOPAY_CONFIG_DIR) + "/tracker/tracker.yaml";
  std::string urdf = tools::ConfigDir(TOPAY_CONFIG_DIR) + "/robot/topay_mm.urdf";
  std::string robot_yaml = tools::ConfigDir(TOPAY_CONFIG_DIR) + "/robot/topay_mm.yaml";
  int max_trajectories = 50;
  double budget_ms = 0.0;
  app.add_option("--trajectories", dirs, "Folders of *_topay_trajectory.json (topay-bench --dump-trajectories), taken in order")
      ->required();
  app.add_option("--config", tracker_config, "Tracker YAML")->capture_default_str();
  app.add_option("--max", max_trajectories, "Use at most this many (successful plans, in name order)")
      ->capture_default_str();
  app.add_option("--budget-ms", budget_ms,
                 "Replace nmpc.time_budget_s (ms; 0: the config's). A large budget takes the machine's "
                 "scheduling out of the tracking figures (no wall-clock fallbacks)")
      ->capture_default_str();
  if (const std::optional<int> code = tools::ParseCommandLine(app, argc, argv, "topay-track-bench")) return *code;
  try {
    tracker::TrackerOptions options = tracker::LoadTrackerOptions(tracker_config);
    if (budget_ms > 0.0) options.nmpc.time_budget_s = budget_ms * 1e-3;
    const RobotModel model = LoadRobotModel(urdf, robot_yaml);
    std::vector<std::string> files;
    for (const std::string& dir : dirs) {
      std::vector<std::string> in_dir;
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.size() > 22 && name.ends_with("_topay_trajectory.json")) in_dir.push_back(entry.path().string());
      }
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    }
    Errors all;
    std::vector<double> solve_ms, rms_position;
    int used = 0, fallbacks = 0;
    for (const std::string& file : files) {
      if (used >= max_trajectories) break;
      const plan::TrajectoryFile trajectory_file = plan::ReadTrajectoryJson(file);
      if (!trajectory_file.pieces) continue;
      const ArcYawTrajectory trajectory = plan::RebuildTrajectory(*trajectory_file.pieces);
      const RunResult r = Track(model, options.nmpc, trajectory);
      ++used;
      all.Add(r.errors);
      solve_ms.insert(solve_ms.end(), r.solve_ms.begin(), r.solve_ms.end());
      rms_position.push_back(r.errors.PositionRms());
      fallbacks += r.fallbacks;
      std::printf("%-58s %6.2f s  pos RMS %.4f m max %.4f  yaw RMS %.4f max %.4f  joints RMS %.4f max %.4f  end %.4f m\n",
                  (std::filesystem::path(file).parent_path().filename() / std::filesystem::path(file).filename()).c_str(), r.duration_s, r.errors.PositionRms(),
                  r.errors.position_max, r.errors.YawRms(), r.errors.yaw_max, r.errors.JointRms(), r.errors.joint_max,
                  r.end_position_m);
    }
    std::printf("\n%d trajectories, %ld samples at %.0f Hz: base position RMS %.4f m (max %.4f), yaw RMS %.4f rad "
                "(max %.4f), joints RMS %.4f rad (max %.4f)\n",
                used, all.samples, 1.0 / options.nmpc.control_period_s, all.PositionRms(), all.position_max,
                all.YawRms(), all.yaw_max, all.JointRms(), all.joint_max);
    std::printf("worst trajectory's position RMS %.4f m; solves %zu: median %.3f ms, p99 %.3f ms; fallbacks %d\n",
                rms_position.empty() ? 0.0 : *std::max_element(rms_position.begin(), rms_position.end()),
                solve_ms.size(), solve_ms.empty() ? 0.0 : Median(solve_ms),
                solve_ms.empty() ? 0.0 : NearestRankQuantile(solve_ms, 0.99), fallbacks);
    return used > 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "topay-track-bench: %s\n", e.what());
    return 1;
  }
}
