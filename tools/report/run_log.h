#pragma once
// A closed-loop run's LCM log, read once and decoded: the messages the report uses, in log
// order, the occupancy map at the end of the run, and per channel the message and decode
// failure counts. Malformed messages are counted, never followed (and never crash the reader).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/map/grid_geometry.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/convert_trajectory.h"
#include "topay/goal_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::report {

/// Messages and failures of one channel.
struct ChannelCount {
  std::int64_t messages = 0;
  /// Messages that failed CheckedDecode as the channel's type (wrong type, truncated,
  /// corrupted, trailing bytes), or whose contents the conversion refused (non-finite robot
  /// state, a malformed map update); on other channels: an unknown fingerprint or a failed
  /// decode of the type it names.
  std::int64_t decode_failures = 0;
};

/// One TRAJECTORY, rebuilt into the core trajectory (procs/msgs/trajectory_from_message.h).
struct LoggedTrajectory {
  msgs::PolyTrajectory poly;       ///< ids, start_utime, publication utime, coefficients
  ArcYawTrajectory trajectory;     ///< evaluable: poses, v, omega, joints over [0, duration]
};

/// The occupancy map at the end of the run (MAP_UPDATE snapshots and deltas applied in order).
struct FinalMap {
  GridGeometry3 geometry;
  std::vector<std::uint8_t> states;  ///< one VoxelState per voxel, linear order
};

/// What the report reads from a log. Vectors hold the decoded messages in log order.
struct RunLog {
  std::string path;
  std::int64_t first_utime = 0;  ///< the log's first and last event timestamps, us
  std::int64_t last_utime = 0;
  std::vector<mission_status_t> mission_statuses;
  std::vector<planner_status_t> planner_statuses;
  std::vector<tracker_status_t> tracker_statuses;
  std::vector<sim_status_t> sim_statuses;
  std::vector<sim_contact_t> sim_contacts;
  std::vector<sim_event_t> sim_events;
  std::vector<goal_t> goals;
  std::vector<msgs::RobotStateEstimate> robot_states;
  /// The plant's true state (SIM_PLANT_STATE: topay-sim in CAN mode); empty in other graphs.
  std::vector<msgs::RobotStateEstimate> plant_states;
  /// Every TRAJECTORY message that decoded; `trajectories` those that also rebuilt.
  std::int64_t trajectory_messages = 0;
  std::vector<LoggedTrajectory> trajectories;
  std::optional<FinalMap> map;  ///< nullopt: no snapshot in the log
  std::map<std::string, ChannelCount> channels;
};

/// Reads the whole log. Throws std::runtime_error "<path>: <what>" if the file cannot be
/// opened or is not an LCM log (a non-empty file of which no event can be read).
RunLog ReadRunLog(const std::string& path);

}  // namespace topay::report
