#include "sim/scenes/distance_range.h"

namespace topay {

DistanceBounds DistanceRangeBounds(DistanceRange range) {
  switch (range) {
    case DistanceRange::kSmall:
      return {3.0, 8.0};
    case DistanceRange::kMedium:
      return {8.0, 15.0};
    case DistanceRange::kLarge:
      break;
  }
  return {15.0, 30.0};
}

std::string_view DistanceRangeName(DistanceRange range) {
  switch (range) {
    case DistanceRange::kSmall:
      return "small";
    case DistanceRange::kMedium:
      return "medium";
    case DistanceRange::kLarge:
      break;
  }
  return "large";
}

std::optional<DistanceRange> ParseDistanceRange(std::string_view name) {
  for (const DistanceRange range :
       {DistanceRange::kSmall, DistanceRange::kMedium, DistanceRange::kLarge}) {
    if (DistanceRangeName(range) == name) return range;
  }
  return std::nullopt;
}

}  // namespace topay
