#pragma once
// Where the simulator's scene comes from: a scene file (sim/scenes/scene_json.h) or the seeded
// benchmark generator (`--scene tables --seed N`).

#include <cstdint>
#include <optional>
#include <string>

#include "core/geometry/scene.h"
#include "sim/scenes/keep_out.h"
#include "sim/scenes/scene_kind.h"

namespace topay::sim {

struct SceneSource {
  std::string file;                 ///< a scene JSON file (used when kind is empty)
  std::optional<SceneKind> kind;    ///< a generated benchmark room (cuboids, tables)
  std::uint64_t seed = 1;           ///< the generator's seed
};

/// `--scene` as given on the command line: "tables" or "cuboids" (a generator, with `seed`),
/// anything else a file path. Empty text: nullopt (no scene given).
std::optional<SceneSource> ParseSceneArgument(const std::string& text, std::uint64_t seed);

/// Reads the file or runs the generator (no generated obstacle enters `keep_out`, e.g. a disc
/// around the robot's start). Throws ConfigError naming the file and field (scene_json.h), or
/// ConfigError("--scene <kind>", "seed", ...) if the generator fails.
Scene LoadScene(const SceneSource& source, const KeepOutRegions& keep_out = {});

/// "file scene.json" or "tables seed 3", for logs.
std::string Describe(const SceneSource& source);

}  // namespace topay::sim
