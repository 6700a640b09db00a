#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_state.h"

namespace topay {

/// The volume, voxel size and sensor model of an OccupancyMap. Log-odds are natural
/// logarithms of p / (1 - p) of occupancy; a voxel never observed has log-odds 0 (p = 0.5).
/// The map stores them in fixed point, units of 0.001 (kOccupancyLogOddsUnit): every log-odds
/// option is rounded to that (the defaults are exact), and must lie in [-30, 30].
struct OccupancyMapOptions {
  /// The mapped volume (m): the benchmark room, 20 x 20 x 1.6 m. Must be finite, not empty.
  Eigen::AlignedBox3d bounds_W_m{Eigen::Vector3d(-10.0, -10.0, 0.0),
                                 Eigen::Vector3d(10.0, 10.0, 1.6)};
  /// Voxel size (m): 0.05 m, the planner's 3D field (VoxelMapFieldsOptions::resolution_m).
  /// Finite, > 0.
  double resolution_m = 0.05;
  /// Added to a voxel holding a return: 0.85 = logit(0.7), OctoMap's prob_hit. In (0, 30].
  float log_odds_hit = 0.85f;
  /// Added to a voxel a ray passes through: -0.4 = logit(0.4), OctoMap's prob_miss.
  /// In [-30, 0).
  float log_odds_miss = -0.4f;
  /// Clamping bounds: -2.0 = logit(0.12) and 3.5 = logit(0.97), OctoMap's clamping
  /// thresholds. They bound how long a voxel remembers: an occupied voxel at the maximum turns
  /// free after ceil((max - threshold) / -miss) scans that see through it (9 at the
  /// defaults), a free one at the minimum turns occupied after floor((threshold - min) / hit)
  /// + 1 scans with a return in it (3). In [-30, 30], min < threshold < max.
  float log_odds_min = -2.0f;
  float log_odds_max = 3.5f;
  /// An observed voxel is occupied when its log-odds are above this, free otherwise (0: p > 0.5;
  /// no hysteresis: the clamping bounds already keep a voxel from flickering on one odd scan).
  /// In [-30, 30].
  float occupied_threshold_log_odds = 0.0f;
  /// Free-space clearing reaches this far from the sensor (m): a return farther away clears
  /// its ray up to this distance only. The rays' walk is the insertion's main cost (its
  /// length in voxels per point), and what lies farther is cleared as the robot comes nearer.
  /// 10 m by default. Finite, > 0.
  double max_free_ray_length_m = 10.0;
  /// Returns up to this far from the sensor (m) mark their voxel occupied, even beyond the
  /// clearing distance (a far obstacle is in the map before the robot gets near it); farther
  /// ones mark nothing. 20 m by default (the scan filter's range). Finite, > 0.
  double max_hit_range_m = 20.0;
};

/// The fixed-point unit of OccupancyMap's log-odds.
inline constexpr float kOccupancyLogOddsUnit = 0.001f;

/// Throws std::invalid_argument naming the first invalid field (e.g. "OccupancyMapOptions::
/// log_odds_miss must be in [-30, 0)").
void ValidateOccupancyMapOptions(const OccupancyMapOptions& options);

/// What one InsertScan did: counts and wall-clock times (steady clock, s).
struct ScanInsertSummary {
  int num_points = 0;               ///< Points given.
  int num_points_used = 0;          ///< Finite points: each casts its ray.
  int num_points_skipped = 0;       ///< Points with a NaN or infinite coordinate, ignored.
  int num_points_outside = 0;       ///< Used points in range outside the bounds: no hit.
  int num_points_beyond_range = 0;  ///< Used points farther than max_free_ray_length_m.
  int num_voxels_hit = 0;           ///< Distinct voxels updated with a hit.
  int num_voxels_missed = 0;        ///< Distinct voxels updated with a miss.
  std::int64_t num_ray_steps = 0;   ///< Voxels walked over all rays (repeats included).
  int num_changes = 0;              ///< Voxels whose VoxelState changed (appended).
  double hits_s = 0.0;              ///< Marking the returns' voxels.
  double rays_s = 0.0;              ///< Walking the rays.
  double total_s = 0.0;
};

/// How many voxels are in each state.
struct VoxelStateCounts {
  std::int64_t occupied = 0;
  std::int64_t free = 0;
  std::int64_t unknown = 0;
};

/// A dense probabilistic occupancy map (as ROG-Map's): per-voxel log-odds updated by the
/// returns of LiDAR scans and the free space along their rays, with a VoxelState byte per
/// voxel (kUnknown until observed, then kOccupied or kFree by the threshold) that
/// changes are reported on, to feed VoxelMapFields::ApplyChanges and the MAP_UPDATE deltas.
///
/// Storage: flat arrays in the GridGeometry3 order (x fastest, i = ix + nx (iy + ny iz)): per
/// voxel a 4-byte cell (the log-odds as int16 in units of 0.001, or a sentinel while unknown,
/// and the 16-bit per-scan mark: the ray walk touches one cache line per voxel) and the state
/// byte (written only when it changes): 5 bytes a voxel, 26 MB for the default 400 x 400 x 32
/// grid. Fixed point makes the update exact integer arithmetic (0.85 + 0.85 - 0.4 is 1.3).
///
/// Per scan (InsertScan), each voxel is updated at most once and a hit wins over a miss: the
/// returns' voxels are marked and updated first, then each ray is walked (TraverseVoxelRay)
/// and every voxel on it neither hit nor already missed in this scan is updated with a miss.
/// The marks are generation numbers (2 per scan), so nothing is cleared per scan; the mark
/// array is cleared once when the counter wraps (every 32,767 scans, ~55 min at 10 Hz).
/// No allocation per scan but the appended changes (the caller's vector keeps its capacity).
/// Not thread safe.
class OccupancyMap {
 public:
  /// Every voxel unknown (log-odds 0). Throws std::invalid_argument for invalid options.
  explicit OccupancyMap(const OccupancyMapOptions& options = {});

