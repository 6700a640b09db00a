#include "core/map/occupancy_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/stopwatch.h"
#include "core/map/voxel_ray.h"

namespace topay {
namespace {

constexpr auto kUnknown = static_cast<std::uint8_t>(VoxelState::kUnknown);
constexpr auto kFree = static_cast<std::uint8_t>(VoxelState::kFree);
constexpr auto kOccupied = static_cast<std::uint8_t>(VoxelState::kOccupied);

void Require(bool ok, const char* field, const char* condition) {
  if (!ok) {
    throw std::invalid_argument(std::string("OccupancyMapOptions::") + field + " must be " +
                                condition);
  }
}

bool IsFinite(const Eigen::Vector3f& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

// Log-odds in fixed point (units of kOccupancyLogOddsUnit).
int ToFixed(float log_odds) { return static_cast<int>(std::lround(log_odds * 1000.0f)); }

// Fixed-point log-odds must stay clear of the int16 range (and its unknown sentinel).
bool InFixedRange(float log_odds) { return std::isfinite(log_odds) && std::abs(log_odds) <= 30.0f; }

}  // namespace

void ValidateOccupancyMapOptions(const OccupancyMapOptions& o) {
  Require(o.bounds_W_m.min().allFinite() && o.bounds_W_m.max().allFinite() &&
              (o.bounds_W_m.min().array() < o.bounds_W_m.max().array()).all(),
          "bounds_W_m", "finite and not empty");
  Require(std::isfinite(o.resolution_m) && o.resolution_m > 0.0, "resolution_m", "finite and > 0");
  Require(InFixedRange(o.log_odds_hit) && ToFixed(o.log_odds_hit) > 0, "log_odds_hit",
          "in (0, 30]");
  Require(InFixedRange(o.log_odds_miss) && ToFixed(o.log_odds_miss) < 0, "log_odds_miss",
          "in [-30, 0)");
  Require(InFixedRange(o.occupied_threshold_log_odds), "occupied_threshold_log_odds",
          "in [-30, 30]");
  Require(InFixedRange(o.log_odds_min) &&
              ToFixed(o.log_odds_min) < ToFixed(o.occupied_threshold_log_odds),
          "log_odds_min", "in [-30, 30] and < occupied_threshold_log_odds");
  Require(InFixedRange(o.log_odds_max) &&
              ToFixed(o.log_odds_max) > ToFixed(o.occupied_threshold_log_odds),
          "log_odds_max", "in [-30, 30] and > occupied_threshold_log_odds");
  Require(std::isfinite(o.max_free_ray_length_m) && o.max_free_ray_length_m > 0.0,
          "max_free_ray_length_m", "finite and > 0");
  Require(std::isfinite(o.max_hit_range_m) && o.max_hit_range_m > 0.0, "max_hit_range_m",
          "finite and > 0");
}

OccupancyMap::OccupancyMap(const OccupancyMapOptions& options) : options_(options) {
  ValidateOccupancyMapOptions(options_);
  geometry_ = GridGeometry3::FromBounds(options_.bounds_W_m, options_.resolution_m);
  hit_ = ToFixed(options_.log_odds_hit);
  miss_ = ToFixed(options_.log_odds_miss);
  min_ = ToFixed(options_.log_odds_min);
  max_ = ToFixed(options_.log_odds_max);
  threshold_ = ToFixed(options_.occupied_threshold_log_odds);
  const auto n = static_cast<std::size_t>(geometry_.NumCells());
  cells_.assign(n, Cell{});
  states_.assign(n, kUnknown);
}

float OccupancyMap::log_odds(int ix, int iy, int iz) const {
  const std::int16_t fixed = cells_[geometry_.Index(ix, iy, iz)].log_odds;
  return fixed == kUnknownLogOdds ? 0.0f : static_cast<float>(fixed) / 1000.0f;
}

std::uint8_t OccupancyMap::StateOf(int log_odds) const {
  if (log_odds == kUnknownLogOdds) return kUnknown;
  return log_odds > threshold_ ? kOccupied : kFree;
}

void OccupancyMap::Set(std::int64_t i, int log_odds, const Eigen::Vector3i& voxel,
                       std::vector<VoxelChange>* changes, int* num_changes) {
  Cell& cell = cells_[i];
  const std::uint8_t before = StateOf(cell.log_odds);
  cell.log_odds = static_cast<std::int16_t>(log_odds);
  const std::uint8_t after = StateOf(log_odds);
  if (after == before) return;
  states_[i] = after;
  ++*num_changes;
  if (changes != nullptr) changes->push_back({voxel, static_cast<VoxelState>(after)});
}

void OccupancyMap::Update(std::int64_t i, int delta, const Eigen::Vector3i& voxel,
                          std::vector<VoxelChange>* changes, int* num_changes) {
  const int log_odds = cells_[i].log_odds == kUnknownLogOdds ? 0 : cells_[i].log_odds;
  // L <- clamp(L + delta, L_min, L_max): the clamped log-odds update (OctoMap's), unknown
  // voxels starting from L = 0 (p = 0.5).
  Set(i, std::clamp(log_odds + delta, min_, max_), voxel, changes, num_changes);
}

void OccupancyMap::NextGeneration() {
  // Two marks per scan (hit, missed); before the counter would pass 0xFFFF, start again from
  // cleared marks so that no stale mark equals a new one.
  if (hit_mark_ > 0xFFFF - 3) {
    for (Cell& cell : cells_) cell.mark = 0;
    hit_mark_ = 0;
  }
  hit_mark_ += 2;
}

ScanInsertSummary OccupancyMap::InsertScan(const Eigen::Vector3d& p_WS,
                                           std::span<const Eigen::Vector3f> p_WP,
                                           std::vector<VoxelChange>* changes) {
  if (!p_WS.allFinite()) {
    throw std::invalid_argument("OccupancyMap::InsertScan: the sensor origin p_WS must be finite");
  }
  const Stopwatch total;
  ScanInsertSummary summary;
  summary.num_points = static_cast<int>(p_WP.size());
  NextGeneration();
  InsertHits(p_WS, p_WP, changes, &summary);
  summary.hits_s = total.ElapsedS();
  const Stopwatch rays;
  InsertMisses(p_WS, p_WP, changes, &summary);
  summary.rays_s = rays.ElapsedS();
  summary.total_s = total.ElapsedS();
  return summary;
}

void OccupancyMap::InsertHits(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP,
                              std::vector<VoxelChange>* changes, ScanInsertSummary* summary) {
  const double max_range_squared = options_.max_hit_range_m * options_.max_hit_range_m;
  for (const Eigen::Vector3f& point : p_WP) {
    if (!IsFinite(point)) {
      ++summary->num_points_skipped;
      continue;
    }
    ++summary->num_points_used;
    const Eigen::Vector3d p_WP_d = point.cast<double>();
    if ((p_WP_d - p_WS).squaredNorm() > max_range_squared) {
      ++summary->num_points_beyond_range;
      continue;
    }
    if (!geometry_.Contains(p_WP_d)) {
      ++summary->num_points_outside;
      continue;
    }
    const Eigen::Vector3i voxel = geometry_.CellOf(p_WP_d);
    const std::int64_t i = geometry_.Index(voxel.x(), voxel.y(), voxel.z());
    if (cells_[i].mark == hit_mark_) continue;  // already hit in this scan
    cells_[i].mark = hit_mark_;
    ++summary->num_voxels_hit;
    Update(i, hit_, voxel, changes, &summary->num_changes);
  }
}

void OccupancyMap::InsertMisses(const Eigen::Vector3d& p_WS,
                                std::span<const Eigen::Vector3f> p_WP,
                                std::vector<VoxelChange>* changes, ScanInsertSummary* summary) {
  const double max_range_m = options_.max_free_ray_length_m;
  const std::uint16_t miss_mark = hit_mark_ + 1;
  std::int64_t steps = 0;
  const auto miss = [&](const Eigen::Vector3i& voxel, std::int64_t i) {
    ++steps;
    // Marks below hit_mark_ are from earlier scans; hit_mark_ (hit) and miss_mark (already
    // missed) are this scan's: each voxel is updated once per scan and a hit wins.
    if (cells_[i].mark >= hit_mark_) return;
    cells_[i].mark = miss_mark;
    ++summary->num_voxels_missed;
    Update(i, miss_, voxel, changes, &summary->num_changes);
  };
  for (const Eigen::Vector3f& point : p_WP) {
    if (!IsFinite(point)) continue;
    const Eigen::Vector3d p_WP_d = point.cast<double>();
    const Eigen::Vector3d d_W = p_WP_d - p_WS;
    const double range_m = d_W.norm();
    // A return beyond the clearing distance clears its ray up to that distance only; a ray to
    // a nearer one ends in the return's own voxel (the hit).
    const Eigen::Vector3d p_WE =
        range_m > max_range_m ? Eigen::Vector3d(p_WS + d_W * (max_range_m / range_m)) : p_WP_d;
    TraverseVoxelRay(geometry_, p_WS, p_WE, miss);
  }
  summary->num_ray_steps = steps;
}

void OccupancyMap::SetVoxel(const Eigen::Vector3i& voxel, float log_odds,
                            std::vector<VoxelChange>* changes) {
  if ((voxel.array() < 0).any() || (voxel.array() >= geometry_.dims.array()).any()) {
    throw std::invalid_argument("OccupancyMap::SetVoxel: voxel outside the grid");
  }
  if (std::isnan(log_odds)) {
    throw std::invalid_argument("OccupancyMap::SetVoxel: log_odds is NaN");
  }
  const std::int64_t i = geometry_.Index(voxel.x(), voxel.y(), voxel.z());
  int num_changes = 0;
  // The prior, clamped (an infinite prior is a certain one) and in fixed point.
  const int fixed = ToFixed(std::clamp(log_odds, -30.0f, 30.0f));
  Set(i, std::clamp(fixed, min_, max_), voxel, changes, &num_changes);
}

void OccupancyMap::Reset(std::vector<VoxelChange>* changes) {
  const Eigen::Vector3i& n = geometry_.dims;
  std::int64_t i = 0;
  for (int iz = 0; iz < n.z(); ++iz)
    for (int iy = 0; iy < n.y(); ++iy)
      for (int ix = 0; ix < n.x(); ++ix, ++i) {
        cells_[i].log_odds = kUnknownLogOdds;
        if (states_[i] == kUnknown) continue;
        states_[i] = kUnknown;
        if (changes != nullptr) changes->push_back({{ix, iy, iz}, VoxelState::kUnknown});
      }
}

VoxelStateCounts OccupancyMap::CountStates() const {
  VoxelStateCounts counts;
  for (const std::uint8_t s : states_) {
    counts.occupied += s == kOccupied;
    counts.free += s == kFree;
  }
  counts.unknown = static_cast<std::int64_t>(states_.size()) - counts.occupied - counts.free;
  return counts;
}

}  // namespace topay
