#include "sim/scenes/scene_kind.h"

namespace topay {

std::string_view SceneKindName(SceneKind kind) {
  return kind == SceneKind::kCuboids ? "cuboids" : "tables";
}

std::optional<SceneKind> ParseSceneKind(std::string_view name) {
  if (name == "cuboids") return SceneKind::kCuboids;
  if (name == "tables") return SceneKind::kTables;
  return std::nullopt;
}

}  // namespace topay
