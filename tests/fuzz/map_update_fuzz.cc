// The map update decoder as every map subscriber runs it (msgs::MapReceiver: the planner's map
// intake, the viewer, topay-report): a stream of MAP_UPDATE messages, snapshots and deltas in
// any order. Checked after every message: a refused one says why; the receiver's grid is
// consistent (one valid VoxelState per voxel of its geometry, at most max_voxels); every
// applied delta change lies inside the grid; and an applied snapshot encodes (EncodeFullMap)
// into a message that a fresh receiver decodes to the same voxels.
// Input: subscriber_fuzz.h with one channel (ticks are ignored).
#include <algorithm>
#include <cstdint>

#include "procs/msgs/map_codec.h"
#include "procs/msgs/map_receiver.h"
#include "tests/fuzz/subscriber_fuzz.h"

namespace {

using topay::msgs::MapAcceptResult;
using topay::msgs::MapReceiver;
using topay::msgs::MapUpdateOutcome;

void CheckGrid(const MapReceiver& receiver, const topay::msgs::MapCodecOptions& options) {
  if (!receiver.has_map()) return;
  const std::int64_t cells = receiver.geometry().NumCells();
  FuzzCheck(cells > 0 && cells <= options.max_voxels, "the grid is within max_voxels");
  FuzzCheck(static_cast<std::int64_t>(receiver.states().size()) == cells, "one state per voxel");
  for (std::uint8_t s : receiver.states()) FuzzCheck(s <= 2, "every voxel holds a VoxelState");
}

void CheckSnapshotRoundTrip(const MapReceiver& receiver) {
  const topay::map_update_t again =
      topay::msgs::EncodeFullMap(receiver.geometry(), receiver.states(), receiver.utime(), receiver.map_seq());
  MapReceiver fresh;
  FuzzCheck(fresh.Accept(again).outcome == MapUpdateOutcome::kSnapshotApplied, "a re-encoded snapshot applies");
  FuzzCheck(std::equal(fresh.states().begin(), fresh.states().end(), receiver.states().begin(),
                       receiver.states().end()),
            "a re-encoded snapshot decodes to the same voxels");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  const msgs::MapCodecOptions options;
  MapReceiver receiver(options);
  FuzzReader in(data, size);
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 1);
    if (!op) break;
    if (op->tick) continue;
    const std::optional<map_update_t> msg = DecodeFuzzed<map_update_t>(op->bytes, op->fix_fingerprint);
    if (!msg) continue;
    const MapAcceptResult result = receiver.Accept(*msg);
    if (result.outcome == MapUpdateOutcome::kRejected) FuzzCheck(!result.reason.empty(), "a rejection says why");
    CheckGrid(receiver, options);
    if (result.outcome == MapUpdateOutcome::kDeltaApplied) {
      const GridGeometry3& g = receiver.geometry();
      for (const VoxelChange& c : result.changes) {
        FuzzCheck((c.voxel.array() >= 0).all() && (c.voxel.array() < g.dims.array()).all(),
                  "an applied change lies inside the grid");
        FuzzCheck(static_cast<std::uint8_t>(c.state) <= 2, "an applied change is a VoxelState");
      }
    }
    if (result.outcome == MapUpdateOutcome::kSnapshotApplied) CheckSnapshotRoundTrip(receiver);
  }
  return 0;
}
