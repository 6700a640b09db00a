#include "procs/mapper/scan_filter_summary.h"

#include <cstdio>

namespace topay::mapper {

std::string ScanFilterSummary::Report() const {
  char line[512];
  std::snprintf(line, sizeof(line),
                "scan filter: %d in, %d non-finite, %d in range, %d above ground, %d not the "
                "robot, %d after voxel grid, %d out\n"
                "  times ms: range %.2f, ground %.2f, self %.2f, voxel %.2f, outlier %.2f, "
                "total %.2f",
                num_input, num_non_finite, num_after_range, num_after_ground, num_after_self,
                num_after_voxel, num_output, range_ms, ground_ms, self_ms, voxel_ms, outlier_ms,
                total_ms);
  std::string report = line;
  if (!warning.empty()) report += "\n  warning: " + warning;
  return report;
}

}  // namespace topay::mapper
