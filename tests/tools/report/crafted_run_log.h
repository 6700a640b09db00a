#pragma once
// A hand-made closed-loop run log for topay-report's tests: a few messages on each channel
// with values chosen so that every summary number can be worked out by hand (the tests say
// how), three malformed payloads, two rebuildable trajectories and one that is not a MINCO
// solution, and a small map (snapshot + delta). Written with lcm::LogFile; no LCM bus.

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/map_codec.h"
#include "topay/goal_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/tracker_status_t.hpp"

namespace topay::report::test {

/// A fresh folder for the running test: <build>/test_out/report/<suite>/<test> (ctest runs the
/// cases of one file in parallel processes, so no two share a folder).
inline std::string FreshTestDir(const std::string& suite) {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/report/" + suite + "/" +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// t = 0 of the crafted run, us since the epoch.
inline constexpr std::int64_t kT0Utime = 1'700'000'000'000'000;
inline constexpr int kJoints = 7;
inline constexpr int kRobotStates = 21;  ///< one every 100 ms, t = 0 .. 2 s

inline std::int64_t At(double t_s) { return kT0Utime + static_cast<std::int64_t>(t_s * 1e6 + 0.5); }

/// The base at ROBOT_STATE k: 0.3 m along x per state up to (3, 0) at k = 10, then 0.4 m along
/// y per state up to (3, 4) at k = 20: 7 m driven.
inline Eigen::Vector2d BaseAt(int k) {
  return {0.3 * std::min(k, 10), 0.4 * std::max(k - 10, 0)};
}

class CraftedLogWriter {
 public:
  explicit CraftedLogWriter(const std::string& path) : log_(path, "w") {}
  bool good() const { return log_.good(); }

  template <class Msg>
  void Publish(std::int64_t utime, const std::string& channel, const Msg& msg) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
    msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    Raw(utime, channel, bytes);
  }
  void Raw(std::int64_t utime, const std::string& channel, std::vector<std::uint8_t> bytes) {
    lcm::LogEvent event;
    event.eventnum = 0;
    event.timestamp = utime;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    log_.writeEvent(&event);
  }

 private:
  lcm::LogFile log_;
};

inline mission_status_t Mission(double elapsed_s, std::int8_t state, int step, const std::string& what,
                                int attempts, const std::string& detail = "") {
  mission_status_t m;
  m.utime = 0;  // set when published
  m.mission = "two_goals";
  m.state = state;
  m.step_index = step;
  m.num_steps = 3;
  m.step = what;
  m.goal_id = 0;
  m.attempts = attempts;
  m.elapsed_s = elapsed_s;
  m.detail = detail;
  return m;
}

inline planner_status_t Planner(std::int8_t state, std::int64_t goal, std::int64_t trajectory, double total_ms,
                                int replans, const std::string& reason = "") {
  planner_status_t p;
  p.utime = kT0Utime;
  p.state = state;
  p.goal_id = goal;
  p.trajectory_id = trajectory;
  p.failure_reason = reason;
  p.front_end_ms = p.sampling_ms = p.optimization_ms = 0.0;
  p.total_ms = total_ms;
  p.replans = replans;
  p.detail = "";
  return p;
}

inline tracker_status_t Tracker(std::int8_t state, double position_m, double yaw_rad, double joint_rad,
                                double solve_ms) {
  tracker_status_t t;
  t.utime = kT0Utime;
  t.state = state;
  t.trajectory_id = 101;
  t.goal_id = 11;
  t.t_along_s = 0.0;
  t.position_error_m = position_m;
  t.yaw_error_rad = yaw_rad;
  t.joint_error_rad = joint_rad;
  t.solve_ms = solve_ms;
  return t;
}

inline sim_status_t SimStatus(std::int64_t events, std::int64_t steps, double depth_m) {
  sim_status_t s{};
  s.utime = kT0Utime;
  s.contact_events = events;
  s.contact_steps = steps;
  s.max_depth_m = depth_m;
  return s;
}

inline sim_event_t Appear(std::int32_t id, bool has_box, const Eigen::Vector3d& centre, const std::string& name) {
  sim_event_t e{};
  e.name = name;
  e.action = sim_event_t::APPEAR;
  e.box_id = id;
  e.has_box = has_box;
  for (int a = 0; a < 3; ++a) {
    e.center_m[a] = centre(a);
    e.size_m[a] = 0.4;
  }
  e.trigger = sim_event_t::NOW;
  return e;
}

inline robot_state_t RobotState(int k) {
  msgs::RobotStateEstimate s;
  s.utime = At(0.1 * k);
  s.state.x_m = BaseAt(k).x();
  s.state.y_m = BaseAt(k).y();
  s.state.yaw_rad = k <= 10 ? 0.0 : 1.5707963267948966;
  s.state.q_rad = Eigen::VectorXd::Constant(kJoints, 0.05 * k);
  s.v_mps = 0.5;
  s.omega_radps = 0.1;
  s.qdot_radps = Eigen::VectorXd::Zero(kJoints);
  s.gripper = 0.0;
  return msgs::ToMessage(s);
}

/// 1.5 m of arc, a 0.6 rad turn and every joint +0.4 rad over 6 s, from rest to rest, from
/// (x0, y0) = (0, 1) (away from the driven path).
inline ArcYawTrajectory SmoothTrajectory() {
  ArcYawTrajectory trajectory(kJoints, 2, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(kJoints + 2, 3), tail = Eigen::MatrixXd::Zero(kJoints + 2, 3);
  tail(0, 0) = 1.5;
  tail(1, 0) = 0.6;
  tail.col(0).tail(kJoints).setConstant(0.4);
  trajectory.Update(Eigen::Vector2d(0.0, 1.0), head, tail, 0.5 * (head.col(0) + tail.col(0)),
                    Eigen::Vector2d(3.0, 3.0));
  return trajectory;
}

inline poly_trajectory_t TrajectoryMessage(std::int64_t id, double published_s, double start_s) {
  msgs::PolyTrajectory poly = msgs::FromArcYaw(SmoothTrajectory(), Eigen::Vector2d(0.0, 1.0));
  poly.utime = At(published_s);
  poly.trajectory_id = id;
  poly.goal_id = 11;
  poly.start_utime = At(start_s);
  return msgs::ToMessage(poly);
}

/// The map: 40 x 40 x 10 voxels of 0.1 m from (-1, -1, 0), all free but one occupied column
/// top at voxel (1, 25, 4) (x -0.9..-0.8, y 1.5..1.6, top 0.5 m) in the snapshot; the delta
/// makes voxel (1, 25, 7) occupied too (top 0.8 m).
inline GridGeometry3 MapGeometry() {
  GridGeometry3 g;
  g.origin_W_m = Eigen::Vector3d(-1.0, -1.0, 0.0);
  g.resolution_m = 0.1;
  g.dims = Eigen::Vector3i(40, 40, 10);
  return g;
}

inline void WriteMap(CraftedLogWriter* log) {
  const GridGeometry3 g = MapGeometry();
  std::vector<std::uint8_t> states(static_cast<std::size_t>(g.NumCells()),
                                   static_cast<std::uint8_t>(VoxelState::kFree));
  states[g.Index(1, 25, 4)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
  log->Publish(At(0.5), "MAP_UPDATE", msgs::EncodeFullMap(g, states, At(0.5), 1));
  const std::vector<VoxelChange> changes = {{Eigen::Vector3i(1, 25, 7), VoxelState::kOccupied}};
  log->Publish(At(0.6), "MAP_UPDATE", msgs::EncodeMapDelta(g, changes, At(0.6), 2));
}

// Statuses at log times 0, 0.5, 0.7, 1.0, 1.1 and 2.0 s (utime = log time) with the mission's
// own elapsed times 0, 0.5, 3.0, 4.5, 5.0 and 9.0 s. The gripper step carries the goto's
// attempts, as topay-mission's statuses do.
inline void WriteMission(CraftedLogWriter* log) {
  auto publish = [log](double log_s, mission_status_t status) {
    status.utime = At(log_s);
    log->Publish(status.utime, "MISSION_STATUS", status);
  };
  publish(0.0, Mission(0.0, mission_status_t::IDLE, 0, "goto pickup", 0));
  publish(0.5, Mission(0.5, mission_status_t::RUNNING, 0, "goto pickup", 1));
  publish(0.7, Mission(3.0, mission_status_t::RUNNING, 0, "goto pickup", 2, "attempt 1 failed"));
  publish(1.0, Mission(4.5, mission_status_t::RUNNING, 1, "gripper close", 2));
  publish(1.1, Mission(5.0, mission_status_t::RUNNING, 2, "home", 1));
  publish(2.0, Mission(9.0, mission_status_t::SUCCEEDED, 2, "home", 1, "every step done"));
}

inline void WritePlanner(CraftedLogWriter* log) {
  const std::string ch = "PLANNER_STATUS";
  using P = planner_status_t;
  for (const P& p : {Planner(P::PLANNING, 11, 0, 0.0, 0), Planner(P::SUCCEEDED, 11, 101, 100.0, 0),
                     Planner(P::SUCCEEDED, 11, 101, 100.0, 0), Planner(P::STOPPING, 11, 102, 0.0, 1),
                     Planner(P::STOPPING, 11, 102, 0.0, 1), Planner(P::SUCCEEDED, 11, 103, 300.0, 2),
                     Planner(P::SUCCEEDED, 11, 103, 300.0, 2), Planner(P::FAILED, 12, 0, 0.0, 0, "no goal"),
                     Planner(P::FAILED, 12, 0, 0.0, 0, "no goal"), Planner(P::SUCCEEDED, 13, 104, 200.0, 1),
                     Planner(P::FAILED, 14, 0, 0.0, 0, "target unreachable")}) {
    log->Publish(At(0.3), ch, p);
  }
}

inline void WriteTracker(CraftedLogWriter* log) {
  const std::string ch = "TRACKER_STATUS";
  using T = tracker_status_t;
  for (const T& t : {Tracker(T::IDLE, 9.0, 9.0, 9.0, 90.0), Tracker(T::TRACKING, 0.01, 0.02, 0.001, 1.0),
                     Tracker(T::TRACKING, 0.02, -0.04, 0.002, 2.0), Tracker(T::TRACKING, 0.02, 0.0, 0.002, 3.0),
                     Tracker(T::TRACKING, 0.04, 0.02, 0.004, 4.0), Tracker(T::STOPPING, 0.5, 0.5, 0.5, 50.0),
                     Tracker(T::FINISHED, 0.3, 0.3, 0.3, 30.0)}) {
    log->Publish(At(0.4), ch, t);
  }
}

inline void WriteSim(CraftedLogWriter* log) {
  log->Publish(At(0.1), "SIM_STATUS", SimStatus(0, 0, 0.0));
  log->Publish(At(1.9), "SIM_STATUS", SimStatus(2, 7, 0.012));
  sim_contact_t contact;
  contact.body = "base";
  contact.box_id = 3;
  contact.depth_m = 0.004;
  for (int k : {2, 18}) {  // at ROBOT_STATE 2 (0.6, 0) and 18 (3, 3.2)
    contact.utime = At(0.1 * k) + 20'000;
    log->Publish(contact.utime, "SIM_CONTACT", contact);
  }
  log->Publish(At(1.0), "SIM_EVENT", Appear(40, true, {1.5, 2.5, 0.4}, "crate"));
  sim_event_t gone = Appear(3, false, Eigen::Vector3d::Zero(), "gone");
  gone.action = sim_event_t::DISAPPEAR;
  log->Publish(At(1.2), "SIM_EVENT", gone);
  log->Publish(At(1.3), "SIM_EVENT", Appear(5, false, Eigen::Vector3d::Zero(), "back"));
}

inline void WriteGoalAndTrajectories(CraftedLogWriter* log) {
  goal_t goal{};
  goal.utime = At(0.2);
  goal.goal_id = 11;
  goal.p_WE[0] = 2.0;
  goal.p_WE[1] = -0.5;
  goal.p_WE[2] = 0.8;
  goal.quat_WE[0] = 1.0;
  goal.has_hint = false;
  goal.hint.num_joints = 0;
  log->Publish(At(0.2), "GOAL", goal);
  log->Publish(At(0.25), "TRAJECTORY", TrajectoryMessage(101, 0.25, 0.3));   // active from 0.3 s
  poly_trajectory_t bent = TrajectoryMessage(102, 0.8, 0.8);
  bent.coeffs[3] += 0.5;  // no longer a MINCO solution: decodes, does not rebuild
  log->Publish(At(0.8), "TRAJECTORY", bent);
  log->Publish(At(1.05), "TRAJECTORY", TrajectoryMessage(103, 1.05, 1.0));  // published late: active from 1.05 s
}

/// Writes the crafted run to `path` (its folder created).
inline void WriteCraftedRunLog(const std::string& path) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  CraftedLogWriter log(path);
  WriteMission(&log);
  WritePlanner(&log);
  WriteTracker(&log);
  WriteSim(&log);
  WriteGoalAndTrajectories(&log);
  WriteMap(&log);
  for (int k = 0; k < kRobotStates; ++k) log.Publish(At(0.1 * k), "ROBOT_STATE", RobotState(k));
  // Malformed: garbage on ROBOT_STATE, a tracker status on PLANNER_STATUS, an unknown type.
  log.Raw(At(0.55), "ROBOT_STATE", {1, 2, 3, 4, 5});
  log.Publish(At(0.56), "PLANNER_STATUS", Tracker(tracker_status_t::IDLE, 0, 0, 0, 0));
  log.Raw(At(0.57), "MYSTERY", {9, 9, 9, 9, 9, 9, 9, 9, 9});
  log.Raw(At(0.58), "LCM_SELF_TEST", {'l', 'c', 'm'});  // LCM's probe: not a failure
}

}  // namespace topay::report::test
