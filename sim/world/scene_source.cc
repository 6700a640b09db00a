#include "sim/world/scene_source.h"

#include <exception>

#include "core/common/error.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/scene_json.h"

namespace topay::sim {

std::optional<SceneSource> ParseSceneArgument(const std::string& text, std::uint64_t seed) {
  if (text.empty()) return std::nullopt;
  SceneSource source;
  source.seed = seed;
  if (const std::optional<SceneKind> kind = ParseSceneKind(text)) {
    source.kind = kind;
  } else {
    source.file = text;
  }
  return source;
}

Scene LoadScene(const SceneSource& source, const KeepOutRegions& keep_out) {
  if (!source.kind) return ReadSceneJson(source.file);
  try {
    return GenerateBenchmarkScene(*source.kind, source.seed, keep_out).scene;
  } catch (const std::exception& e) {
    throw ConfigError("--scene " + std::string(SceneKindName(*source.kind)), "seed",
                      "generator failed for seed " + std::to_string(source.seed) + ": " + e.what());
  }
}

std::string Describe(const SceneSource& source) {
  if (!source.kind) return "file " + source.file;
  return std::string(SceneKindName(*source.kind)) + " seed " + std::to_string(source.seed);
}

}  // namespace topay::sim
