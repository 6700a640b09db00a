#include "procs/msgs/map_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "procs/msgs/zlib_buffer.h"

namespace topay::msgs {
namespace {

// Payload state codes (lcmtypes/map_update_t.lcm): code = message value + 1.
constexpr std::uint8_t kCodeOfState[3] = {1, 2, 0};  // kFree, kOccupied, kUnknown
constexpr std::uint8_t kStateOfCode[3] = {2, 0, 1};  // UNKNOWN, FREE, OCCUPIED
constexpr int kMaxVarintBytes = 5;
constexpr std::uint64_t kMaxVarint = std::uint64_t{1} << 35;

bool Fail(std::string* error, const std::string& field_and_reason) {
  *error = "map_update_t." + field_and_reason;
  return false;
}

bool IsState(std::uint8_t state) { return state <= 2; }

void AppendVarint(std::uint64_t v, std::vector<std::uint8_t>* out) {
  while (v >= 0x80) {
    out->push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  out->push_back(static_cast<std::uint8_t>(v));
}

// Reads the LEB128 varints of an inflated payload.
class VarintReader {
 public:
  explicit VarintReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  bool done() const { return pos_ == bytes_.size(); }
  // The next (count, code); false with *error at a truncated, overlong or zero-count varint or
  // code 3.
  bool Next(std::uint64_t* count, std::uint8_t* code, std::string* error) {
    const std::size_t start = pos_;
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      if (pos_ == bytes_.size()) return Fail(error, At(start) + "truncated varint");
      if (shift == 7 * kMaxVarintBytes) return Fail(error, At(start) + "varint above 5 bytes");
      const std::uint8_t byte = bytes_[pos_++];
      v |= std::uint64_t{byte & 0x7fu} << shift;
      if ((byte & 0x80) == 0) break;
    }
    if (v >= kMaxVarint) return Fail(error, At(start) + "varint above 2^35");
    *code = static_cast<std::uint8_t>(v & 3);
    *count = v >> 2;
    if (*code == 3) return Fail(error, At(start) + "state code 3 (not a state)");
    if (*count == 0) return Fail(error, At(start) + "count 0");
    return true;
  }

 private:
  static std::string At(std::size_t pos) {
    return "payload (inflated byte " + std::to_string(pos) + "): ";
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

void SetHeader(const GridGeometry3& geometry, std::int64_t utime, std::int64_t map_seq,
               bool is_full, map_update_t* msg) {
  msg->utime = utime;
  msg->map_seq = map_seq;
  msg->resolution_m = geometry.resolution_m;
  for (int a = 0; a < 3; ++a) {
    msg->origin_W[a] = geometry.origin_W_m(a);
    msg->dims[a] = geometry.dims(a);
  }
  msg->is_full = is_full;
  msg->num_indices = msg->num_values = 0;
  msg->compression = map_update_t::COMPRESSION_NONE;
  msg->num_payload_voxels = msg->payload_raw_bytes = msg->num_payload_bytes = 0;
}

void SetPayload(std::span<const std::uint8_t> raw, std::int64_t num_voxels,
                const MapCodecOptions& options, map_update_t* msg) {
  msg->compression = map_update_t::COMPRESSION_ZLIB;
  msg->num_payload_voxels = static_cast<std::int32_t>(num_voxels);
  msg->payload_raw_bytes = static_cast<std::int32_t>(raw.size());
  msg->payload = ZlibDeflate(raw, options.zlib_level);
  msg->num_payload_bytes = static_cast<std::int32_t>(msg->payload.size());
}

// The end of the run of equal bytes starting at `begin`, eight bytes at a time where it can.
std::size_t RunEnd(std::span<const std::uint8_t> states, std::size_t begin) {
  const std::uint8_t value = states[begin];
  const std::uint64_t splat = value * 0x0101010101010101ull;
  std::size_t end = begin + 1;
  while (end + 8 <= states.size()) {
    std::uint64_t word = 0;
    std::memcpy(&word, states.data() + end, 8);
    if (word != splat) break;
    end += 8;
  }
  while (end < states.size() && states[end] == value) ++end;
  return end;
}

// The run varints of a full payload; throws at a byte that is not a VoxelState.
std::vector<std::uint8_t> RunVarints(std::span<const std::uint8_t> states) {
  std::vector<std::uint8_t> raw;
  raw.reserve(4096);
  for (std::size_t begin = 0; begin < states.size();) {
    if (!IsState(states[begin])) {
      throw std::invalid_argument("EncodeFullMap: states[" + std::to_string(begin) + "] = " +
                                  std::to_string(states[begin]) + " is not a VoxelState");
    }
    const std::size_t end = RunEnd(states, begin);
    AppendVarint((std::uint64_t{end - begin} << 2) | kCodeOfState[states[begin]], &raw);
    begin = end;
  }
  return raw;
}

// A change by linear index.
struct IndexedChange {
  std::int32_t index;
  std::uint8_t state;
};

// Sorts by index, keeping the list order among equal indices (least significant digit radix
// sort, 12 bits per pass: two passes for grids below 2^24 voxels).
void StableSortByIndex(std::vector<IndexedChange>* changes) {
  constexpr int kBits = 12;
  constexpr std::uint32_t kMask = (1u << kBits) - 1;
  std::uint32_t max_index = 0;
  for (const IndexedChange& c : *changes) max_index = std::max<std::uint32_t>(max_index, c.index);
  std::vector<IndexedChange> sorted(changes->size());
  std::vector<std::uint32_t> start(kMask + 2);
  for (int shift = 0; shift < 32 && (max_index >> shift) != 0; shift += kBits) {
    std::fill(start.begin(), start.end(), 0u);
    for (const IndexedChange& c : *changes) ++start[((c.index >> shift) & kMask) + 1];
    for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (const IndexedChange& c : *changes) sorted[start[(c.index >> shift) & kMask]++] = c;
    changes->swap(sorted);
  }
}

// Each voxel of `changes` once, with its last state, by increasing index.
std::vector<IndexedChange> SortedUniqueChanges(const GridGeometry3& geometry,
                                               std::span<const VoxelChange> changes) {
  std::vector<IndexedChange> indexed(changes.size());
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const VoxelChange& change = changes[k];
    const Eigen::Vector3i& v = change.voxel;
    if ((v.array() < 0).any() || (v.array() >= geometry.dims.array()).any() ||
        !IsState(static_cast<std::uint8_t>(change.state))) {
      throw std::invalid_argument("EncodeMapDelta: changes[" + std::to_string(k) +
                                  "] is outside the grid or not a VoxelState");
    }
    indexed[k] = {static_cast<std::int32_t>(geometry.Index(v.x(), v.y(), v.z())),
                  static_cast<std::uint8_t>(change.state)};
  }
  StableSortByIndex(&indexed);
  // The last of each run of equal indices wins.
  std::size_t kept = 0;
  for (std::size_t j = 0; j < indexed.size(); ++j) {
    if (j + 1 < indexed.size() && indexed[j + 1].index == indexed[j].index) continue;
    indexed[kept++] = indexed[j];
  }
  indexed.resize(kept);
  return indexed;
}

std::vector<std::uint8_t> GapVarints(std::span<const IndexedChange> changes) {
  std::vector<std::uint8_t> raw;
  raw.reserve(2 * changes.size() + 16);
  std::int64_t previous = -1;
  for (const IndexedChange& change : changes) {
    const auto gap = static_cast<std::uint64_t>(change.index - previous);
    AppendVarint((gap << 2) | kCodeOfState[change.state], &raw);
    previous = change.index;
  }
  return raw;
}

Eigen::Vector3i VoxelOf(const GridGeometry3& geometry, std::int64_t index) {
  const std::int64_t nx = geometry.dims.x(), ny = geometry.dims.y();
  return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
          static_cast<int>(index / (nx * ny))};
}

bool StateOfValue(std::int8_t value, std::uint8_t* state) {
  if (value < map_update_t::UNKNOWN || value > map_update_t::OCCUPIED) return false;
  *state = kStateOfCode[value + 1];
  return true;
}

// --- Decoding -----------------------------------------------------------------------------

bool CheckArraySizes(const map_update_t& msg, std::string* error) {
  if (msg.num_indices < 0 || static_cast<std::size_t>(msg.num_indices) != msg.indices.size()) {
    return Fail(error, "num_indices: " + std::to_string(msg.num_indices) + " for " +
                           std::to_string(msg.indices.size()) + " indices");
  }
  if (msg.num_values < 0 || static_cast<std::size_t>(msg.num_values) != msg.values.size()) {
    return Fail(error, "num_values: " + std::to_string(msg.num_values) + " for " +
                           std::to_string(msg.values.size()) + " values");
  }
  if (msg.num_payload_bytes < 0 ||
      static_cast<std::size_t>(msg.num_payload_bytes) != msg.payload.size()) {
    return Fail(error, "num_payload_bytes: " + std::to_string(msg.num_payload_bytes) + " for " +
                           std::to_string(msg.payload.size()) + " bytes");
  }
  return true;
}

// The counts of a COMPRESSION_NONE message: payload fields zero; a full map has every value
// and no index, a delta as many indices as values (at most max_voxels).
bool CheckPlainCounts(const map_update_t& msg, std::int64_t num_voxels,
                      const MapCodecOptions& options, std::string* error) {
  if (msg.num_payload_voxels != 0 || msg.payload_raw_bytes != 0 || msg.num_payload_bytes != 0) {
    return Fail(error, "num_payload_voxels/payload_raw_bytes/num_payload_bytes: must be 0 "
                       "with COMPRESSION_NONE");
  }
  if (msg.is_full && (msg.num_indices != 0 || msg.num_values != num_voxels)) {
    return Fail(error, "num_values: " + std::to_string(msg.num_values) + " values and " +
                           std::to_string(msg.num_indices) + " indices for a full map of " +
                           std::to_string(num_voxels) + " voxels");
  }
  if (!msg.is_full && (msg.num_indices != msg.num_values || msg.num_values > options.max_voxels)) {
    return Fail(error, "num_indices: " + std::to_string(msg.num_indices) + " indices for " +
                           std::to_string(msg.num_values) + " values in a delta");
  }
  return true;
}

// The counts of a COMPRESSION_ZLIB message, and payload_raw_bytes within what its varints take.
bool CheckZlibCounts(const map_update_t& msg, std::int64_t num_voxels, std::string* error) {
  if (msg.num_indices != 0 || msg.num_values != 0) {
    return Fail(error, "num_indices/num_values: must be 0 with COMPRESSION_ZLIB");
  }
  if (msg.is_full && msg.num_payload_voxels != num_voxels) {
    return Fail(error, "num_payload_voxels: " + std::to_string(msg.num_payload_voxels) +
                           " in a full map of " + std::to_string(num_voxels) + " voxels");
  }
  if (msg.num_payload_voxels < 0 || msg.num_payload_voxels > num_voxels) {
    return Fail(error, "num_payload_voxels: " + std::to_string(msg.num_payload_voxels) +
                           " changes in a grid of " + std::to_string(num_voxels) + " voxels");
  }
  // A run of n voxels takes at most n bytes; a change at most kMaxVarintBytes.
  const std::int64_t max_raw = msg.is_full ? std::int64_t{msg.num_payload_voxels}
                                           : std::int64_t{kMaxVarintBytes} * msg.num_payload_voxels;
  const std::int64_t min_raw = msg.is_full ? 1 : msg.num_payload_voxels;
  if (msg.payload_raw_bytes < min_raw || msg.payload_raw_bytes > max_raw) {
    return Fail(error, "payload_raw_bytes: " + std::to_string(msg.payload_raw_bytes) +
                           " outside [" + std::to_string(min_raw) + ", " +
                           std::to_string(max_raw) + "] for " +
                           std::to_string(msg.num_payload_voxels) + " payload voxels");
  }
  return true;
}

bool CheckCounts(const map_update_t& msg, std::int64_t num_voxels,
                 const MapCodecOptions& options, std::string* error) {
  if (!CheckArraySizes(msg, error)) return false;
  switch (msg.compression) {
    case map_update_t::COMPRESSION_NONE:
      return CheckPlainCounts(msg, num_voxels, options, error);
    case map_update_t::COMPRESSION_ZLIB:
      return CheckZlibCounts(msg, num_voxels, error);
    default:
      return Fail(error, "compression: " + std::to_string(msg.compression) +
                             " is not a COMPRESSION_* constant");
  }
}

bool InflatePayload(const map_update_t& msg, std::vector<std::uint8_t>* raw,
                    std::string* error) {
  std::string reason;
  if (!ZlibInflateExactly(msg.payload, static_cast<std::size_t>(msg.payload_raw_bytes), raw,
                          &reason)) {
    return Fail(error, "payload: " + reason);
  }
  return true;
}

bool DecodeRuns(std::span<const std::uint8_t> raw, std::int64_t num_voxels,
                std::vector<std::uint8_t>* states, std::string* error) {
  states->resize(static_cast<std::size_t>(num_voxels));
  VarintReader reader(raw);
  std::uint64_t filled = 0, count = 0;
  std::uint8_t code = 0;
  while (!reader.done()) {
    if (!reader.Next(&count, &code, error)) return false;
    if (count > static_cast<std::uint64_t>(num_voxels) - filled) {
      return Fail(error, "payload: runs cover more than the " + std::to_string(num_voxels) +
                             " voxels");
    }
    std::memset(states->data() + filled, kStateOfCode[code], count);
    filled += count;
  }
  if (filled != static_cast<std::uint64_t>(num_voxels)) {
    return Fail(error, "payload: runs cover " + std::to_string(filled) + " of " +
                           std::to_string(num_voxels) + " voxels");
  }
  return true;
}

bool DecodeGaps(std::span<const std::uint8_t> raw, const GridGeometry3& geometry,
                std::int32_t num_changes, std::vector<VoxelChange>* changes,
                std::string* error) {
  changes->reserve(static_cast<std::size_t>(num_changes));
  VarintReader reader(raw);
  std::int64_t index = -1;
  std::uint64_t gap = 0;
  std::uint8_t code = 0;
  while (!reader.done()) {
    if (!reader.Next(&gap, &code, error)) return false;
    const std::string at = "payload: change " + std::to_string(changes->size());
    if (changes->size() == static_cast<std::size_t>(num_changes)) {
      return Fail(error, at + " is beyond num_payload_voxels");
    }
    if (gap >= static_cast<std::uint64_t>(geometry.NumCells() - index)) {
      return Fail(error, at + " lies outside the grid");
    }
    index += static_cast<std::int64_t>(gap);
    changes->push_back({VoxelOf(geometry, index), static_cast<VoxelState>(kStateOfCode[code])});
  }
  if (changes->size() != static_cast<std::size_t>(num_changes)) {
    return Fail(error, "num_payload_voxels: " + std::to_string(num_changes) +
                           " changes declared, the payload holds " +
                           std::to_string(changes->size()));
  }
  return true;
}

bool DecodePlainStates(const map_update_t& msg, std::vector<std::uint8_t>* states,
                       std::string* error) {
  states->resize(msg.values.size());
  for (std::size_t i = 0; i < msg.values.size(); ++i) {
    if (!StateOfValue(msg.values[i], &(*states)[i])) {
      return Fail(error, "values[" + std::to_string(i) + "]: " + std::to_string(msg.values[i]) +
                             " is not a state constant");
    }
  }
  return true;
}

bool DecodePlainChanges(const map_update_t& msg, const GridGeometry3& geometry,
                        std::vector<VoxelChange>* changes, std::string* error) {
  changes->resize(msg.indices.size());
  for (std::size_t k = 0; k < msg.indices.size(); ++k) {
    std::uint8_t state = 0;
    if (msg.indices[k] < 0 || msg.indices[k] >= geometry.NumCells()) {
      return Fail(error, "indices[" + std::to_string(k) + "]: " +
                             std::to_string(msg.indices[k]) + " lies outside the grid");
    }
    if (!StateOfValue(msg.values[k], &state)) {
      return Fail(error, "values[" + std::to_string(k) + "]: " + std::to_string(msg.values[k]) +
                             " is not a state constant");
    }
    (*changes)[k] = {VoxelOf(geometry, msg.indices[k]), static_cast<VoxelState>(state)};
  }
  return true;
}

}  // namespace

std::int8_t MessageValueOf(VoxelState state) {
  if (!IsState(static_cast<std::uint8_t>(state))) {
    throw std::invalid_argument("MessageValueOf: " +
                                std::to_string(static_cast<int>(state)) + " is not a VoxelState");
  }
  return static_cast<std::int8_t>(kCodeOfState[static_cast<std::uint8_t>(state)] - 1);
}

map_update_t EncodeFullMap(const GridGeometry3& geometry, std::span<const std::uint8_t> states,
                           std::int64_t utime, std::int64_t map_seq,
                           const MapCodecOptions& options) {
  geometry.Validate("EncodeFullMap");
  if (static_cast<std::int64_t>(states.size()) != geometry.NumCells()) {
    throw std::invalid_argument("EncodeFullMap: " + std::to_string(states.size()) +
                                " states for " + std::to_string(geometry.NumCells()) + " voxels");
  }
  map_update_t msg;
  SetHeader(geometry, utime, map_seq, true, &msg);
  if (options.compress) {
    SetPayload(RunVarints(states), geometry.NumCells(), options, &msg);
    return msg;
  }
  msg.values.resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!IsState(states[i])) {
      throw std::invalid_argument("EncodeFullMap: states[" + std::to_string(i) +
                                  "] is not a VoxelState");
    }
    msg.values[i] = MessageValueOf(static_cast<VoxelState>(states[i]));
  }
  msg.num_values = static_cast<std::int32_t>(msg.values.size());
  return msg;
}

