// topay-mapper's subscriptions (POINT_CLOUD, ROBOT_STATE) with the calls its node makes
// (MapperNode::On*): the robot state read (msgs::FromMessage) into the state history, the cloud
// checked (CheckCloud) and integrated (ScanMapper::Integrate: the PCL scan filter with the
// self filter at the interpolated state, then the occupancy map's ray casting), on the shipped
// options and robot, but with 0.1 m voxels: the room's map then has 8 times fewer voxels, and
// allocating the shipped 5 million per input was 70 % of an input's time. Checked: refusals
// say why; every voxel change lies inside the map.
// Input: subscriber_fuzz.h, 2 channels (ticks are ignored); at most 8 clouds per input.
#include <cstdint>
#include <string>
#include <vector>

#include "core/robot/kinematics.h"
#include "procs/msgs/cloud_input.h"
#include "procs/mapper/mapper_options.h"
#include "core/robot/robot_state_history.h"
#include "procs/mapper/scan_mapper.h"
#include "procs/msgs/convert_robot_state.h"
#include "tests/fuzz/subscriber_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  static const mapper::MapperOptions options = [] {
    mapper::MapperOptions shipped = mapper::LoadMapperOptions(ShippedConfig("mapper/mapper.yaml"));
    shipped.map.resolution_m = 0.1;
    return shipped;
  }();
  static const Kinematics kinematics(ShippedRobotModel());
  mapper::ScanMapper scan_mapper(options.filter, options.map, kinematics);
  RobotStateHistory history(options.robot_state);
  msgs::CheckedCloud cloud;
  std::vector<VoxelChange> changes;
  FuzzReader in(data, size);
  int clouds = 0;
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 2);
    if (!op) break;
    if (op->tick) continue;
    if (op->channel == 1) {
      if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) {
        std::string error;
        if (auto estimate = msgs::FromMessage(*m, &error)) history.Add(estimate->utime, estimate->state);
      }
      continue;
    }
    const std::optional<point_cloud_t> msg = DecodeFuzzed<point_cloud_t>(op->bytes, op->fix_fingerprint);
    if (!msg) continue;
    if (++clouds > 8) break;
    if (const auto error = msgs::CheckCloud(*msg, options.filter.input, &cloud)) {
      FuzzCheck(!error->ToString().empty(), "a refused cloud says why");
      continue;
    }
    changes.clear();
    scan_mapper.Integrate(cloud, history.At(cloud.utime), &changes);
    const GridGeometry3& g = scan_mapper.map().geometry();
    for (const VoxelChange& c : changes) {
      FuzzCheck((c.voxel.array() >= 0).all() && (c.voxel.array() < g.dims.array()).all(), "a change lies in the map");
    }
  }
  return 0;
}
