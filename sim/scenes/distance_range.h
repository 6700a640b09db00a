#pragma once

#include <optional>
#include <string_view>

namespace topay {

/// The benchmark's start-goal base distance ranges (paper Sec. IV-C): small 3-8 m, medium
/// 8-15 m, large 15-30 m. The distance is the straight-line distance between the start and
/// goal base positions (not a path length through the room). In the 20 x 20 m room with the
/// 2 m wall margin the largest possible is 16 sqrt(2) = 22.6 m, so "large" is in effect
/// 15-22.6 m.
enum class DistanceRange { kSmall, kMedium, kLarge };

struct DistanceBounds {
  double min_m = 0.0;
  double max_m = 0.0;
  bool Contains(double distance_m) const { return min_m <= distance_m && distance_m <= max_m; }
};

DistanceBounds DistanceRangeBounds(DistanceRange range);
/// "small", "medium", "large".
std::string_view DistanceRangeName(DistanceRange range);
/// Inverse of DistanceRangeName; nullopt for anything else.
std::optional<DistanceRange> ParseDistanceRange(std::string_view name);

}  // namespace topay
