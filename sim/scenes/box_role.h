#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace topay {

/// What a box of a generated scene is. Written to the scene JSON as the optional "role" key.
enum class BoxRole { kWall, kGroundedBox, kFloatingCube, kTableTop, kTableLeg, kOther };

/// "wall", "grounded_box", "floating_cube", "table_top", "table_leg", "other".
std::string_view BoxRoleName(BoxRole role);
/// Inverse of BoxRoleName; nullopt for an unknown name.
std::optional<BoxRole> ParseBoxRole(std::string_view name);

}  // namespace topay
