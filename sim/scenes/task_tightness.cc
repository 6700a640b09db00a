#include "sim/scenes/task_tightness.h"

#include <array>
#include <utility>

namespace topay {
namespace {

constexpr std::array<std::pair<TightGoalKind, std::string_view>, 3> kGoalKindNames{{
    {TightGoalKind::kNearBox, "near_box"},
    {TightGoalKind::kOnTable, "on_table"},
    {TightGoalKind::kUnderTable, "under_table"},
}};

constexpr std::array<std::pair<TightBody, std::string_view>, 2> kBodyNames{{
    {TightBody::kBase, "base"},
    {TightBody::kArm, "arm"},
}};

template <typename Enum, std::size_t N>
std::string_view NameIn(const std::array<std::pair<Enum, std::string_view>, N>& names,
                        Enum value) {
  for (const auto& [entry, name] : names) {
    if (entry == value) return name;
  }
  return names.front().second;
}

template <typename Enum, std::size_t N>
std::optional<Enum> ParseIn(const std::array<std::pair<Enum, std::string_view>, N>& names,
                            std::string_view text) {
  for (const auto& [entry, name] : names) {
    if (name == text) return entry;
  }
  return std::nullopt;
}

}  // namespace

std::string_view TightGoalKindName(TightGoalKind kind) { return NameIn(kGoalKindNames, kind); }

std::optional<TightGoalKind> ParseTightGoalKind(std::string_view name) {
  return ParseIn(kGoalKindNames, name);
}

std::string_view TightBodyName(TightBody body) { return NameIn(kBodyNames, body); }

std::optional<TightBody> ParseTightBody(std::string_view name) {
  return ParseIn(kBodyNames, name);
}

}  // namespace topay
