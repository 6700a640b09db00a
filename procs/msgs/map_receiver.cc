#include "procs/msgs/map_receiver.h"

#include <utility>

namespace topay::msgs {
MapReceiver::MapReceiver(const MapCodecOptions& options) : options_(options) {}

MapAcceptResult MapReceiver::Accept(const map_update_t& msg) {
  return msg.is_full ? AcceptFull(msg) : AcceptDelta(msg);
}

MapAcceptResult MapReceiver::AcceptFull(const map_update_t& msg) {
  std::string error;
  std::optional<DecodedFullMap> map = DecodeFullMap(msg, options_, &error);
  if (!map) return Rejected(std::move(error));
  geometry_ = map->geometry;
  states_ = std::move(map->states);
  map_seq_ = map->map_seq;
  utime_ = map->utime;
  has_map_ = in_sync_ = true;
  ++counts_.snapshots;
  return {MapUpdateOutcome::kSnapshotApplied, {}, {}};
}

MapAcceptResult MapReceiver::AcceptDelta(const map_update_t& msg) {
  std::string error;
  std::optional<DecodedMapDelta> delta = DecodeMapDelta(msg, options_, &error);
  if (!delta) return Rejected(std::move(error));
  if (std::optional<std::string> why = WhyNotNext(*delta)) {
    in_sync_ = false;
    return Waiting(std::move(*why));
  }
  for (const VoxelChange& change : delta->changes) {
    states_[geometry_.Index(change.voxel.x(), change.voxel.y(), change.voxel.z())] =
        static_cast<std::uint8_t>(change.state);
  }
  map_seq_ = delta->map_seq;
  utime_ = delta->utime;
  ++counts_.deltas;
  return {MapUpdateOutcome::kDeltaApplied, std::move(delta->changes), {}};
}

std::optional<std::string> MapReceiver::WhyNotNext(const DecodedMapDelta& delta) const {
  const std::string seq = "delta map_seq " + std::to_string(delta.map_seq);
  if (!has_map_) return seq + ": no snapshot yet";
  if (!in_sync_) return seq + ": a delta was missed since the snapshot";
  if (delta.map_seq != map_seq_ + 1) {
    return seq + " does not follow map_seq " + std::to_string(map_seq_);
  }
  if (!SameGeometry(delta.geometry, geometry_)) return seq + ": another grid geometry";
  return std::nullopt;
}

MapAcceptResult MapReceiver::Rejected(std::string error) {
  ++counts_.rejected;
  return {MapUpdateOutcome::kRejected, {}, std::move(error)};
}

MapAcceptResult MapReceiver::Waiting(std::string reason) {
  ++counts_.waiting;
  return {MapUpdateOutcome::kWaitingForSnapshot, {}, std::move(reason)};
}

}  // namespace topay::msgs
