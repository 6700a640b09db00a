// Benchmarks of the MAP_UPDATE codec (procs/msgs/map_codec.h, issue 17 item 4) on the
// mapper's grid, 20 x 20 x 1.6 m at 0.05 m (400 x 400 x 32 = 5.12 M voxels):
//  - full snapshots of an all-unknown grid and of a mapped room (seeded: walls, a floor and
//    table-sized boxes as occupied shells, free space seen within 8 m of the robot, unknown
//    inside the boxes and beyond, 0.5 % of the seen voxels left unknown at random);
//  - deltas of 500, 5,000 and 50,000 changes clustered as a scan's: rays from the sensor to
//    box surfaces, the hit voxel occupied and the 4 voxels before it free.
// Each message is timed on its own (wall clock, and thread CPU time: *_cpu_ms, less disturbed
// on a shared machine); counters: median and p95 (nearest rank) in ms, and the message's LCM
// size in bytes. Encode and decode are timed separately; decode
// includes every check. Run (Release build):
//   build/bin/map_codec_bench
// Arguments: zlib level (0: COMPRESSION_NONE), then the change count for deltas.

#include <algorithm>
#include <cmath>
#include <ctime>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "procs/msgs/map_codec.h"
#include "tests/bench/bench_clock.h"

namespace topay::msgs {
namespace {

using bench_clock::ThreadCpuSeconds;
using bench_clock::WallSeconds;

void ReportPercentiles(benchmark::State& state, std::vector<double> times,
                       const std::string& name) {
  if (times.empty()) return;
  std::sort(times.begin(), times.end());
  const auto at = [&](double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * times.size()));
    return times[std::clamp<std::size_t>(rank, 1, times.size()) - 1] * 1e3;
  };
  state.counters["median_" + name] = at(0.5);
  state.counters["p95_" + name] = at(0.95);
}

GridGeometry3 RoomGeometry() {
  GridGeometry3 g;
  g.origin_W_m = Eigen::Vector3d(-10.0, -10.0, 0.0);
  g.resolution_m = 0.05;
  g.dims = Eigen::Vector3i(400, 400, 32);
  return g;
}

// Boxes in voxels [lo, hi).
struct VoxelBox {
  Eigen::Vector3i lo, hi;
};

std::vector<VoxelBox> TableBoxes(const GridGeometry3& g, Rng* rng) {
  std::vector<VoxelBox> boxes;
  for (int b = 0; b < 40; ++b) {
    const Eigen::Vector3i size(static_cast<int>(rng->UniformInt(8, 32)),
                               static_cast<int>(rng->UniformInt(8, 32)),
                               static_cast<int>(rng->UniformInt(6, 20)));
    const Eigen::Vector3i lo(static_cast<int>(rng->UniformInt(4, g.dims.x() - 40)),
                             static_cast<int>(rng->UniformInt(4, g.dims.y() - 40)), 1);
    boxes.push_back({lo, lo + size});
  }
  return boxes;
}

void Fill(const GridGeometry3& g, const VoxelBox& box, VoxelState state,
          std::vector<std::uint8_t>* states) {
  for (int iz = box.lo.z(); iz < box.hi.z(); ++iz)
    for (int iy = box.lo.y(); iy < box.hi.y(); ++iy)
      for (int ix = box.lo.x(); ix < box.hi.x(); ++ix)
        (*states)[g.Index(ix, iy, iz)] = static_cast<std::uint8_t>(state);
}

std::vector<std::uint8_t> MappedRoom(const GridGeometry3& g, const std::vector<VoxelBox>& boxes) {
  Rng rng(7);
  std::vector<std::uint8_t> states(g.NumCells(), static_cast<std::uint8_t>(VoxelState::kUnknown));
  // Seen free within 8 m of the robot at the centre; the floor below it occupied.
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        if (std::hypot(ix - 200, iy - 200) > 160) continue;
        states[g.Index(ix, iy, iz)] = static_cast<std::uint8_t>(
            iz == 0 ? VoxelState::kOccupied
                    : (rng.Uniform01() < 0.005 ? VoxelState::kUnknown : VoxelState::kFree));
      }
  // Walls along the border, boxes as occupied shells with unknown inside.
  Fill(g, {{0, 0, 0}, {400, 2, 32}}, VoxelState::kOccupied, &states);
  Fill(g, {{0, 398, 0}, {400, 400, 32}}, VoxelState::kOccupied, &states);
  Fill(g, {{0, 0, 0}, {2, 400, 32}}, VoxelState::kOccupied, &states);
  Fill(g, {{398, 0, 0}, {400, 400, 32}}, VoxelState::kOccupied, &states);
  for (const VoxelBox& box : boxes) {
    Fill(g, box, VoxelState::kOccupied, &states);
    const Eigen::Vector3i one = Eigen::Vector3i::Ones();
    Fill(g, {box.lo + one, box.hi - one}, VoxelState::kUnknown, &states);
  }
  return states;
}

