// MapReceiver (procs/msgs/map_receiver.h): snapshots and deltas keep the receiver's grid equal
// to the sender's; a receiver that missed a delta or joined late waits for the next snapshot
// and then equals the sender; malformed messages are rejected with the grid unchanged; the
// changes it reports drive VoxelMapFields to the same voxels.

#include "procs/msgs/map_receiver.h"

#include <gtest/gtest.h>

#include "procs/msgs/map_publish_schedule.h"
#include "msgs/map_test_support.h"

namespace topay::msgs {
namespace {

using test::RandomChanges;
using test::RandomStates;
using test::SmallGeometry;
using test::ThroughLcm;

// The mapper's side: a grid, random scans of changes and the messages the schedule asks for.
class Sender {
 public:
  Sender(const GridGeometry3& geometry, bool compress, double snapshot_period_s = 1.0)
      : geometry_(geometry), states_(RandomStates(geometry, 1)),
        schedule_(MapPublishScheduleOptions{snapshot_period_s, 1}) {
    options_.compress = compress;
  }
  // One scan (every 0.125 s, exact in binary): changes applied to the grid, then the update to publish.
  map_update_t Scan() {
    const std::vector<VoxelChange> changes = RandomChanges(geometry_, 200, ++scan_);
    test::ApplyTo(geometry_, changes, &states_);
    const MapPublishStep step = schedule_.Next(0.125 * static_cast<double>(scan_));
    return ThroughLcm(step.is_full ? EncodeFullMap(geometry_, states_, scan_, step.map_seq, options_)
                                   : EncodeMapDelta(geometry_, changes, scan_, step.map_seq, options_));
  }
  const GridGeometry3& geometry() const { return geometry_; }
  const std::vector<std::uint8_t>& states() const { return states_; }

