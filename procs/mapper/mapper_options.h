#pragma once
// The options of topay-mapper, from config/mapper/mapper.yaml (every key documented there and
// in docs/mapper.md). Command-line flags override some of them (main.cc).

#include <string>

#include "core/map/occupancy_map.h"
#include "procs/mapper/octomap_mirror.h"
#include "core/robot/robot_state_history.h"
#include "procs/mapper/scan_filter_options.h"
#include "procs/msgs/map_codec.h"

namespace topay::mapper {

/// When MAP_UPDATE goes out and how it is encoded.
struct MapPublishOptions {
  /// A full snapshot at least this often (s); deltas in between. A subscriber that joins late
  /// or missed a delta has the map again within this time; a snapshot costs tens of kB and a
  /// few ms to encode (docs/benchmarks.md), a delta usually a few kB.
  double snapshot_period_s = 5.0;
  /// With no scans (the LiDAR stopped), an update (an empty delta) still goes out after this
  /// long (s), so MAP_UPDATE keeps >= 2 Hz and its receivers see the mapper alive.
  double max_silence_s = 0.5;
  msgs::MapCodecOptions codec;
};

/// The OctoMap kept beside the dense map (octomap_mirror.h).
struct OctomapSideOptions {
  /// Off: no OctoMap at all (--save then writes the dense map's states as an OctoMap).
  bool enabled = true;
  /// One scan in this many goes into the OctoMap, on a background thread at low priority
  /// (insertion costs ~10 x a scan period at 0.05 m: docs/benchmarks.md). 10 = 1 Hz.
  int every_n_scans = 10;
};

struct MapperOptions {
  std::string source = "(built-in defaults)";  ///< the config file, for errors
  std::string robot_urdf;   ///< empty: the shipped TopAY robot (config/robot/)
  std::string robot_yaml;   ///< empty: the shipped one
  OccupancyMapOptions map;  ///< volume, voxel size, sensor model (YAML `map`)
  ScanFilterOptions filter;  ///< YAML `filter`
  RobotStateHistoryOptions robot_state;  ///< YAML `robot_state`
  OctomapSideOptions octomap;  ///< YAML `octomap`
  MapPublishOptions publish;  ///< YAML `publish`
  std::string save_path;   ///< write the OctoMap here at exit (SIGINT/SIGTERM); empty: no
  std::string prior_path;  ///< start from this OctoMap .bt; empty: all unknown
  /// The map journal (map_journal.h): every MAP_UPDATE published goes into it, and a mapper
  /// that starts with one there (restarted after a crash) starts from its map, not from the
  /// prior or an empty map. Empty: none.
  std::string checkpoint_path;
};

/// Loads the YAML at `path`. Throws ConfigError naming the file and key for a missing file,
/// an unknown key, a wrong type or a value out of range.
MapperOptions LoadMapperOptions(const std::string& path);

/// Throws ConfigError naming options.source and the key for inconsistent options.
void CheckMapperOptions(const MapperOptions& options);

/// The OctoMap mirror's options from the dense map's: the same volume, voxel size and sensor
/// model (probabilities from the log-odds: p = 1 / (1 + exp(-l))), and the filter's range.
OctomapMirrorOptions MirrorOptionsOf(const MapperOptions& options);

}  // namespace topay::mapper
