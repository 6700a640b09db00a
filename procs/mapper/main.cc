// topay-mapper: the LiDAR mapper of the graph (docs/mapper.md). POINT_CLOUD and ROBOT_STATE in;
// MAP_UPDATE out after every scan (a compressed delta, a snapshot every few seconds). Scans are
// filtered with PCL (range, floor, the robot's own body at the scan's time, voxel grid,
// outliers) and inserted into a dense occupancy grid with free-space ray casting; an OctoMap
// is kept beside it at a lower rate (--save writes it as a .bt at exit; --prior starts from
// one). --checkpoint keeps a journal of the map, so that a mapper restarted after a crash starts
// from the map it had. Exit codes: 0, 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "core/common/error.h"
#include "core/io/robot_loader.h"
#include "procs/mapper/map_journal.h"
#include "procs/mapper/map_seed.h"
#include "procs/mapper/mapper_node.h"
#include "procs/mapper/mapper_options.h"
#include "procs/mapper/octree_dense_states.h"
#include "procs/runtime/process_loop.h"

using namespace topay;
using namespace topay::mapper;

namespace {

struct Flags {
  std::string save, prior, checkpoint, robot_urdf, robot_yaml;
};

MapperOptions ResolveOptions(const procs::ProcessOptions& process, const Flags& f) {
  MapperOptions o = process.config_path.empty() ? MapperOptions{} : LoadMapperOptions(process.config_path);
  const std::string config_dir = procs::ConfigDir(TOPAY_CONFIG_DIR);
  procs::DefaultRobotFiles(config_dir, &o.robot_urdf, &o.robot_yaml);
  if (!f.robot_urdf.empty()) o.robot_urdf = f.robot_urdf;
  if (!f.robot_yaml.empty()) o.robot_yaml = f.robot_yaml;
  if (!f.save.empty()) o.save_path = f.save;
  if (!f.prior.empty()) o.prior_path = f.prior;
  if (!f.checkpoint.empty()) o.checkpoint_path = f.checkpoint;
  return o;
}

// The map a restarted mapper had, from its journal (--checkpoint): true if there was one.
// Throws ConfigError naming the journal if it cannot be read or holds another grid.
bool StartFromJournal(const MapperOptions& options, OccupancyMap* map) {
  if (options.checkpoint_path.empty()) return false;
  const std::optional<JournaledMap> journaled = ReadMapJournal(options.checkpoint_path, options.publish.codec);
  if (!journaled) return false;
  if (!SameGeometry(journaled->geometry, map->geometry())) {
    throw ConfigError(options.checkpoint_path, "", "the map journal holds another grid than the mapper's (config changed?)");
  }
  const std::int64_t seeded = SeedKnownVoxels(VoxelStatesOf(journaled->states), map);
  spdlog::warn("restarted: the map of the journal {} ({} updates, {} voxels known){}", options.checkpoint_path,
               journaled->records, seeded,
               journaled->stopped_early.empty() ? "" : "; its tail was dropped: " + journaled->stopped_early);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"topay-mapper: LiDAR scans to the occupancy map (MAP_UPDATE), PCL filters, OctoMap beside"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-mapper", &process);
  Flags flags;
  app.add_option("--save", flags.save, "write the OctoMap (.bt, octovis opens it) here at exit (SIGINT/SIGTERM)");
  app.add_option("--prior", flags.prior, "start from this OctoMap .bt");
  app.add_option("--checkpoint", flags.checkpoint,
                 "the map journal: every MAP_UPDATE goes into it; a restart starts from its map if it exists");
  app.add_option("--robot", flags.robot_urdf, "robot URDF (default: the config's, else the shipped TopAY robot)");
  app.add_option("--robot-yaml", flags.robot_yaml, "robot YAML (collision model)");
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  MapperOptions options;
  std::unique_ptr<RobotModel> model;
  std::unique_ptr<Kinematics> kinematics;
  std::unique_ptr<ScanMapper> mapper;
  std::optional<OctomapMirror> mirror;
  bool from_journal = false;
  try {
    options = ResolveOptions(process, flags);
    model = std::make_unique<RobotModel>(LoadRobotModel(options.robot_urdf, options.robot_yaml));
    kinematics = std::make_unique<Kinematics>(*model);
    mapper = std::make_unique<ScanMapper>(options.filter, options.map, *kinematics);
    const OctomapMirrorOptions mirror_options = MirrorOptionsOf(options);
    // A journal (a restart) holds the newest map, the prior's voxels included; the OctoMap
    // then starts empty, and --save writes the dense map's states.
    from_journal = StartFromJournal(options, &mapper->mutable_map());
    if (from_journal) {
      if (options.octomap.enabled) mirror.emplace(mirror_options);
    } else if (!options.prior_path.empty()) {
      mirror.emplace(OctomapMirror::LoadPrior(options.prior_path, mirror_options));
      const std::vector<VoxelState> states = DenseStatesFromOcTree(mirror->tree(), mapper->map().geometry());
      const std::int64_t seeded = SeedKnownVoxels(states, &mapper->mutable_map());
      spdlog::info("prior {}: {} voxels known", options.prior_path, seeded);
    } else if (options.octomap.enabled) {
      mirror.emplace(mirror_options);
    }
  } catch (const ConfigError& e) {
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  } catch (const std::exception& e) {  // robot files, the prior's .bt, the journal
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  std::unique_ptr<OctomapWorker> octomap;
  if (mirror && options.octomap.enabled) octomap = std::make_unique<OctomapWorker>(std::move(*mirror));
  const GridGeometry3& g = mapper->map().geometry();
  spdlog::info("{}: map {} x {} x {} voxels of {} m, OctoMap {}, robot {}", process.name, g.dims.x(), g.dims.y(), g.dims.z(),
               g.resolution_m, octomap ? fmt::format("every {} scans", options.octomap.every_n_scans) : "off",
               model->name);
  std::optional<MapJournal> journal;
  if (!options.checkpoint_path.empty()) journal.emplace(options.checkpoint_path);
  MapperNode node(&loop, mapper.get(), octomap.get(), options, journal ? &*journal : nullptr);
  node.Publish(procs::NowUtime(), /*force_snapshot=*/true);  // the prior (or nothing) at once
  const int code = loop.Run();
  std::printf("%s", node.stats().Report().c_str());
  std::fflush(stdout);
  if (!options.save_path.empty()) {
    try {
      if (octomap && !from_journal) {
        octomap->SaveWhenIdle(options.save_path);
      } else {
        const std::vector<VoxelState> states = VoxelStatesOf(mapper->map().states());
        WriteOcTreeFile(*OcTreeFromDenseStates(states, g, MirrorOptionsOf(options)), options.save_path);
      }
      spdlog::info("saved the OctoMap to {}", options.save_path);
    } catch (const std::exception& e) {
      spdlog::error("{}", e.what());
      return procs::kExitConfigError;
    }
  }
  return code;
}
