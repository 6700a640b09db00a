#include "sim/scenes/box_role.h"

#include <array>
#include <utility>

namespace topay {
namespace {

constexpr std::array<std::pair<BoxRole, std::string_view>, 6> kRoleNames{{
    {BoxRole::kWall, "wall"},
    {BoxRole::kGroundedBox, "grounded_box"},
    {BoxRole::kFloatingCube, "floating_cube"},
    {BoxRole::kTableTop, "table_top"},
    {BoxRole::kTableLeg, "table_leg"},
    {BoxRole::kOther, "other"},
}};

}  // namespace

std::string_view BoxRoleName(BoxRole role) {
  for (const auto& [value, name] : kRoleNames) {
    if (value == role) return name;
  }
  return "other";
}

std::optional<BoxRole> ParseBoxRole(std::string_view name) {
  for (const auto& [value, role_name] : kRoleNames) {
    if (role_name == name) return value;
  }
  return std::nullopt;
}

}  // namespace topay
