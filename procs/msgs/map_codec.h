#pragma once
// map_update_t <-> the mapper's voxel states (the one map codec): full snapshots and deltas,
// plain (indices / values) or zlib-compressed (the varint payload documented in
// lcmtypes/map_update_t.lcm), and a decoder that checks every field of untrusted messages.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_map_fields.h"
#include "topay/map_update_t.hpp"

namespace topay::msgs {

/// How maps are encoded, and what the decoder accepts.
struct MapCodecOptions {
  /// Encoding: carry the voxels as COMPRESSION_ZLIB (true, default: a 400 x 400 x 32 snapshot
  /// of a mapped room is a few tens of kB instead of 5 MB) or COMPRESSION_NONE (indices /
  /// values, one byte per voxel plus four per delta index).
  bool compress = true;
  /// Encoding: the zlib level, 0 (stored) to 9 (smallest). 1 (default): the varint stream is
  /// already run-length or gap coded, so higher levels save few bytes for much more time
  /// (tests/bench/map_codec_bench.cc, a mapped 400 x 400 x 32 room: level 6 makes the
  /// snapshot 16 % smaller, 53 kB instead of 64 kB, and its encoding 2.5 x slower).
  int zlib_level = 1;
  /// Decoding: the largest grid accepted, in voxels. 2^26 (default, 67 M voxels: 13 x the
  /// 20 x 20 x 1.6 m planning volume at 0.05 m) bounds what a hostile or corrupted message can
  /// make a receiver allocate (one byte per voxel, and at most 5 per payload voxel inflated).
  std::int64_t max_voxels = std::int64_t{1} << 26;
};

/// The message state constant (map_update_t::UNKNOWN, FREE, OCCUPIED) of a voxel state;
/// throws std::invalid_argument for a byte that is not a VoxelState.
std::int8_t MessageValueOf(VoxelState state);

/// A snapshot of every voxel. `states` holds one VoxelState per voxel of `geometry` in its
/// linear order (GridGeometry3::Index). Throws std::invalid_argument for an invalid geometry
/// (GridGeometry3::Validate), a size other than geometry.NumCells() or a byte that is not a
/// VoxelState (naming its index).
map_update_t EncodeFullMap(const GridGeometry3& geometry, std::span<const std::uint8_t> states,
                           std::int64_t utime, std::int64_t map_seq,
                           const MapCodecOptions& options = {});

/// A delta: the voxels `changes` lists, each once with its last state in the list (a voxel
/// listed several times: the last one wins), in increasing linear index. Throws
/// std::invalid_argument for an invalid geometry or a change outside the grid or with a state
/// that is not a VoxelState (naming the change).
map_update_t EncodeMapDelta(const GridGeometry3& geometry, std::span<const VoxelChange> changes,
                            std::int64_t utime, std::int64_t map_seq,
                            const MapCodecOptions& options = {});

/// A decoded full snapshot.
struct DecodedFullMap {
  std::int64_t utime = 0;
  std::int64_t map_seq = 0;
  GridGeometry3 geometry;
  std::vector<std::uint8_t> states;  ///< One VoxelState per voxel, linear order.
};

/// A decoded delta (applies to map_seq - 1).
struct DecodedMapDelta {
  std::int64_t utime = 0;
  std::int64_t map_seq = 0;
  GridGeometry3 geometry;
  /// In message order (increasing index for compressed deltas; a plain delta may list a voxel
  /// more than once, to be applied in order as VoxelMapFields::ApplyChanges does).
  std::vector<VoxelChange> changes;
};

/// The grid a message describes: nullopt with *error naming the field unless the resolution is
/// finite and > 0, the origin finite, every dims entry >= 2 and their product at most
/// options.max_voxels.
std::optional<GridGeometry3> MapGeometryOf(const map_update_t& msg,
                                           const MapCodecOptions& options, std::string* error);

/// The snapshot of a full message (is_full). nullopt with *error ("map_update_t.<field>: ...")
/// for a delta, a bad geometry (MapGeometryOf), an unknown compression code, counts that
/// disagree with each other, the arrays or the geometry, a value that is not a state
/// constant, or a payload that does not inflate to exactly payload_raw_bytes or whose varints
/// are malformed or do not cover exactly every voxel. Never throws for a malformed message.
std::optional<DecodedFullMap> DecodeFullMap(const map_update_t& msg,
                                            const MapCodecOptions& options, std::string* error);

/// The changes of a delta (not is_full). nullopt with *error as DecodeFullMap, and for an
/// index outside the grid, a compressed delta whose indices do not increase, or a change
/// count other than num_payload_voxels.
std::optional<DecodedMapDelta> DecodeMapDelta(const map_update_t& msg,
                                              const MapCodecOptions& options, std::string* error);

}  // namespace topay::msgs
