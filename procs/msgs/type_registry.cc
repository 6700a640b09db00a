#include "procs/msgs/type_registry.h"

#include "topay/base_pose_t.hpp"
#include "topay/base_velocity_t.hpp"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/graph_status_t.hpp"
#include "topay/planner_paths_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/joint_state_t.hpp"
#include "topay/map_update_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"
#include "topay/whole_body_state_t.hpp"
#include "topay_msgs/checked_decode.h"

namespace topay::msgs {
namespace {

template <class Msg>
MessageTypeInfo Info() {
  return {Msg::getTypeName(), Msg::getHash(),
          [](const void* data, std::size_t size, std::string* error) {
            return CheckedDecode<Msg>(data, size, error).has_value();
          }};
}

}  // namespace

const std::vector<MessageTypeInfo>& AllMessageTypes() {
  static const std::vector<MessageTypeInfo> kTypes = {
      Info<base_pose_t>(),      Info<base_velocity_t>(),  Info<joint_state_t>(),
      Info<robot_state_t>(),    Info<whole_body_state_t>(), Info<point_cloud_t>(),
      Info<map_update_t>(),     Info<goal_t>(),           Info<poly_trajectory_t>(),
      Info<control_command_t>(), Info<planner_status_t>(), Info<heartbeat_t>(),
      Info<graph_status_t>(),   Info<sim_contact_t>(),    Info<sim_status_t>(),
      Info<sim_event_t>(),      Info<tracker_status_t>(), Info<gripper_command_t>(), Info<mission_status_t>(),
      Info<drive_status_t>(),   Info<drive_command_t>(),
      Info<motorsim_fault_t>(), Info<planner_paths_t>()};
  return kTypes;
}

std::optional<MessageTypeInfo> IdentifyMessage(const void* data, std::size_t size) {
  if (data == nullptr || size < 8) return std::nullopt;
  const std::int64_t fingerprint = internal::ReadFingerprint(static_cast<const unsigned char*>(data));
  for (const MessageTypeInfo& info : AllMessageTypes()) {
    if (info.fingerprint == fingerprint) return info;
  }
  return std::nullopt;
}

}  // namespace topay::msgs
