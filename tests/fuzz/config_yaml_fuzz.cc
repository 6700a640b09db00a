// Every other configuration loader from untrusted text, one per input: the mission spec
// (ParseMission), the motor simulator's options (ParseMotorSimOptions), the event script
// (ParseEventScript), the LiDAR options (LoadLidarOptionsFile, whole file and `lidar` section),
// and the loaders that only take a path, fed through one temporary file: topay-canbridge,
// -tracker, -sim (with its inline LiDAR options, as its sensor factory reads them), -director,
// -mission, -estimator, -viz, -kinematic-sim and the pick-and-place scenario. Bad input must be
// the loader's documented error (ConfigError naming the file; the kinematic model's
// std::runtime_error naming it, not yaml-cpp's); what loads must pass the options' own checks.
// Not here: topay-planner's options (planner_yaml target) and topay-mapper's options and scan
// filter (their library, topay_mapper_filters, links PCL).
// Input: [selector][YAML text]; the selector (modulo the number of loaders) picks the loader,
// in the order of kLoaders below.
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/director/director_options.h"
#include "procs/estimator/estimator_config.h"
#include "procs/kinematic_sim/kinematic_model.h"
#include "procs/mission/mission_options.h"
#include "procs/mission/mission_spec.h"
#include "procs/sim/sim_options.h"
#include "procs/tracker/tracker_options.h"
#include "procs/viz/viz_options.h"
#include "sim/events/event_file.h"
#include "sim/lidar/lidar_options.h"
#include "sim/motors/motorsim_options.h"
#include "sim/scenarios/pick_place_options.h"
#include "tests/fuzz/fuzz_reader.h"
#include "tests/fuzz/loader_checks.h"
#include "tests/fuzz/loader_rigid.h"
#include "tests/fuzz/loader_temp_file.h"

namespace topay::fuzz {
namespace {

constexpr const char* kTextSource = "fuzz_config.yaml";  // for the loaders that take text

bool FiniteAtLeast(double value, double low) { return std::isfinite(value) && value >= low; }
bool FinitePositive(double value) { return std::isfinite(value) && value > 0.0; }

// Runs check(), which must not throw std::invalid_argument (an options struct's Check()).
template <class Check>
void ExpectValid(Check check, const char* what) {
  try {
    check();
  } catch (const std::invalid_argument&) {
    FuzzCheck(false, what);
  }
}

// Loads with `load`; a ConfigError must name `source`. Returns nullopt for an error.
template <class Load>
auto LoadOrConfigError(Load load, const std::string& source) -> std::optional<decltype(load())> {
  try {
    return load();
  } catch (const ConfigError& e) {
    CheckConfigError(e, source);
    return std::nullopt;
  }
}

void CheckMissionHints(const mission::Mission& mission) {
  std::set<int> sizes;
  for (const mission::MissionStep& step : mission.steps) {
    if (step.hint) sizes.insert(step.hint->num_joints());
  }
  const int n = sizes.empty() ? 7 : *sizes.begin();
  for (const int robot : {n, n + 1}) {
    bool refused = false;
    try {
      mission::CheckMissionForRobot(mission, robot);
    } catch (const ConfigError& e) {
      CheckConfigError(e, kTextSource);
      refused = true;
    }
    FuzzCheck(refused == (sizes.size() > 1 || (sizes.size() == 1 && *sizes.begin() != robot)),
              "a mission is refused for a robot exactly when a hint has another joint count");
  }
}

void FuzzMission(const std::string& text, const LoaderTempFile&) {
  const auto mission = LoadOrConfigError([&] { return mission::ParseMission(text, kTextSource); }, kTextSource);
  if (!mission) return;
  FuzzCheck(!mission->name.empty() && mission->source == kTextSource, "a mission has a name and its source");
  FuzzCheck(!mission->steps.empty(), "a mission has steps");
  for (const mission::MissionStep& step : mission->steps) {
    FuzzCheck(!step.Describe().empty(), "a step describes itself");
    switch (step.type) {
      case mission::StepType::kGoto:
        FuzzCheck(IsRigid(step.X_WE), "a goto's target is a finite rigid transform");
        if (step.hint) {
          const WholeBodyState& hint = *step.hint;
          FuzzCheck(std::isfinite(hint.x_m) && std::isfinite(hint.y_m) && std::isfinite(hint.yaw_rad) &&
                        hint.q_rad.allFinite() && hint.num_joints() > 0,
                    "a hint is finite, with joints");
        }
        break;
      case mission::StepType::kGripper:
        FuzzCheck(step.gripper_position >= 0.0 && step.gripper_position <= 1.0, "a gripper position is in 0..1");
        FuzzCheck(!step.settle_s || FiniteAtLeast(*step.settle_s, 0.0), "a settle time is finite and >= 0");
        break;
      case mission::StepType::kWait:
        FuzzCheck(FiniteAtLeast(step.duration_s, 0.0), "a wait is finite and >= 0");
        break;
      case mission::StepType::kHome:
        break;
    }
    if (step.tolerance) {
      FuzzCheck(FiniteAtLeast(step.tolerance->position_m, 0.0) && FiniteAtLeast(step.tolerance->orientation_rad, 0.0),
                "a tolerance is finite and >= 0");
    }
    FuzzCheck(!step.timeout_s || FinitePositive(*step.timeout_s), "a timeout is finite and > 0");
  }
  CheckMissionHints(*mission);
}

void FuzzMotorSim(const std::string& text, const LoaderTempFile&) {
  const auto options =
      LoadOrConfigError([&] { return sim::motors::ParseMotorSimOptions(text, kTextSource); }, kTextSource);
  if (!options) return;
  FuzzCheck(sim::motors::CheckMotorSimOptions(*options).empty(), "loaded motorsim options pass their check");
}

void FuzzEventScript(const std::string& text, const LoaderTempFile&) {
  const auto script = LoadOrConfigError([&] { return sim::ParseEventScript(text, kTextSource); }, kTextSource);
  if (!script) return;
  for (const sim::SimEvent& event : script->events) {
    FuzzCheck(!event.name.empty() && event.box_id >= 0, "an event has a name and a box id");
    if (event.trigger == sim::SimEvent::Trigger::kAtTime) {
      FuzzCheck(FiniteAtLeast(event.at_s, 0.0) && FiniteAtLeast(event.jitter_s, 0.0), "event times are finite, >= 0");
    } else {
      FuzzCheck(event.trigger == sim::SimEvent::Trigger::kNearPoint, "a scripted event has a time or a place");
      FuzzCheck(event.point_W_m.allFinite() && FinitePositive(event.distance_m), "a place is finite");
    }
    if (event.box) {
      FuzzCheck(event.action == sim::SimEvent::Action::kAppear, "only an appearing box has geometry");
      FuzzCheck(event.box->center_W_m.allFinite() && std::isfinite(event.box->yaw_rad),
                "an appearing box's centre and yaw are finite");
      FuzzCheck(event.box->size_m.allFinite() && (event.box->size_m.array() > 0.0).all(),
                "an appearing box's size is finite and positive");
    }
  }
}

void CheckLidar(const sim::LidarOptions& options) {
  try {
    sim::CheckLidarOptions(options);
  } catch (const ConfigError&) {
    FuzzCheck(false, "loaded LiDAR options pass CheckLidarOptions");
  }
  FuzzCheck(options.PointsPerScan() >= 1 && options.PointsPerScan() <= 10'000'000, "a scan has 1..1e7 points");
  FuzzCheck(IsRigid(options.mount.X_PS()), "the mount is a finite rigid transform");
}

void FuzzLidar(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return sim::LoadLidarOptionsFile(file.path()); }, file.path());
  if (options) CheckLidar(*options);
}

