#pragma once
// Differences of time stamps that came from outside (a message's utime may be any int64: a
// hostile or corrupted one), without signed overflow: saturated to the int64 range. Found by the
// estimator_inputs and director_inputs fuzz targets (docs/reliability.md).

#include <cstdint>
#include <limits>

namespace topay {

/// later - earlier (us), saturated to [INT64_MIN, INT64_MAX].
inline std::int64_t StampDifferenceUs(std::int64_t later, std::int64_t earlier) {
  std::int64_t difference = 0;
  if (__builtin_sub_overflow(later, earlier, &difference)) {
    return later > earlier ? std::numeric_limits<std::int64_t>::max() : std::numeric_limits<std::int64_t>::min();
  }
  return difference;
}

}  // namespace topay
