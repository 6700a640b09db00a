#pragma once

#include <optional>
#include <string_view>

namespace topay {

/// The paper's two benchmark rooms (Sec. IV-C): Cuboids and Tables.
enum class SceneKind { kCuboids, kTables };

/// "cuboids" or "tables" (the Scene::kind strings).
std::string_view SceneKindName(SceneKind kind);
/// Inverse of SceneKindName; nullopt for anything else.
std::optional<SceneKind> ParseSceneKind(std::string_view name);

}  // namespace topay