void FuzzLidarSection(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options =
      LoadOrConfigError([&] { return sim::LoadLidarOptionsFile(file.path(), "lidar"); }, file.path());
  if (options) CheckLidar(*options);
}

void FuzzCanbridge(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return canbridge::LoadCanbridgeOptions(file.path()); }, file.path());
  if (options) ExpectValid([&] { options->Check(); }, "loaded canbridge options pass Check()");
}

void FuzzTracker(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return tracker::LoadTrackerOptions(file.path()); }, file.path());
  if (!options) return;
  ExpectValid([&] { options->nmpc.Check(); }, "loaded NMPC options pass Check()");
  FuzzCheck(FinitePositive(options->rest_command), "rest_command is finite and > 0");
  const msgs::TrajectoryRebuildOptions& rebuild = options->rebuild;
  FuzzCheck(rebuild.trajectory.integrator.panels_per_piece >= 1 && rebuild.coefficient_tolerance > 0.0 &&
                rebuild.yaw0_tolerance_rad > 0.0,
            "rebuild options are in range");
}

void FuzzSim(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return simproc::LoadSimOptions(file.path()); }, file.path());
  if (!options) return;
  const simproc::SimOptions& o = *options;
  FuzzCheck(o.start_utime >= 0, "start_utime is >= 0");
  FuzzCheck(FiniteAtLeast(o.rate, 0.0) && o.max_catch_up_steps >= 1, "pacing options are in range");
  FuzzCheck(o.keep_out_radius_m >= 0.0, "the keep-out radius is >= 0");
  FuzzCheck(FinitePositive(o.state_rate_hz) && FinitePositive(o.status_rate_hz) &&
                FinitePositive(o.plant_state_rate_hz),
            "rates are finite and > 0");
  FuzzCheck(o.plant_input == "control_command" || o.plant_input == "actuators", "plant_input is known");
  FuzzCheck(!(o.follow && o.plant_input == "actuators"), "follow runs only on control commands");
  // What topay-sim's sensor factory does next with inline LiDAR options.
  if (o.lidar_file.empty() && o.lidar_options.IsDefined() && !o.lidar_options.IsNull()) {
    const auto lidar = LoadOrConfigError(
        [&] { return sim::LoadLidarOptions(o.lidar_options, o.source, "lidar.options"); }, file.path());
    if (lidar) CheckLidar(*lidar);
  }
}

