#include "core/common/heap_retention.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <climits>

namespace topay {

bool RetainFreedHeapMemory(std::size_t max_block_bytes) {
#if defined(__GLIBC__)
  const std::size_t trim = 4 * max_block_bytes;
  if (max_block_bytes > static_cast<std::size_t>(INT_MAX) ||
      trim > static_cast<std::size_t>(INT_MAX)) {
    return false;
  }
  // Fixing either value also stops glibc's dynamic threshold adjustment.
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(max_block_bytes)) == 1 &&
         mallopt(M_TRIM_THRESHOLD, static_cast<int>(trim)) == 1;
#else
  (void)max_block_bytes;
  return false;
#endif
}

}  // namespace topay
