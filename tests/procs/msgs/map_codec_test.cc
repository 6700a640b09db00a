// map_update_t <-> voxel states (procs/msgs/map_codec.h): full maps and deltas round trip
// (compressed and plain, through the generated LCM encoder and decoder), a voxel listed twice
// keeps its last state, compressed maps are small, and every malformed message is refused
// with an error naming the field, never a crash.

#include "procs/msgs/map_codec.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "msgs/map_test_support.h"
#include "procs/msgs/zlib_buffer.h"

namespace topay::msgs {
namespace {

using test::RandomChanges;
using test::RandomStates;
using test::SmallGeometry;
using test::ThroughLcm;

MapCodecOptions Options(bool compress) {
  MapCodecOptions options;
  options.compress = compress;
  return options;
}

// The changes as the codec should deliver them: each voxel once, its last state, by index.
std::vector<VoxelChange> LastWinsByIndex(const GridGeometry3& geometry,
                                         const std::vector<VoxelChange>& changes) {
  std::map<std::int64_t, VoxelChange> by_index;
  for (const VoxelChange& change : changes) {
    by_index[geometry.Index(change.voxel.x(), change.voxel.y(), change.voxel.z())] = change;
  }
  std::vector<VoxelChange> expected;
  for (const auto& [index, change] : by_index) expected.push_back(change);
  return expected;
}

void ExpectSameChanges(const std::vector<VoxelChange>& a, const std::vector<VoxelChange>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].voxel, b[k].voxel) << k;
    EXPECT_EQ(a[k].state, b[k].state) << k;
  }
}

void ExpectGeometry(const GridGeometry3& expected, const GridGeometry3& actual) {
  EXPECT_EQ(expected.origin_W_m, actual.origin_W_m);
  EXPECT_EQ(expected.resolution_m, actual.resolution_m);
  EXPECT_EQ(expected.dims, actual.dims);
}

class MapCodecRoundTrip : public ::testing::TestWithParam<bool> {};

TEST_P(MapCodecRoundTrip, RandomFullMapsRoundTripThroughLcm) {
  const GridGeometry3 geometry = SmallGeometry();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::vector<std::uint8_t> states = RandomStates(geometry, seed);
    const map_update_t msg = ThroughLcm(EncodeFullMap(geometry, states, 123, 7, Options(GetParam())));
    EXPECT_TRUE(msg.is_full);
    EXPECT_EQ(msg.compression, GetParam() ? map_update_t::COMPRESSION_ZLIB
                                          : map_update_t::COMPRESSION_NONE);
    std::string error;
    const std::optional<DecodedFullMap> map = DecodeFullMap(msg, {}, &error);
    ASSERT_TRUE(map) << error;
    EXPECT_EQ(map->utime, 123);
    EXPECT_EQ(map->map_seq, 7);
    ExpectGeometry(geometry, map->geometry);
    EXPECT_EQ(map->states, states) << "seed " << seed;
  }
}

TEST_P(MapCodecRoundTrip, UniformAndAlternatingGridsRoundTrip) {
  const GridGeometry3 geometry = SmallGeometry();
  std::vector<std::vector<std::uint8_t>> grids;
  for (std::uint8_t s = 0; s < 3; ++s) grids.emplace_back(geometry.NumCells(), s);
  grids.emplace_back(geometry.NumCells());
  for (std::size_t i = 0; i < grids.back().size(); ++i) grids.back()[i] = i % 3;  // runs of 1
  for (const std::vector<std::uint8_t>& states : grids) {
    std::string error;
    const auto map = DecodeFullMap(
        ThroughLcm(EncodeFullMap(geometry, states, 0, 1, Options(GetParam()))), {}, &error);
    ASSERT_TRUE(map) << error;
    EXPECT_EQ(map->states, states);
  }
}

TEST_P(MapCodecRoundTrip, RandomDeltasRoundTripWithTheLastStateOfEachVoxel) {
  const GridGeometry3 geometry = SmallGeometry();
  for (int n : {0, 1, 2, 10, 500, 5000, 20000}) {
    const std::vector<VoxelChange> changes = RandomChanges(geometry, n, 1000 + n);
    const map_update_t msg =
        ThroughLcm(EncodeMapDelta(geometry, changes, 55, 9, Options(GetParam())));
    EXPECT_FALSE(msg.is_full);
    std::string error;
    const std::optional<DecodedMapDelta> delta = DecodeMapDelta(msg, {}, &error);
    ASSERT_TRUE(delta) << error;
    EXPECT_EQ(delta->utime, 55);
    EXPECT_EQ(delta->map_seq, 9);
    ExpectGeometry(geometry, delta->geometry);
    ExpectSameChanges(LastWinsByIndex(geometry, changes), delta->changes);
  }
}