map_update_t EncodeMapDelta(const GridGeometry3& geometry, std::span<const VoxelChange> changes,
                            std::int64_t utime, std::int64_t map_seq,
                            const MapCodecOptions& options) {
  geometry.Validate("EncodeMapDelta");
  const std::vector<IndexedChange> unique = SortedUniqueChanges(geometry, changes);
  map_update_t msg;
  SetHeader(geometry, utime, map_seq, false, &msg);
  if (options.compress) {
    SetPayload(GapVarints(unique), static_cast<std::int64_t>(unique.size()), options, &msg);
    return msg;
  }
  msg.indices.reserve(unique.size());
  msg.values.reserve(unique.size());
  for (const IndexedChange& change : unique) {
    msg.indices.push_back(change.index);
    msg.values.push_back(MessageValueOf(static_cast<VoxelState>(change.state)));
  }
  msg.num_indices = msg.num_values = static_cast<std::int32_t>(unique.size());
  return msg;
}

std::optional<GridGeometry3> MapGeometryOf(const map_update_t& msg,
                                           const MapCodecOptions& options, std::string* error) {
  GridGeometry3 geometry;
  if (!(std::isfinite(msg.resolution_m) && msg.resolution_m > 0.0)) {
    Fail(error, "resolution_m: " + std::to_string(msg.resolution_m) + " (finite and > 0)");
    return std::nullopt;
  }
  std::int64_t num_voxels = 1;
  for (int a = 0; a < 3; ++a) {
    const std::string at = "[" + std::to_string(a) + "]: ";
    if (!std::isfinite(msg.origin_W[a])) {
      Fail(error, "origin_W" + at + std::to_string(msg.origin_W[a]) + " (must be finite)");
      return std::nullopt;
    }
    if (msg.dims[a] < 2) {
      Fail(error, "dims" + at + std::to_string(msg.dims[a]) + " (must be >= 2)");
      return std::nullopt;
    }
    num_voxels *= msg.dims[a];  // < 2^62: each factor < 2^31, checked after each product
    if (num_voxels > options.max_voxels) {
      Fail(error, "dims: more than max_voxels = " + std::to_string(options.max_voxels) +
                      " voxels");
      return std::nullopt;
    }
    geometry.origin_W_m(a) = msg.origin_W[a];
    geometry.dims(a) = msg.dims[a];
  }
  geometry.resolution_m = msg.resolution_m;
  return geometry;
}