  const OccupancyMapOptions& options() const { return options_; }
  const GridGeometry3& geometry() const { return geometry_; }

  /// Integrates one scan: `p_WP` are the returns (filtered, in W) of a sensor at p_WS.
  /// A return within max_free_ray_length_m of the sensor and inside the bounds is a hit in
  /// its voxel; every return's ray p_WS -> p_WP (cut at max_free_ray_length_m) clears the
  /// voxels it crosses inside the bounds (the in-bounds part of a ray to a return outside
  /// them too). Points with a NaN or infinite coordinate are skipped and counted. Appends to
  /// `changes` (if not null) every voxel whose state changed, once each. Throws
  /// std::invalid_argument if p_WS is not finite (the map is then unchanged).
  ScanInsertSummary InsertScan(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP,
                               std::vector<VoxelChange>* changes);

  VoxelState state(int ix, int iy, int iz) const {
    return static_cast<VoxelState>(states_[geometry_.Index(ix, iy, iz)]);
  }
  /// The voxel's log-odds (0 while unknown), a multiple of kOccupancyLogOddsUnit.
  float log_odds(int ix, int iy, int iz) const;
  /// Every voxel's VoxelState byte, indexed by geometry().Index(ix, iy, iz).
  std::span<const std::uint8_t> states() const { return states_; }

  /// Seeds one voxel from a prior map (e.g. an OctoMap .bt): sets its log-odds (clamped to
  /// [log_odds_min, log_odds_max]) and marks it observed; appends the change to `changes` (if
  /// not null) when its state changed. Throws std::invalid_argument for a voxel outside the
  /// grid or a NaN log-odds.
  void SetVoxel(const Eigen::Vector3i& voxel, float log_odds, std::vector<VoxelChange>* changes);

  /// Forgets everything: every voxel unknown, log-odds 0. Appends the voxels that were
  /// observed (now unknown) to `changes` if not null.
  void Reset(std::vector<VoxelChange>* changes);

  VoxelStateCounts CountStates() const;

 private:
  // One voxel as the ray walk touches it: log-odds (fixed point, kUnknownLogOdds while
  // unknown) and the scan mark side by side.
  struct Cell {
    std::int16_t log_odds = kUnknownLogOdds;
    std::uint16_t mark = 0;
  };
  static constexpr std::int16_t kUnknownLogOdds = -32768;

  // The state of a voxel with these fixed-point log-odds.
  std::uint8_t StateOf(int log_odds) const;
  // Sets voxel i's log-odds (fixed point, within the clamps); a state change is counted and
  // appended to `changes`.
  void Set(std::int64_t i, int log_odds, const Eigen::Vector3i& voxel,
           std::vector<VoxelChange>* changes, int* num_changes);
  // Adds `delta` (fixed point) to voxel i's log-odds (0 if unknown), clamped, and Sets it.
  void Update(std::int64_t i, int delta, const Eigen::Vector3i& voxel,
              std::vector<VoxelChange>* changes, int* num_changes);
  // Starts a scan's marks: hit_mark_ and hit_mark_ + 1 are unused in the mark array.
  void NextGeneration();
  // Marks and updates the returns' voxels (counted in `summary`).
  void InsertHits(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP,
                  std::vector<VoxelChange>* changes, ScanInsertSummary* summary);
  // Walks every ray and updates the voxels not marked in this scan with a miss.
  void InsertMisses(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP,
                    std::vector<VoxelChange>* changes, ScanInsertSummary* summary);

  OccupancyMapOptions options_;
  GridGeometry3 geometry_;
  // The options in fixed point.
  int hit_ = 0, miss_ = 0, min_ = 0, max_ = 0, threshold_ = 0;
  std::vector<Cell> cells_;  // mark hit_mark_: hit this scan; hit_mark_ + 1: missed
  std::vector<std::uint8_t> states_;
  std::uint16_t hit_mark_ = 0;
};

}  // namespace topay
