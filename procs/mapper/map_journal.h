#pragma once
// The mapper's map on disk while it runs (`--checkpoint FILE`), so that a mapper killed mid-run
// (kill -9, a crash) and restarted by the launcher starts from the map it had, not from an
// empty one (a planner that takes unknown voxels as free would otherwise plan through what
// was mapped before and is out of the LiDAR's view now: docs/reliability.md, finding 21).
//
// The file is a journal of the MAP_UPDATEs the mapper published: records of
//   [uint32 length, little endian][map_update_t, LCM encoded (with its fingerprint)]
// the first a full map, each later one the delta published after it. Each full map starts
// the file afresh (written to FILE.tmp and renamed over FILE, so a crash leaves the old file or
// the new one whole); each delta is appended and handed to the kernel at once (a killed
// process loses nothing; a power cut may tear the last record, which the reader drops).

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/map/grid_geometry.h"
#include "procs/msgs/map_codec.h"
#include "topay/map_update_t.hpp"

namespace topay::mapper {

/// Writes the journal. Not thread safe; movable, not copyable.
class MapJournal {
 public:
  /// Writes nothing until the first full map.
  explicit MapJournal(std::string path);
  ~MapJournal();
  MapJournal(MapJournal&& other) noexcept;
  MapJournal& operator=(MapJournal&&) = delete;
  MapJournal(const MapJournal&) = delete;
  MapJournal& operator=(const MapJournal&) = delete;

  /// Adds one published update: a full map starts the file afresh, a delta is appended (a
  /// delta before the first full map is dropped: it could not be replayed). Throws
  /// std::runtime_error naming the file if it cannot be written (the journal is then closed
  /// until the next full map).
  void Record(const map_update_t& msg);

  const std::string& path() const { return path_; }
  /// Records in the current file (0 before the first full map).
  std::int64_t records() const { return records_; }

 private:
  void StartWith(const std::vector<std::uint8_t>& record);
  void Append(const std::vector<std::uint8_t>& record);
  void Close();

  std::string path_;
  std::FILE* file_ = nullptr;
  std::int64_t records_ = 0;
};

/// The map a journal holds.
struct JournaledMap {
  GridGeometry3 geometry;
  /// One VoxelState per voxel (GridGeometry3::Index order).
  std::vector<std::uint8_t> states;
  std::int64_t utime = 0;    ///< of the newest update replayed (µs)
  std::int64_t records = 0;  ///< records replayed (the full map and the deltas after it)
  /// Empty if every record replayed; otherwise why the replay stopped early (a torn or
  /// unreadable record: the map is the one before it).
  std::string stopped_early;
};

/// The map in the journal at `path`: nullopt if there is no such file (the mapper's first
/// start). Throws ConfigError naming the file if it cannot be read or its first record is not
/// a valid full map; a torn or invalid later record ends the replay there (stopped_early).
std::optional<JournaledMap> ReadMapJournal(const std::string& path, const msgs::MapCodecOptions& options = {});

}  // namespace topay::mapper