INSTANTIATE_TEST_SUITE_P(Compressed, MapCodecRoundTrip, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Zlib" : "None"; });

TEST(MapCodec, MessageValuesAreTheLcmConstants) {
  EXPECT_EQ(MessageValueOf(VoxelState::kFree), map_update_t::FREE);
  EXPECT_EQ(MessageValueOf(VoxelState::kOccupied), map_update_t::OCCUPIED);
  EXPECT_EQ(MessageValueOf(VoxelState::kUnknown), map_update_t::UNKNOWN);
  EXPECT_THROW(MessageValueOf(static_cast<VoxelState>(3)), std::invalid_argument);
}

TEST(MapCodec, PlainMessagesFollowTheDocumentedLayout) {
  const GridGeometry3 geometry = SmallGeometry();
  std::vector<std::uint8_t> states(geometry.NumCells(), 2);
  states[5] = 0;
  states[7] = 1;
  const map_update_t full = EncodeFullMap(geometry, states, 0, 1, Options(false));
  EXPECT_EQ(full.num_indices, 0);
  ASSERT_EQ(full.num_values, geometry.NumCells());
  EXPECT_EQ(full.values[5], map_update_t::FREE);
  EXPECT_EQ(full.values[7], map_update_t::OCCUPIED);
  EXPECT_EQ(full.values[6], map_update_t::UNKNOWN);
  EXPECT_EQ(full.num_payload_bytes, 0);
  const std::vector<VoxelChange> changes = {{{3, 2, 1}, VoxelState::kFree},
                                            {{1, 0, 0}, VoxelState::kUnknown},
                                            {{3, 2, 1}, VoxelState::kOccupied}};
  const map_update_t delta = EncodeMapDelta(geometry, changes, 0, 2, Options(false));
  EXPECT_EQ(delta.indices,
            (std::vector<std::int32_t>{1, static_cast<std::int32_t>(geometry.Index(3, 2, 1))}));
  EXPECT_EQ(delta.values, (std::vector<std::int8_t>{map_update_t::UNKNOWN, map_update_t::OCCUPIED}));
}

TEST(MapCodec, CompressedPayloadFollowsTheDocumentedLayout) {
  // Decoded here by hand, as a receiver in another language would.
  const GridGeometry3 geometry = SmallGeometry();
  const std::vector<VoxelChange> changes = {{{1, 0, 0}, VoxelState::kFree},
                                            {{0, 2, 0}, VoxelState::kOccupied}};
  const map_update_t delta = EncodeMapDelta(geometry, changes, 0, 2);
  std::vector<std::uint8_t> raw;
  std::string error;
  ASSERT_TRUE(ZlibInflateExactly(delta.payload, delta.payload_raw_bytes, &raw, &error)) << error;
  // Index 1: gap 2, FREE (code 1) -> 9; index 80: gap 79, OCCUPIED (code 2) -> 318 = 0xBE 0x02.
  EXPECT_EQ(raw, (std::vector<std::uint8_t>{9, 0xBE, 0x02}));
  EXPECT_EQ(delta.num_payload_voxels, 2);
  std::vector<std::uint8_t> states(geometry.NumCells(), 2);
  states[0] = 0;
  const map_update_t full = EncodeFullMap(geometry, states, 0, 1);
  ASSERT_TRUE(ZlibInflateExactly(full.payload, full.payload_raw_bytes, &raw, &error)) << error;
  // One FREE voxel ((1 << 2) | 1), then 9599 UNKNOWN (9599 << 2 = 38396 = 0xFC 0xAB 0x02).
  EXPECT_EQ(raw, (std::vector<std::uint8_t>{5, 0xFC, 0xAB, 0x02}));
}

TEST(MapCodec, CompressedMapsAreSmall) {
  const GridGeometry3 geometry = SmallGeometry();
  const std::vector<std::uint8_t> states = RandomStates(geometry, 3, 2);
  const map_update_t full = EncodeFullMap(geometry, states, 0, 1);
  EXPECT_LT(test::BusBytes(full), geometry.NumCells() / 4);
  std::vector<std::uint8_t> uniform(geometry.NumCells(), 2);
  EXPECT_LT(test::BusBytes(EncodeFullMap(geometry, uniform, 0, 1)), 200);
  const auto changes = RandomChanges(geometry, 1000, 4);
  EXPECT_LT(test::BusBytes(EncodeMapDelta(geometry, changes, 0, 2)),
            test::BusBytes(EncodeMapDelta(geometry, changes, 0, 2, Options(false))) / 2);
}

TEST(MapCodec, EncodersRefuseBadInput) {
  const GridGeometry3 geometry = SmallGeometry();
  std::vector<std::uint8_t> states(geometry.NumCells(), 0);
  EXPECT_THROW(EncodeFullMap(geometry, std::span(states).first(10), 0, 1), std::invalid_argument);
  states[17] = 3;
  for (bool compress : {true, false}) {
    EXPECT_THROW(EncodeFullMap(geometry, states, 0, 1, Options(compress)), std::invalid_argument);
    const std::vector<VoxelChange> outside = {{{40, 0, 0}, VoxelState::kFree}};
    EXPECT_THROW(EncodeMapDelta(geometry, outside, 0, 1, Options(compress)),
                 std::invalid_argument);
    const std::vector<VoxelChange> bad_state = {{{0, 0, 0}, static_cast<VoxelState>(7)}};
    EXPECT_THROW(EncodeMapDelta(geometry, bad_state, 0, 1, Options(compress)),
                 std::invalid_argument);
  }
  GridGeometry3 bad = geometry;
  bad.resolution_m = -1.0;
  EXPECT_THROW(EncodeMapDelta(bad, {}, 0, 1), std::invalid_argument);
  MapCodecOptions level;
  level.zlib_level = 10;
  EXPECT_THROW(EncodeMapDelta(geometry, {}, 0, 1, level), std::invalid_argument);
}

TEST(MapCodec, KindMismatchIsRefused) {
  const GridGeometry3 geometry = SmallGeometry();
  std::string error;
  EXPECT_FALSE(DecodeMapDelta(EncodeFullMap(geometry, RandomStates(geometry, 1), 0, 1), {}, &error));
  EXPECT_NE(error.find("map_update_t.is_full"), std::string::npos) << error;
  EXPECT_FALSE(DecodeFullMap(EncodeMapDelta(geometry, {}, 0, 1), {}, &error));
  EXPECT_NE(error.find("map_update_t.is_full"), std::string::npos) << error;
}

// --- Malformed messages -----------------------------------------------------------------

struct Corruption {
  std::string name;
  bool full;                       // corrupt a full map (else a delta)
  bool compress;                   // ... encoded with compression
  std::function<void(map_update_t*)> corrupt;
  std::string field;               // the error must name it
};

// Re-deflates `raw` as the message's payload, with the declared raw size given.
void SetPayload(std::vector<std::uint8_t> raw, std::int32_t declared_raw, map_update_t* msg) {
  msg->payload = ZlibDeflate(raw, 6);
  msg->num_payload_bytes = static_cast<std::int32_t>(msg->payload.size());
  msg->payload_raw_bytes = declared_raw;
}

std::vector<Corruption> Corruptions() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  return {
      {"ZeroDim", true, true, [](map_update_t* m) { m->dims[1] = 0; }, "dims[1]"},
      {"NegativeDim", false, true, [](map_update_t* m) { m->dims[2] = -4; }, "dims[2]"},
      {"HugeDims", true, true,
       [](map_update_t* m) { m->dims[0] = m->dims[1] = m->dims[2] = 2'000'000'000; }, "max_voxels"},
      {"OtherDims", true, true, [](map_update_t* m) { m->dims[0] += 1; }, "num_payload_voxels"},
      {"OtherDimsPlain", true, false, [](map_update_t* m) { m->dims[0] -= 1; }, "num_values"},
      {"NanResolution", true, true, [nan](map_update_t* m) { m->resolution_m = nan; }, "resolution_m"},
      {"ZeroResolution", false, true, [](map_update_t* m) { m->resolution_m = 0.0; }, "resolution_m"},
      {"NanOrigin", false, false, [nan](map_update_t* m) { m->origin_W[1] = nan; }, "origin_W[1]"},
      {"InfOrigin", true, true, [inf](map_update_t* m) { m->origin_W[2] = -inf; }, "origin_W[2]"},
      {"UnknownCompression", true, true, [](map_update_t* m) { m->compression = 2; }, "compression"},
      {"NegativeCompression", false, false, [](map_update_t* m) { m->compression = -1; }, "compression"},
      {"NegativeNumIndices", false, false, [](map_update_t* m) { m->num_indices = -1; }, "num_indices"},
      {"NumValuesMismatch", false, false, [](map_update_t* m) { m->num_values += 1; }, "num_values"},
      {"IndicesWithoutValues", false, false,
       [](map_update_t* m) { m->values.pop_back(); m->num_values -= 1; }, "num_indices"},
      {"IndexOutOfRange", false, false, [](map_update_t* m) { m->indices[3] = 9600; }, "indices[3]"},
      {"NegativeIndex", false, false, [](map_update_t* m) { m->indices[0] = -1; }, "indices[0]"},
      {"ValueOutOfRange", false, false, [](map_update_t* m) { m->values[2] = 2; }, "values[2]"},
      {"FullValueOutOfRange", true, false, [](map_update_t* m) { m->values[9] = -2; }, "values[9]"},
      {"PayloadWithPlain", false, false,
       [](map_update_t* m) { m->payload = {1}; m->num_payload_bytes = 1; }, "num_payload_bytes"},
      {"IndicesWithZlib", false, true,
       [](map_update_t* m) { m->indices = {1}; m->values = {0}; m->num_indices = m->num_values = 1; },
       "num_indices"},
      {"NegativePayloadVoxels", false, true, [](map_update_t* m) { m->num_payload_voxels = -5; },
       "num_payload_voxels"},
      {"TooManyPayloadVoxels", false, true, [](map_update_t* m) { m->num_payload_voxels = 9601; },
       "num_payload_voxels"},
      {"NumPayloadBytesMismatch", true, true, [](map_update_t* m) { m->num_payload_bytes -= 1; },
       "num_payload_bytes"},
      {"AbsurdRawBytes", true, true, [](map_update_t* m) { m->payload_raw_bytes = 2'000'000'000; },
       "payload_raw_bytes"},
      {"NegativeRawBytes", false, true, [](map_update_t* m) { m->payload_raw_bytes = -1; },
       "payload_raw_bytes"},
      {"TruncatedPayload", true, true,
       [](map_update_t* m) { m->payload.resize(m->payload.size() / 2);
                             m->num_payload_bytes = static_cast<int>(m->payload.size()); },
       "payload"},
      {"GarbagePayload", false, true,
       [](map_update_t* m) { for (auto& b : m->payload) b = static_cast<std::uint8_t>(b * 7 + 3); },
       "payload"},
      {"FlippedChecksum", true, true, [](map_update_t* m) { m->payload.back() ^= 1; }, "payload"},
      {"TrailingBytes", false, true,
       [](map_update_t* m) { m->payload.push_back(0); m->num_payload_bytes += 1; }, "payload"},
      {"InflatesBeyondDeclared", true, true,  // a bomb: 9600 bytes of zeros, declared 100
       [](map_update_t* m) { SetPayload(std::vector<std::uint8_t>(9600, 0), 100, m); },
       "more than the declared"},
      {"InflatesShortOfDeclared", false, true,
       [](map_update_t* m) { m->payload_raw_bytes += 1; }, "payload"},
      {"RunsShortOfTheGrid", true, true,
       [](map_update_t* m) { SetPayload({(20 << 2) | 1}, 1, m); }, "cover 20 of 9600"},
      {"RunsBeyondTheGrid", true, true,  // 9601 free voxels: 0x85 0xAC 0x02
       [](map_update_t* m) { SetPayload({0x85, 0xAC, 0x02}, 3, m); }, "more than the 9600"},
      {"StateCode3", true, true,
       [](map_update_t* m) { SetPayload({0xFF, 0xAB, 0x02}, 3, m); }, "state code 3"},
      {"ZeroRun", true, true, [](map_update_t* m) { SetPayload({0x01}, 1, m); }, "count 0"},
      {"TruncatedVarint", true, true, [](map_update_t* m) { SetPayload({0x85}, 1, m); },
       "truncated varint"},
      {"OverlongVarint", true, true,
       [](map_update_t* m) { SetPayload({0x80, 0x80, 0x80, 0x80, 0x80, 0x01}, 6, m); },
       "varint above 5 bytes"},
      {"ChangeOutsideGrid", false, true,
       [](map_update_t* m) { SetPayload({0x85, 0xAC, 0x02}, 3, m); m->num_payload_voxels = 1; },
       "outside the grid"},
      {"RepeatedIndex", false, true,  // gap 0 after the first change
       [](map_update_t* m) { SetPayload({9, 1}, 2, m); m->num_payload_voxels = 2; }, "count 0"},
      {"MoreChangesThanDeclared", false, true,
       [](map_update_t* m) { SetPayload({9, 9, 9}, 3, m); m->num_payload_voxels = 2; },
       "beyond num_payload_voxels"},
      {"FewerChangesThanDeclared", false, true,
       [](map_update_t* m) { SetPayload({0x89, 0x01}, 2, m); m->num_payload_voxels = 2; },
       "num_payload_voxels"},
  };
}

TEST(MapCodec, MalformedMessagesAreRefusedNamingTheField) {
  const GridGeometry3 geometry = SmallGeometry();
  const std::vector<std::uint8_t> states = RandomStates(geometry, 5);
  const std::vector<VoxelChange> changes = RandomChanges(geometry, 300, 6);
  for (const Corruption& c : Corruptions()) {
    SCOPED_TRACE(c.name);
    map_update_t msg = c.full ? EncodeFullMap(geometry, states, 0, 1, Options(c.compress))
                              : EncodeMapDelta(geometry, changes, 0, 1, Options(c.compress));
    c.corrupt(&msg);
    std::string error;
    const bool decoded = c.full ? DecodeFullMap(msg, {}, &error).has_value()
                                : DecodeMapDelta(msg, {}, &error).has_value();
    EXPECT_FALSE(decoded);
    EXPECT_EQ(error.rfind("map_update_t.", 0), 0u) << error;
    EXPECT_NE(error.find(c.field), std::string::npos) << error;
  }
}

TEST(MapCodec, RandomlyDamagedPayloadsNeverCrash) {
  const GridGeometry3 geometry = SmallGeometry();
  const map_update_t full = EncodeFullMap(geometry, RandomStates(geometry, 8), 0, 1);
  const map_update_t delta = EncodeMapDelta(geometry, RandomChanges(geometry, 2000, 9), 0, 2);
  Rng rng(10);
  int refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    map_update_t msg = trial % 2 == 0 ? full : delta;
    const int flips = static_cast<int>(rng.UniformInt(1, 4));
    for (int f = 0; f < flips; ++f) {
      msg.payload[rng.UniformInt(0, msg.num_payload_bytes - 1)] ^=
          static_cast<std::uint8_t>(rng.UniformInt(1, 255));
    }
    std::string error;
    const bool ok = msg.is_full ? DecodeFullMap(msg, {}, &error).has_value()
                                : DecodeMapDelta(msg, {}, &error).has_value();
    if (!ok) {
      ++refused;
      EXPECT_EQ(error.rfind("map_update_t.payload", 0), 0u) << error;
    }
  }
  EXPECT_EQ(refused, 400);  // the Adler-32 checksum catches every flip
}

TEST(MapCodec, MaxVoxelsBoundsTheGrid) {
  const GridGeometry3 geometry = SmallGeometry();
  MapCodecOptions options;
  options.max_voxels = geometry.NumCells() - 1;
  std::string error;
  EXPECT_FALSE(DecodeFullMap(EncodeFullMap(geometry, RandomStates(geometry, 1), 0, 1), options,
                             &error));
  EXPECT_NE(error.find("max_voxels"), std::string::npos) << error;
  options.max_voxels = geometry.NumCells();
  EXPECT_TRUE(DecodeFullMap(EncodeFullMap(geometry, RandomStates(geometry, 1), 0, 1), options,
                            &error)) << error;
}

}  // namespace
}  // namespace topay::msgs