std::optional<DecodedFullMap> DecodeFullMap(const map_update_t& msg,
                                            const MapCodecOptions& options, std::string* error) {
  if (!msg.is_full) {
    Fail(error, "is_full: false (a delta; DecodeMapDelta)");
    return std::nullopt;
  }
  const std::optional<GridGeometry3> geometry = MapGeometryOf(msg, options, error);
  if (!geometry || !CheckCounts(msg, geometry->NumCells(), options, error)) return std::nullopt;
  DecodedFullMap map{msg.utime, msg.map_seq, *geometry, {}};
  if (msg.compression == map_update_t::COMPRESSION_NONE) {
    if (!DecodePlainStates(msg, &map.states, error)) return std::nullopt;
    return map;
  }
  std::vector<std::uint8_t> raw;
  if (!InflatePayload(msg, &raw, error) ||
      !DecodeRuns(raw, geometry->NumCells(), &map.states, error)) {
    return std::nullopt;
  }
  return map;
}

std::optional<DecodedMapDelta> DecodeMapDelta(const map_update_t& msg,
                                              const MapCodecOptions& options, std::string* error) {
  if (msg.is_full) {
    Fail(error, "is_full: true (a full map; DecodeFullMap)");
    return std::nullopt;
  }
  const std::optional<GridGeometry3> geometry = MapGeometryOf(msg, options, error);
  if (!geometry || !CheckCounts(msg, geometry->NumCells(), options, error)) return std::nullopt;
  DecodedMapDelta delta{msg.utime, msg.map_seq, *geometry, {}};
  if (msg.compression == map_update_t::COMPRESSION_NONE) {
    if (!DecodePlainChanges(msg, *geometry, &delta.changes, error)) return std::nullopt;
    return delta;
  }
  std::vector<std::uint8_t> raw;
  if (!InflatePayload(msg, &raw, error) ||
      !DecodeGaps(raw, *geometry, msg.num_payload_voxels, &delta.changes, error)) {
    return std::nullopt;
  }
  return delta;
}

}  // namespace topay::msgs
