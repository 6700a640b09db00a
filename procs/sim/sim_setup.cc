#include "procs/sim/sim_setup.h"

#include <fmt/format.h>

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "procs/sim/plant_checkpoint.h"
#include "procs/sim/sensor_factory.h"
#include "sim/events/event_file.h"
#include "sim/plant/plant.h"
#include "sim/world/scene_source.h"

namespace topay::simproc {

SimAssembly AssembleSim(const SimOptions& options) {
  SimAssembly a;
  a.model = std::make_unique<RobotModel>(LoadRobotModel(options.robot_urdf, options.robot_yaml));
  sim::CheckPlantOptions(options.plant, *a.model, options.source);
  a.kinematics = std::make_unique<Kinematics>(*a.model);

  const sim::SceneSource source = *sim::ParseSceneArgument(options.scene, options.scene_seed);
  KeepOutRegions keep_out;
  if (options.keep_out_radius_m > 0.0) {
    VerticalCylinder start;
    start.axis_W_m = Eigen::Vector2d(options.plant.initial.x_m, options.plant.initial.y_m);
    start.radius_m = options.keep_out_radius_m;
    start.height_m = 3.0;
    keep_out.cylinders.push_back(start);
  }
  const Scene scene = sim::LoadScene(source, keep_out);
  a.scene_description = sim::Describe(source) + ", " + std::to_string(scene.boxes.size()) + " boxes";

  sim::EventScript script;
  if (!options.events_file.empty()) script = sim::LoadEventFile(options.events_file);
  a.num_scripted_events = static_cast<int>(script.events.size());

  SimCoreOptions core;
  core.plant = options.plant;
  if (!options.checkpoint_file.empty()) {
    if (const std::optional<PlantCheckpoint> checkpoint = ReadPlantCheckpoint(options.checkpoint_file)) {
      ResumeFrom(*checkpoint, &core.plant);
      sim::CheckPlantOptions(core.plant, *a.model, options.checkpoint_file);
      a.resumed_from = fmt::format("{} ({:.3f}, {:.3f}, {:.3f} rad)", options.checkpoint_file, checkpoint->x_m,
                                   checkpoint->y_m, checkpoint->yaw_rad);
    }
  }
  core.state_rate_hz = options.state_rate_hz;
  core.pose_noise = options.pose_noise;
  core.seed = options.seed;
  core.event_seed = script.seed.value_or(DeriveSeed(options.seed, 4));
  a.core = std::make_unique<SimCore>(*a.model, core, scene, std::move(script.events),
                                     MakeLidar(options, *a.kinematics, DeriveSeed(options.seed, 3)),
                                     MakeMonitor(options, *a.kinematics));
  return a;
}

}  // namespace topay::simproc
