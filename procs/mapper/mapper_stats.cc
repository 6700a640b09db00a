#include "procs/mapper/mapper_stats.h"

#include <cstdio>

#include "core/common/sample_statistics.h"

namespace topay::mapper {
namespace {

std::string Line(const char* what, const std::vector<double>& v, const char* unit) {
  char text[160];
  std::snprintf(text, sizeof(text), "  %-22s median %8.2f  p95 %8.2f  max %8.2f %s (n %zu)\n", what, Median(v),
                NearestRankQuantile(v, 0.95), NearestRankQuantile(v, 1.0), unit, v.size());
  return text;
}

double Last(const std::vector<double>& v) { return v.empty() ? 0.0 : v.back(); }

}  // namespace

void AddSample(std::vector<double>* sample, double value) {
  if (sample->size() >= 2 * kMaxSamples) sample->erase(sample->begin(), sample->begin() + kMaxSamples);
  sample->push_back(value);
}

void MapperStats::AddScan(const ScanMapperSummary& s) {
  points_non_finite += s.filter.num_non_finite;
  if (s.filter.self_filter_skipped) ++scans_without_state;
  AddSample(&range_ms, s.filter.range_ms);
  AddSample(&ground_ms, s.filter.ground_ms);
  AddSample(&self_ms, s.filter.self_ms);
  AddSample(&voxel_ms, s.filter.voxel_ms);
  AddSample(&outlier_ms, s.filter.outlier_ms);
  AddSample(&filter_ms, s.filter.total_ms);
  AddSample(&insert_ms, s.insert.total_s * 1e3);
  AddSample(&changes, s.insert.num_changes);
}

std::string MapperStats::StatusLine(const VoxelStateCounts& counts) const {
  char text[256];
  std::snprintf(text, sizeof(text),
                "occupied %lld free %lld unknown %lld; scans %lld (rejected %lld); updates %lld; last scan ms: "
                "filter %.1f insert %.1f encode %.1f total %.1f",
                static_cast<long long>(counts.occupied), static_cast<long long>(counts.free),
                static_cast<long long>(counts.unknown), static_cast<long long>(clouds),
                static_cast<long long>(clouds_rejected), static_cast<long long>(updates), Last(filter_ms),
                Last(insert_ms), Last(encode_ms), Last(scan_to_update_ms));
  return text;
}

std::string MapperStats::Report() const {
  char head[384];
  std::snprintf(head, sizeof(head),
                "topay-mapper: %lld clouds (%lld rejected, %lld NaN points dropped, %lld without a robot "
                "state), %lld MAP_UPDATEs (%lld snapshots, %lld not journaled), %lld bad ROBOT_STATEs\n",
                static_cast<long long>(clouds), static_cast<long long>(clouds_rejected),
                static_cast<long long>(points_non_finite), static_cast<long long>(scans_without_state),
                static_cast<long long>(updates), static_cast<long long>(snapshots),
                static_cast<long long>(journal_errors), static_cast<long long>(states_rejected));
  return head + Line("filter: range", range_ms, "ms") + Line("filter: ground", ground_ms, "ms") +
         Line("filter: self", self_ms, "ms") + Line("filter: voxel grid", voxel_ms, "ms") +
         Line("filter: outliers", outlier_ms, "ms") + Line("filter: total", filter_ms, "ms") +
         Line("map insertion", insert_ms, "ms") + Line("delta encoding", encode_ms, "ms") +
         Line("scan in -> MAP_UPDATE", scan_to_update_ms, "ms") + Line("changes per scan", changes, "") +
         Line("delta bytes", delta_bytes, "B") + Line("snapshot bytes", snapshot_bytes, "B") +
         Line("snapshot encoding", snapshot_encode_ms, "ms");
}

}  // namespace topay::mapper