void FuzzDirector(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return director::LoadDirectorOptions(file.path()); }, file.path());
  if (!options) return;
  FuzzCheck(options->tick_period_s > 0.0 && options->path_sample_s > 0.0 && options->retry_period_s >= 0.0,
            "director periods are > 0 (the retry's >= 0)");
  for (const director::BoxOnRouteEvent& event : options->events) {
    FuzzCheck(!event.during_step.empty() && event.min_speed_mps >= 0.0 && event.box_id >= -1,
              "a director event names its step");
    ExpectValid([&] { CheckRouteBoxOptions(event.box); }, "a loaded event's box passes CheckRouteBoxOptions");
  }
}

void FuzzMissionOptions(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return mission::LoadMissionOptions(file.path()); }, file.path());
  if (!options) return;
  try {
    mission::CheckMissionOptions(*options, file.path());
  } catch (const ConfigError&) {
    FuzzCheck(false, "loaded mission options pass CheckMissionOptions");
  }
}

void FuzzEstimator(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options =
      LoadOrConfigError([&] { return estimator::LoadEstimatorProcessOptions(file.path()); }, file.path());
  if (!options) return;
  ExpectValid([&] { estimator::CheckProcessOptions(*options); }, "loaded estimator options pass their check");
  ExpectValid([&] { options->filter.Check(); }, "loaded filter options pass Check()");
}

void FuzzViz(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return viz::LoadVizOptions(file.path()); }, file.path());
  if (!options) return;
  try {
    viz::CheckVizOptions(*options, file.path());
  } catch (const ConfigError&) {
    FuzzCheck(false, "loaded viz options pass CheckVizOptions");
  }
}

void FuzzKinematicModel(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  std::optional<kinsim::KinematicModelOptions> options;
  try {
    options = kinsim::LoadKinematicModelOptions(file.path());
  } catch (const std::runtime_error& e) {
    CheckRuntimeError(e, file.path());
    return;
  }
  const kinsim::KinematicModelOptions& o = *options;
  FuzzCheck(o.joint_names.empty() || o.joint_names.size() == o.q_rad.size(), "one name per joint");
  FuzzCheck(o.max_step_s > 0.0 && o.state_rate_hz >= 0.0, "kinematic model periods are in range");
  // What topay-kinematic-sim does next: a model from the options, driven by a command.
  kinsim::KinematicModel model(o);
  control_command_t command{};
  command.utime = 1;
  command.num_joints = static_cast<std::int32_t>(o.q_rad.size());
  command.qdot_radps.assign(o.q_rad.size(), 0.0);
  FuzzCheck(model.Apply(command), "the model takes a command with its joint count");
}

void FuzzPickPlace(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  const auto options = LoadOrConfigError([&] { return LoadPickPlaceScenarioOptions(file.path()); }, file.path());
  if (!options) return;
  try {
    CheckPickPlaceScenarioOptions(*options, file.path());
  } catch (const ConfigError&) {
    FuzzCheck(false, "loaded scenario options pass their check");
  }
}

using Loader = void (*)(const std::string& text, const LoaderTempFile& file);

// The selector's order: tools/fuzz/write_loader_seeds.sh writes the seeds with these indices.
constexpr Loader kLoaders[] = {
    FuzzMission,         // 0: config/missions/*.yaml
    FuzzMotorSim,        // 1: config/sim/motorsim.yaml
    FuzzEventScript,     // 2: config/sim/events_example.yaml
    FuzzLidar,           // 3: config/sim/lidar.yaml
    FuzzLidarSection,    // 4: the same as a `lidar:` section
    FuzzCanbridge,       // 5: config/canbridge/canbridge.yaml
    FuzzTracker,         // 6: config/tracker/tracker.yaml
    FuzzSim,             // 7: config/sim/sim.yaml
    FuzzDirector,        // 8: config/director/pick_place.yaml
    FuzzMissionOptions,  // 9: config/mission/mission.yaml
    FuzzEstimator,       // 10: config/estimator/estimator.yaml
    FuzzViz,             // 11: config/viz/viz.yaml
    FuzzKinematicModel,  // 12: config/sim/kinematic_sim.yaml
    FuzzPickPlace,       // 13: config/scenarios/pick_place.yaml
};

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  static const LoaderTempFile file("topay_fuzz_config", ".yaml");
  FuzzReader in(data, size);
  const std::size_t selector = in.Byte() % std::size(kLoaders);
  kLoaders[selector](in.RestAsString(), file);
  return 0;
}