// A scan's changes: rays from the sensor at the room's centre (1 m up) to random points on
// the boxes' tops and sides; per ray the hit voxel occupied and the 4 before it free.
std::vector<VoxelChange> ScanChanges(const GridGeometry3& g, const std::vector<VoxelBox>& boxes,
                                     int n, std::uint64_t seed) {
  Rng rng(seed);
  const Eigen::Vector3d sensor(0.0, 0.0, 1.0);
  std::vector<VoxelChange> changes;
  while (static_cast<int>(changes.size()) < n) {
    const VoxelBox& box = boxes[rng.UniformInt(0, boxes.size() - 1)];
    Eigen::Vector3i hit;
    for (int a = 0; a < 3; ++a) {
      hit(a) = static_cast<int>(rng.UniformInt(box.lo(a), box.hi(a) - 1));
    }
    const Eigen::Vector3d p = g.CellCenter(hit.x(), hit.y(), hit.z());
    const Eigen::Vector3d back = (sensor - p).normalized() * g.resolution_m;
    changes.push_back({hit, VoxelState::kOccupied});
    for (int k = 1; k <= 4 && static_cast<int>(changes.size()) < n; ++k) {
      const Eigen::Vector3i v = g.CellOf(p + k * back);
      if ((v.array() >= 0).all() && (v.array() < g.dims.array()).all()) {
        changes.push_back({v, VoxelState::kFree});
      }
    }
  }
  return changes;
}

MapCodecOptions OptionsOf(int level) {
  MapCodecOptions options;
  options.compress = level > 0;
  options.zlib_level = std::max(level, 1);
  return options;
}

// Arguments: zlib level (0: no compression), mapped (1) or all unknown (0).
void BM_FullSnapshot(benchmark::State& state) {
  const GridGeometry3 g = RoomGeometry();
  Rng rng(3);
  const std::vector<VoxelBox> boxes = TableBoxes(g, &rng);
  const std::vector<std::uint8_t> states =
      state.range(1) != 0 ? MappedRoom(g, boxes)
                          : std::vector<std::uint8_t>(g.NumCells(), 2);
  const MapCodecOptions options = OptionsOf(static_cast<int>(state.range(0)));
  std::vector<double> encode, decode, encode_cpu, decode_cpu;
  map_update_t msg;
  for (auto _ : state) {
    double t = WallSeconds(), c = ThreadCpuSeconds();
    msg = EncodeFullMap(g, states, 0, 1, options);
    encode_cpu.push_back(ThreadCpuSeconds() - c);
    encode.push_back(WallSeconds() - t);
    std::string error;
    t = WallSeconds(), c = ThreadCpuSeconds();
    const auto map = DecodeFullMap(msg, options, &error);
    decode_cpu.push_back(ThreadCpuSeconds() - c);
    decode.push_back(WallSeconds() - t);
    if (!map || map->states != states) state.SkipWithError("round trip failed");
  }
  ReportPercentiles(state, encode, "encode_ms");
  ReportPercentiles(state, decode, "decode_ms");
  ReportPercentiles(state, encode_cpu, "encode_cpu_ms");
  ReportPercentiles(state, decode_cpu, "decode_cpu_ms");
  state.counters["bus_bytes"] = msg.getEncodedSize();
  state.counters["raw_bytes"] = msg.payload_raw_bytes;
}
BENCHMARK(BM_FullSnapshot)
    ->ArgsProduct({{0, 1, 6}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);

// Arguments: zlib level (0: no compression), number of changes.
void BM_ScanDelta(benchmark::State& state) {
  const GridGeometry3 g = RoomGeometry();
  Rng rng(3);
  const std::vector<VoxelBox> boxes = TableBoxes(g, &rng);
  const MapCodecOptions options = OptionsOf(static_cast<int>(state.range(0)));
  const int n = static_cast<int>(state.range(1));
  std::vector<double> encode, decode, encode_cpu, decode_cpu;
  double bytes = 0.0;
  std::uint64_t seed = 100;
  std::vector<std::vector<VoxelChange>> scans;
  for (int s = 0; s < 16; ++s) scans.push_back(ScanChanges(g, boxes, n, ++seed));
  std::size_t next = 0;
  for (auto _ : state) {
    const std::vector<VoxelChange>& changes = scans[next++ % scans.size()];
    double t = WallSeconds(), c = ThreadCpuSeconds();
    const map_update_t msg = EncodeMapDelta(g, changes, 0, 2, options);
    encode_cpu.push_back(ThreadCpuSeconds() - c);
    encode.push_back(WallSeconds() - t);
    std::string error;
    t = WallSeconds(), c = ThreadCpuSeconds();
    const auto delta = DecodeMapDelta(msg, options, &error);
    decode_cpu.push_back(ThreadCpuSeconds() - c);
    decode.push_back(WallSeconds() - t);
    if (!delta) state.SkipWithError(error.c_str());
    bytes += msg.getEncodedSize();
  }
  ReportPercentiles(state, encode, "encode_ms");
  ReportPercentiles(state, decode, "decode_ms");
  ReportPercentiles(state, encode_cpu, "encode_cpu_ms");
  ReportPercentiles(state, decode_cpu, "decode_cpu_ms");
  state.counters["bus_bytes"] = bytes / static_cast<double>(encode.size());
}
BENCHMARK(BM_ScanDelta)
    ->ArgsProduct({{0, 1, 6}, {500, 5000, 50000}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(200);

}  // namespace
}  // namespace topay::msgs

BENCHMARK_MAIN();
