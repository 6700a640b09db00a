#include "sim/scenes/benchmark_scene.h"

#include "core/common/random.h"
#include "sim/scenes/room_builder.h"

namespace topay {
namespace {

GeneratedScene StartScene(SceneKind kind, std::uint64_t seed) {
  GeneratedScene out;
  out.scene.kind = std::string(SceneKindName(kind));
  out.scene.seed = seed;
  return out;
}

}  // namespace

GeneratedScene GenerateCuboidsScene(std::uint64_t seed, const KeepOutRegions& keep_out,
                                    const CuboidsOptions& options) {
  GeneratedScene out = StartScene(SceneKind::kCuboids, seed);
  Rng rng(seed);
  RoomBuilder builder(options.room, keep_out, &rng, &out);
  builder.AddWalls();
  builder.AddGroundedBoxes(options.grounded);
  builder.AddFloatingCubes(options.floating);
  return out;
}

GeneratedScene GenerateTablesScene(std::uint64_t seed, const KeepOutRegions& keep_out,
                                   const TablesOptions& options) {
  GeneratedScene out = StartScene(SceneKind::kTables, seed);
  Rng rng(seed);
  RoomBuilder builder(options.room, keep_out, &rng, &out);
  builder.AddWalls();
  builder.AddTableGroups(options.tables);
  builder.AddGroundedBoxes(options.grounded);
  return out;
}

GeneratedScene GenerateBenchmarkScene(SceneKind kind, std::uint64_t seed,
                                      const KeepOutRegions& keep_out) {
  return kind == SceneKind::kCuboids ? GenerateCuboidsScene(seed, keep_out)
                                     : GenerateTablesScene(seed, keep_out);
}

}  // namespace topay
