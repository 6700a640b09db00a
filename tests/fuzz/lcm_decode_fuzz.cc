// Every LCM type of lcmtypes/ from untrusted bytes: CheckedDecode (every subscriber's first
// step) with the round-trip check of lcm_fuzz.h, the type registry the log tools use, and the
// stateless conversions to core types (goal, robot state, trajectory, map snapshot and delta).
// Input: [selector][bytes...] (lcm_fuzz.h; one message, the rest of the input).
#include <cstdint>
#include <string>
#include <tuple>

#include "procs/msgs/convert_goal.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/map_codec.h"
#include "procs/msgs/trajectory_from_message.h"
#include "procs/msgs/type_registry.h"
#include "tests/fuzz/lcm_fuzz.h"
#include "topay/base_pose_t.hpp"
#include "topay/base_velocity_t.hpp"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/graph_status_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/joint_state_t.hpp"
#include "topay/map_update_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/planner_paths_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"
#include "topay/whole_body_state_t.hpp"

namespace topay::fuzz {
namespace {

using AllTypes = std::tuple<base_pose_t, base_velocity_t, control_command_t, drive_command_t, drive_status_t,
                            goal_t, graph_status_t, gripper_command_t, heartbeat_t, joint_state_t, map_update_t,
                            mission_status_t, motorsim_fault_t, planner_paths_t, planner_status_t, point_cloud_t,
                            poly_trajectory_t, robot_state_t, sim_contact_t, sim_event_t, sim_status_t,
                            tracker_status_t, whole_body_state_t>;

// What a subscriber does next with a decoded message, where a library does it.
template <class Msg>
void Convert(const Msg&) {}

template <>
void Convert(const goal_t& msg) {
  std::string error;
  if (!msgs::FromMessage(msg, &error)) FuzzCheck(!error.empty(), "a refused goal names why");
}
template <>
void Convert(const robot_state_t& msg) {
  std::string error;
  if (!msgs::FromMessage(msg, &error)) FuzzCheck(!error.empty(), "a refused state names why");
}
template <>
void Convert(const poly_trajectory_t& msg) {
  std::string error;
  const std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(msg, &error);
  if (!poly) {
    FuzzCheck(!error.empty(), "a refused trajectory names why");
    return;
  }
  error.clear();
  if (!msgs::ToArcYaw(*poly, msgs::TrajectoryRebuildOptions{}, &error)) {
    FuzzCheck(!error.empty(), "a trajectory that cannot be rebuilt names why");
  }
}
template <>
void Convert(const map_update_t& msg) {
  const msgs::MapCodecOptions options;
  std::string error;
  const bool ok = msg.is_full ? msgs::DecodeFullMap(msg, options, &error).has_value()
                              : msgs::DecodeMapDelta(msg, options, &error).has_value();
  FuzzCheck(ok || !error.empty(), "a refused map update names why");
}

template <std::size_t I = 0>
void DecodeAs(std::size_t index, const LcmRecord& record) {
  if constexpr (I < std::tuple_size_v<AllTypes>) {
    if (index != I) return DecodeAs<I + 1>(index, record);
    using Msg = std::tuple_element_t<I, AllTypes>;
    if (const std::optional<Msg> msg = DecodeFuzzed<Msg>(record.bytes, record.fix_fingerprint)) {
      Convert(*msg);
      const auto info = msgs::IdentifyMessage(record.bytes.data(), record.bytes.size());
      if (!record.fix_fingerprint) FuzzCheck(info && info->fingerprint == Msg::getHash(), "the registry knows it");
    }
  }
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const std::uint8_t selector = in.Byte();
  const LcmRecord record{selector & 0x7f, (selector & 0x80) != 0, in.Rest()};
  DecodeAs(static_cast<std::size_t>(record.channel) % std::tuple_size_v<AllTypes>, record);
  // The log tools identify any bytes.
  if (const auto info = topay::msgs::IdentifyMessage(record.bytes.data(), record.bytes.size())) {
    std::string error;
    info->check(record.bytes.data(), record.bytes.size(), &error);
  }
  return 0;
}