 private:
  GridGeometry3 geometry_;
  std::vector<std::uint8_t> states_;
  MapPublishSchedule schedule_;
  MapCodecOptions options_;
  std::uint64_t scan_ = 0;
};

bool Equal(std::span<const std::uint8_t> a, const std::vector<std::uint8_t>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

class MapReceiverTest : public ::testing::TestWithParam<bool> {};

TEST_P(MapReceiverTest, SnapshotAndDeltasEqualTheSenderAfterEveryUpdate) {
  Sender sender(SmallGeometry(), GetParam());
  MapReceiver receiver;
  for (int scan = 1; scan <= 35; ++scan) {
    const map_update_t msg = sender.Scan();
    const MapAcceptResult result = receiver.Accept(msg);
    EXPECT_EQ(result.outcome, msg.is_full ? MapUpdateOutcome::kSnapshotApplied
                                          : MapUpdateOutcome::kDeltaApplied)
        << scan << " " << result.reason;
    EXPECT_TRUE(Equal(receiver.states(), sender.states())) << scan;
    EXPECT_EQ(receiver.map_seq(), msg.map_seq);
    EXPECT_EQ(receiver.utime(), scan);
  }
  EXPECT_EQ(receiver.counts().snapshots, 5);  // scans 1, 9, 17, 25, 33 (1 s period)
  EXPECT_EQ(receiver.counts().deltas, 30);
  EXPECT_EQ(receiver.counts().waiting + receiver.counts().rejected, 0);
}

TEST_P(MapReceiverTest, AReceiverThatMissedADeltaWaitsForTheNextSnapshot) {
  Sender sender(SmallGeometry(), GetParam());
  MapReceiver receiver;
  for (int scan = 1; scan <= 25; ++scan) {
    const map_update_t msg = sender.Scan();
    if (scan == 4) continue;  // lost
    const MapAcceptResult result = receiver.Accept(msg);
    if (scan >= 5 && scan <= 8) {
      EXPECT_EQ(result.outcome, MapUpdateOutcome::kWaitingForSnapshot) << scan;
      EXPECT_FALSE(receiver.in_sync());
      EXPECT_FALSE(result.reason.empty());
    } else {
      EXPECT_NE(result.outcome, MapUpdateOutcome::kWaitingForSnapshot) << scan;
      EXPECT_TRUE(Equal(receiver.states(), sender.states())) << scan;
    }
  }
  EXPECT_EQ(receiver.counts().waiting, 4);
  EXPECT_EQ(receiver.counts().snapshots, 4);  // 1, 9, 17, 25
  EXPECT_TRUE(receiver.in_sync());
}

TEST_P(MapReceiverTest, ALateReceiverCatchesUpAtTheNextSnapshot) {
  Sender sender(SmallGeometry(), GetParam());
  for (int scan = 1; scan <= 13; ++scan) sender.Scan();
  MapReceiver receiver;
  EXPECT_FALSE(receiver.has_map());
  EXPECT_TRUE(receiver.states().empty());
  for (int scan = 14; scan <= 23; ++scan) {
    const MapAcceptResult result = receiver.Accept(sender.Scan());
    if (scan < 17) {
      EXPECT_EQ(result.outcome, MapUpdateOutcome::kWaitingForSnapshot) << scan;
      EXPECT_NE(result.reason.find("no snapshot yet"), std::string::npos) << result.reason;
    } else {
      EXPECT_TRUE(Equal(receiver.states(), sender.states())) << scan;
    }
  }
  EXPECT_TRUE(receiver.has_map());
  EXPECT_EQ(receiver.counts().waiting, 3);
}

INSTANTIATE_TEST_SUITE_P(Compressed, MapReceiverTest, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Zlib" : "None"; });

TEST(MapReceiver, MalformedMessagesAreRejectedAndLeaveTheGrid) {
  Sender sender(SmallGeometry(), true);
  MapReceiver receiver;
  ASSERT_EQ(receiver.Accept(sender.Scan()).outcome, MapUpdateOutcome::kSnapshotApplied);
  const std::vector<std::uint8_t> before(receiver.states().begin(), receiver.states().end());
  map_update_t delta = sender.Scan();
  map_update_t full = EncodeFullMap(sender.geometry(), sender.states(), 0, 2);
  std::vector<map_update_t> bad(4, delta);
  bad[0].payload.back() ^= 0x10;
  bad[1].resolution_m = std::numeric_limits<double>::quiet_NaN();
  bad[2].compression = 7;
  bad[3] = full;
  bad[3].dims[0] = -1;
  for (const map_update_t& msg : bad) {
    const MapAcceptResult result = receiver.Accept(msg);
    EXPECT_EQ(result.outcome, MapUpdateOutcome::kRejected);
    EXPECT_EQ(result.reason.rfind("map_update_t.", 0), 0u) << result.reason;
    EXPECT_TRUE(Equal(receiver.states(), before));
    EXPECT_EQ(receiver.map_seq(), 1);
  }
  EXPECT_EQ(receiver.counts().rejected, 4);
  EXPECT_TRUE(receiver.in_sync());  // a rejected message is not a missed delta...
  EXPECT_EQ(receiver.Accept(delta).outcome, MapUpdateOutcome::kDeltaApplied);  // ...its intact copy applies
  EXPECT_TRUE(Equal(receiver.states(), sender.states()));
}

TEST(MapReceiver, ADeltaOfAnotherGeometryWaits) {
  Sender sender(SmallGeometry(), true);
  MapReceiver receiver;
  receiver.Accept(sender.Scan());
  map_update_t delta = sender.Scan();
  delta.origin_W[0] += 0.05;
  const MapAcceptResult result = receiver.Accept(delta);
  EXPECT_EQ(result.outcome, MapUpdateOutcome::kWaitingForSnapshot);
  EXPECT_NE(result.reason.find("geometry"), std::string::npos) << result.reason;
}

TEST(MapReceiver, ReportedChangesDriveVoxelMapFieldsToTheReceiversGrid) {
  VoxelMapFieldsOptions options;
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-1.0, -0.75, 0.0),
                                           Eigen::Vector3d(1.0, 0.75, 0.4));
  VoxelMapFields fields(options);  // every voxel unknown
  Sender sender(fields.geometry(), true);
  MapReceiver receiver;
  // The first snapshot: the planner would rebuild; here its voxels are set as changes.
  ASSERT_EQ(receiver.Accept(sender.Scan()).outcome, MapUpdateOutcome::kSnapshotApplied);
  std::vector<VoxelChange> all;
  const GridGeometry3& g = receiver.geometry();
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix) all.push_back({{ix, iy, iz}, receiver.state(ix, iy, iz)});
  fields.ApplyChanges(all);
  for (int scan = 2; scan <= 6; ++scan) {
    const MapAcceptResult result = receiver.Accept(sender.Scan());
    ASSERT_EQ(result.outcome, MapUpdateOutcome::kDeltaApplied);
    fields.ApplyChanges(result.changes);
  }
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix)
        ASSERT_EQ(fields.state(ix, iy, iz), receiver.state(ix, iy, iz)) << ix << " " << iy << " " << iz;
  EXPECT_TRUE(Equal(receiver.states(), sender.states()));
}

}  // namespace
}  // namespace topay::msgs
