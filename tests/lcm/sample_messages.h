#pragma once
// Test support for the LCM message catalogue: for every topay message type, a sample with
// non-trivial contents (negative numbers, non-empty arrays and strings) and a field-by-field
// comparison, gathered in MessageSample<T> so typed tests cover every type without copies.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "topay/base_pose_t.hpp"
#include "topay/base_velocity_t.hpp"
#include "topay/control_command_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/graph_status_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/joint_state_t.hpp"
#include "topay/map_update_t.hpp"
#include "topay/planner_paths_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/tracker_status_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"
#include "topay/whole_body_state_t.hpp"

namespace topay::test {

// A list of message types: as gtest's type list (TYPED_TEST_SUITE) and as a compile-time loop.
template <class... Msgs>
struct MessageList {
  static constexpr int kSize = sizeof...(Msgs);
  using GtestTypes = ::testing::Types<Msgs...>;
  // Calls visit(static_cast<Msg*>(nullptr)) for every type in the list.
  template <class Visitor>
  static void ForEach(Visitor&& visit) {
    (visit(static_cast<Msgs*>(nullptr)), ...);
  }
};

// The whole catalogue: every lcmtypes/*.lcm.
using Catalogue =
    MessageList<base_pose_t, base_velocity_t, joint_state_t, robot_state_t, whole_body_state_t,
                point_cloud_t, map_update_t, goal_t, poly_trajectory_t, control_command_t,
                planner_status_t, heartbeat_t, graph_status_t, sim_contact_t, sim_status_t,
                sim_event_t, tracker_status_t, motorsim_fault_t, planner_paths_t>;
using AllMessageTypes = Catalogue::GtestTypes;

// Names typed tests after the message type ("RoundTrip/joint_state_t") instead of 0, 1, ...
struct MessageTypeName {
  template <class Msg>
  static std::string GetName(int) {
    return Msg::getTypeName();
  }
};

// n values start, start + step, ... (type T).
template <class T>
std::vector<T> Ramp(int n, T start, T step) {
  std::vector<T> values(n);
  for (int i = 0; i < n; ++i) values[i] = start + static_cast<T>(i) * step;
  return values;
}

// Encodes msg into a buffer of exactly getEncodedSize() bytes (fails the test on error).
template <class Msg>
std::vector<std::uint8_t> Encode(const Msg& msg) {
  std::vector<std::uint8_t> bytes(msg.getEncodedSize());
  const int written = msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  EXPECT_EQ(written, static_cast<int>(bytes.size())) << Msg::getTypeName();
  return bytes;
}

template <class Msg>
struct MessageSample;  // static Msg Make(); static void ExpectSame(const Msg&, const Msg&);

template <>
struct MessageSample<base_pose_t> {
  static base_pose_t Make() {
    base_pose_t m;
    m.utime = 1'700'000'000'123'456;
    m.x_m = -3.25;
    m.y_m = 7.5e-3;
    m.yaw_rad = -2.75;
    return m;
  }
  static void ExpectSame(const base_pose_t& a, const base_pose_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.x_m, b.x_m);
    EXPECT_EQ(a.y_m, b.y_m);
    EXPECT_EQ(a.yaw_rad, b.yaw_rad);
  }
};

template <>
struct MessageSample<base_velocity_t> {
  static base_velocity_t Make() {
    base_velocity_t m;
    m.utime = 1'700'000'000'223'456;
    m.v_mps = -0.8;
    m.omega_radps = 1.25;
    return m;
  }
  static void ExpectSame(const base_velocity_t& a, const base_velocity_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.v_mps, b.v_mps);
    EXPECT_EQ(a.omega_radps, b.omega_radps);
  }
};

template <>
struct MessageSample<joint_state_t> {
  static joint_state_t Make() {
    joint_state_t m;
    m.utime = 1'700'000'000'323'456;
    m.num_joints = 7;
    for (int i = 0; i < m.num_joints; ++i) m.names.push_back("joint" + std::to_string(i + 1));
    m.names[3] = "";  // an empty string is legal and must survive
    m.position_rad = Ramp(7, -3.1, 0.9);
    m.velocity_radps = Ramp(7, 2.35, -0.7);
    m.effort_Nm = Ramp(7, -40.0, 11.5);
    return m;
  }
  static void ExpectSame(const joint_state_t& a, const joint_state_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.num_joints, b.num_joints);
    EXPECT_EQ(a.names, b.names);
    EXPECT_EQ(a.position_rad, b.position_rad);
    EXPECT_EQ(a.velocity_radps, b.velocity_radps);
    EXPECT_EQ(a.effort_Nm, b.effort_Nm);
  }
};

template <>
struct MessageSample<robot_state_t> {
  static robot_state_t Make() {
    robot_state_t m;
    m.utime = 1'700'000'000'423'456;
    m.pose = MessageSample<base_pose_t>::Make();
    m.velocity = MessageSample<base_velocity_t>::Make();
    m.joints = MessageSample<joint_state_t>::Make();
    m.gripper = 0.375;
    return m;
  }
  static void ExpectSame(const robot_state_t& a, const robot_state_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    MessageSample<base_pose_t>::ExpectSame(a.pose, b.pose);
    MessageSample<base_velocity_t>::ExpectSame(a.velocity, b.velocity);
    MessageSample<joint_state_t>::ExpectSame(a.joints, b.joints);
    EXPECT_EQ(a.gripper, b.gripper);
  }
};

template <>
struct MessageSample<whole_body_state_t> {
  static whole_body_state_t Make() {
    whole_body_state_t m;
    m.utime = -1;  // negative on purpose: the encoding is two's complement
    m.x_m = 12.5;
    m.y_m = -9.75;
    m.yaw_rad = 3.0;
    m.num_joints = 7;
    m.q_rad = Ramp(7, 2.2, -0.65);
    return m;
  }
  static void ExpectSame(const whole_body_state_t& a, const whole_body_state_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.x_m, b.x_m);
    EXPECT_EQ(a.y_m, b.y_m);
    EXPECT_EQ(a.yaw_rad, b.yaw_rad);
    EXPECT_EQ(a.num_joints, b.num_joints);
    EXPECT_EQ(a.q_rad, b.q_rad);
  }
};

template <>
struct MessageSample<point_cloud_t> {
  static point_cloud_t Make() {
    point_cloud_t m;
    m.utime = 1'700'000'000'523'456;
    m.sensor_frame = "head_depth_optical";
    const double p_WS[3] = {0.1, -0.2, 1.45};
    const double quat_WS[4] = {0.5, -0.5, 0.5, -0.5};
    for (int i = 0; i < 3; ++i) m.p_WS[i] = p_WS[i];
    for (int i = 0; i < 4; ++i) m.quat_WS[i] = quat_WS[i];
    m.num_coords = 3 * 20;
    m.p_SP = Ramp(m.num_coords, -1.5f, 0.125f);
    return m;
  }
  static void ExpectSame(const point_cloud_t& a, const point_cloud_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.sensor_frame, b.sensor_frame);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.p_WS[i], b.p_WS[i]) << i;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(a.quat_WS[i], b.quat_WS[i]) << i;
    EXPECT_EQ(a.num_coords, b.num_coords);
    EXPECT_EQ(a.p_SP, b.p_SP);
  }
};

template <>
struct MessageSample<map_update_t> {
  static map_update_t Make() {
    map_update_t m;
    m.utime = 1'700'000'000'623'456;
    m.map_seq = 42;
    m.resolution_m = 0.1;
    const double origin_W[3] = {-10.0, -10.0, 0.0};
    const int32_t dims[3] = {200, 200, 16};
    for (int i = 0; i < 3; ++i) m.origin_W[i] = origin_W[i];
    for (int i = 0; i < 3; ++i) m.dims[i] = dims[i];
    m.is_full = false;
    m.num_indices = 9;
    m.indices = Ramp<int32_t>(9, 17, 40'001);
    m.num_values = 9;
    for (int k = 0; k < 9; ++k) {
      const int8_t states[3] = {map_update_t::UNKNOWN, map_update_t::FREE, map_update_t::OCCUPIED};
      m.values.push_back(states[k % 3]);
    }
    // Every field set, though a real message fills either indices/values or the payload
    // (procs/msgs/map_codec.h writes and checks the payload).
    m.compression = map_update_t::COMPRESSION_ZLIB;
    m.num_payload_voxels = 9;
    m.payload_raw_bytes = 11;
    m.num_payload_bytes = 6;
    m.payload = {0x78, 0x01, 0x00, 0xff, 0x80, 0x7f};
    return m;
  }
  static void ExpectSame(const map_update_t& a, const map_update_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.map_seq, b.map_seq);
    EXPECT_EQ(a.resolution_m, b.resolution_m);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.origin_W[i], b.origin_W[i]) << i;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.dims[i], b.dims[i]) << i;
    EXPECT_EQ(a.is_full, b.is_full);
    EXPECT_EQ(a.num_indices, b.num_indices);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.num_values, b.num_values);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.compression, b.compression);
    EXPECT_EQ(a.num_payload_voxels, b.num_payload_voxels);
    EXPECT_EQ(a.payload_raw_bytes, b.payload_raw_bytes);
    EXPECT_EQ(a.num_payload_bytes, b.num_payload_bytes);
    EXPECT_EQ(a.payload, b.payload);
  }
};

template <>
struct MessageSample<goal_t> {
  static goal_t Make() {
    goal_t m;
    m.utime = 1'700'000'000'723'456;
    m.goal_id = -77;
    const double p_WE[3] = {4.5, -2.25, 0.9};
    const double quat_WE[4] = {0.0, 1.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) m.p_WE[i] = p_WE[i];
    for (int i = 0; i < 4; ++i) m.quat_WE[i] = quat_WE[i];
    m.has_hint = true;
    m.hint = MessageSample<whole_body_state_t>::Make();
    return m;
  }
  static void ExpectSame(const goal_t& a, const goal_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.goal_id, b.goal_id);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.p_WE[i], b.p_WE[i]) << i;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(a.quat_WE[i], b.quat_WE[i]) << i;
    EXPECT_EQ(a.has_hint, b.has_hint);
    MessageSample<whole_body_state_t>::ExpectSame(a.hint, b.hint);
  }
};

template <>
struct MessageSample<poly_trajectory_t> {
  static poly_trajectory_t Make() {
    poly_trajectory_t m;
    m.utime = 1'700'000'000'823'456;
    m.trajectory_id = 9'000'000'001;
    m.goal_id = -77;
    m.start_utime = 1'700'000'001'000'000;
    m.x0_m = -4.0;
    m.y0_m = 3.5;
    m.yaw0_rad = -1.5;
    m.num_pieces = 3;
    m.num_joints = 7;
    m.durations_s = Ramp(3, 1.5, 0.25);
    m.num_coeffs = m.num_pieces * (2 + m.num_joints) * 6;
    m.coeffs = Ramp(m.num_coeffs, -2.0, 0.03125);
    return m;
  }
  static void ExpectSame(const poly_trajectory_t& a, const poly_trajectory_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.trajectory_id, b.trajectory_id);
    EXPECT_EQ(a.goal_id, b.goal_id);
    EXPECT_EQ(a.start_utime, b.start_utime);
    EXPECT_EQ(a.x0_m, b.x0_m);
    EXPECT_EQ(a.y0_m, b.y0_m);
    EXPECT_EQ(a.yaw0_rad, b.yaw0_rad);
    EXPECT_EQ(a.num_pieces, b.num_pieces);
    EXPECT_EQ(a.num_joints, b.num_joints);
    EXPECT_EQ(a.durations_s, b.durations_s);
    EXPECT_EQ(a.num_coeffs, b.num_coeffs);
    EXPECT_EQ(a.coeffs, b.coeffs);
  }
};

template <>
struct MessageSample<control_command_t> {
  static control_command_t Make() {
    control_command_t m;
    m.utime = 1'700'000'000'923'456;
    m.trajectory_id = 9'000'000'001;
    m.v_mps = 0.6;
    m.omega_radps = -0.45;
    m.num_joints = 7;
    m.qdot_radps = Ramp(7, -1.2, 0.4);
    m.gripper = 1.0;
    return m;
  }
  static void ExpectSame(const control_command_t& a, const control_command_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.trajectory_id, b.trajectory_id);
    EXPECT_EQ(a.v_mps, b.v_mps);
    EXPECT_EQ(a.omega_radps, b.omega_radps);
    EXPECT_EQ(a.num_joints, b.num_joints);
    EXPECT_EQ(a.qdot_radps, b.qdot_radps);
    EXPECT_EQ(a.gripper, b.gripper);
  }
};

template <>
struct MessageSample<planner_paths_t> {
  static planner_paths_t Make() {
    planner_paths_t m;
    m.utime = 1'700'000'001'500'000;
    m.goal_id = 12;
    m.trajectory_id = 34;
    m.chosen = 1;
    m.num_paths = 2;
    m.path_points = {3, 4};
    m.length_m = {1.5, 2.5};
    m.source = {"topological_prm", "jps"};
    for (int k = 0; k < 7; ++k) {
      m.x_m.push_back(0.5 * k);
      m.y_m.push_back(1.0 - 0.25 * k);
    }
    m.num_points = 7;
    return m;
  }
  static void ExpectSame(const planner_paths_t& a, const planner_paths_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.goal_id, b.goal_id);
    EXPECT_EQ(a.trajectory_id, b.trajectory_id);
    EXPECT_EQ(a.chosen, b.chosen);
    EXPECT_EQ(a.num_paths, b.num_paths);
    EXPECT_EQ(a.path_points, b.path_points);
    EXPECT_EQ(a.length_m, b.length_m);
    EXPECT_EQ(a.source, b.source);
    EXPECT_EQ(a.num_points, b.num_points);
    EXPECT_EQ(a.x_m, b.x_m);
    EXPECT_EQ(a.y_m, b.y_m);
  }
};

template <>
struct MessageSample<planner_status_t> {
  static planner_status_t Make() {
    planner_status_t m;
    m.utime = 1'700'000'001'023'456;
    m.state = planner_status_t::FAILED;
    m.goal_id = -77;
    m.trajectory_id = 0;
    m.failure_reason = "no collision-free arm path along any of 6 base paths";
    m.front_end_ms = 9.5;
    m.sampling_ms = 187.25;
    m.optimization_ms = -1.0;  // not run
    m.total_ms = 201.0;
    m.replans = 3;
    m.detail = "replan: the map shows a collision 2.40 s ahead";
    return m;
  }
  static void ExpectSame(const planner_status_t& a, const planner_status_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.goal_id, b.goal_id);
    EXPECT_EQ(a.trajectory_id, b.trajectory_id);
    EXPECT_EQ(a.failure_reason, b.failure_reason);
    EXPECT_EQ(a.front_end_ms, b.front_end_ms);
    EXPECT_EQ(a.sampling_ms, b.sampling_ms);
    EXPECT_EQ(a.optimization_ms, b.optimization_ms);
    EXPECT_EQ(a.total_ms, b.total_ms);
    EXPECT_EQ(a.replans, b.replans);
    EXPECT_EQ(a.detail, b.detail);
  }
};

template <>
struct MessageSample<tracker_status_t> {
  static tracker_status_t Make() {
    tracker_status_t m;
    m.utime = 1'700'000'001'523'456;
    m.state = tracker_status_t::TRACKING;
    m.trajectory_id = 12;
    m.goal_id = 4;
    m.t_along_s = 3.25;
    m.position_error_m = 0.021;
    m.yaw_error_rad = -0.013;
    m.joint_error_rad = 0.004;
    m.solve_ms = 1.2;
    return m;
  }
  static void ExpectSame(const tracker_status_t& a, const tracker_status_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.trajectory_id, b.trajectory_id);
    EXPECT_EQ(a.goal_id, b.goal_id);
    EXPECT_EQ(a.t_along_s, b.t_along_s);
    EXPECT_EQ(a.position_error_m, b.position_error_m);
    EXPECT_EQ(a.yaw_error_rad, b.yaw_error_rad);
    EXPECT_EQ(a.joint_error_rad, b.joint_error_rad);
    EXPECT_EQ(a.solve_ms, b.solve_ms);
  }
};

template <>
struct MessageSample<motorsim_fault_t> {
  static motorsim_fault_t Make() {
    motorsim_fault_t m;
    m.utime = 1'700'000'001'623'456;
    m.kind = motorsim_fault_t::HEARTBEAT_LOSS;
    m.joint = 3;
    m.duration_s = 1.5;
    m.value = 12.5;
    m.code = 0x2310;
    return m;
  }
  static void ExpectSame(const motorsim_fault_t& a, const motorsim_fault_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.joint, b.joint);
    EXPECT_EQ(a.duration_s, b.duration_s);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.code, b.code);
  }
};

template <>
struct MessageSample<heartbeat_t> {
  static heartbeat_t Make() {
    heartbeat_t m;
    m.utime = 1'700'000'001'123'456;
    m.process_name = "topay-planner";
    m.pid = 31337;
    m.seq = 123'456'789'012;
    m.health = heartbeat_t::WARN;
    m.status = "map stale for 2.5 s";
    return m;
  }
  static void ExpectSame(const heartbeat_t& a, const heartbeat_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.process_name, b.process_name);
    EXPECT_EQ(a.pid, b.pid);
    EXPECT_EQ(a.seq, b.seq);
    EXPECT_EQ(a.health, b.health);
    EXPECT_EQ(a.status, b.status);
  }
};

template <>
struct MessageSample<graph_status_t> {
  static graph_status_t Make() {
    graph_status_t m;
    m.utime = 1'700'000'001'223'456;
    m.graph_name = "sim";
    m.run_dir = "out/runs/20261202-101500";
    m.num_processes = 3;
    m.names = {"robot-model", "", "lcm-logger"};
    m.states = {graph_status_t::RUNNING, graph_status_t::BACKOFF, graph_status_t::STARTING};
    m.pids = {4242, 0, -7};
    m.restarts = {0, 12, 1};
    m.cpu_percent = {1.5f, 0.0f, 99.25f};
    m.rss_kB = {10240, 0, 8'000'000'000};
    m.heartbeat_age_s = {0.25f, -1.0f, 3.5f};
    m.health = {heartbeat_t::OK, -1, heartbeat_t::ERROR};
    return m;
  }
  static void ExpectSame(const graph_status_t& a, const graph_status_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.graph_name, b.graph_name);
    EXPECT_EQ(a.run_dir, b.run_dir);
    EXPECT_EQ(a.num_processes, b.num_processes);
    EXPECT_EQ(a.names, b.names);
    EXPECT_EQ(a.states, b.states);
    EXPECT_EQ(a.pids, b.pids);
    EXPECT_EQ(a.restarts, b.restarts);
    EXPECT_EQ(a.cpu_percent, b.cpu_percent);
    EXPECT_EQ(a.rss_kB, b.rss_kB);
    EXPECT_EQ(a.heartbeat_age_s, b.heartbeat_age_s);
    EXPECT_EQ(a.health, b.health);
  }
};

template <>
struct MessageSample<sim_contact_t> {
  static sim_contact_t Make() {
    sim_contact_t m;
    m.utime = 1'700'000'001'323'456;
    m.body = "sphere 11 (link7)";
    m.box_id = -1;  // self collision
    m.depth_m = 0.0125;
    return m;
  }
  static void ExpectSame(const sim_contact_t& a, const sim_contact_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.body, b.body);
    EXPECT_EQ(a.box_id, b.box_id);
    EXPECT_EQ(a.depth_m, b.depth_m);
  }
};

template <>
struct MessageSample<sim_status_t> {
  static sim_status_t Make() {
    sim_status_t m;
    m.utime = 1'700'000'001'423'456;
    m.sim_time_s = 12.5;
    m.real_time_factor = 0.97;
    m.target_rate = 1.0;
    m.plant_steps = 6250;
    m.late_steps = 3;
    m.step_lateness_p99_us = 181.5;
    m.commands_accepted = 625;
    m.commands_rejected = 2;
    m.command_timeouts = 1;
    m.contact_events = 4;
    m.contact_steps = 77;
    m.max_depth_m = 0.031;
    m.in_contact = true;
    m.scans = 125;
    m.events_applied = 2;
    m.boxes_present = -5;  // not meaningful, but it must survive
    return m;
  }
  static void ExpectSame(const sim_status_t& a, const sim_status_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.sim_time_s, b.sim_time_s);
    EXPECT_EQ(a.real_time_factor, b.real_time_factor);
    EXPECT_EQ(a.target_rate, b.target_rate);
    EXPECT_EQ(a.plant_steps, b.plant_steps);
    EXPECT_EQ(a.late_steps, b.late_steps);
    EXPECT_EQ(a.step_lateness_p99_us, b.step_lateness_p99_us);
    EXPECT_EQ(a.commands_accepted, b.commands_accepted);
    EXPECT_EQ(a.commands_rejected, b.commands_rejected);
    EXPECT_EQ(a.command_timeouts, b.command_timeouts);
    EXPECT_EQ(a.contact_events, b.contact_events);
    EXPECT_EQ(a.contact_steps, b.contact_steps);
    EXPECT_EQ(a.max_depth_m, b.max_depth_m);
    EXPECT_EQ(a.in_contact, b.in_contact);
    EXPECT_EQ(a.scans, b.scans);
    EXPECT_EQ(a.events_applied, b.events_applied);
    EXPECT_EQ(a.boxes_present, b.boxes_present);
  }
};

template <>
struct MessageSample<sim_event_t> {
  static sim_event_t Make() {
    sim_event_t m;
    m.utime = 1'700'000'001'523'456;
    m.name = "door closes";
    m.action = sim_event_t::APPEAR;
    m.box_id = 1001;
    m.has_box = true;
    const double center[3] = {2.5, -1.25, 0.75}, size[3] = {0.4, 1.2, 1.5}, point[2] = {-3.0, 4.5};
    for (int i = 0; i < 3; ++i) m.center_m[i] = center[i];
    for (int i = 0; i < 3; ++i) m.size_m[i] = size[i];
    m.yaw_rad = -0.3;
    m.trigger = sim_event_t::NEAR_POINT;
    m.at_s = 7.5;
    for (int i = 0; i < 2; ++i) m.point_m[i] = point[i];
    m.distance_m = 1.5;
    return m;
  }
  static void ExpectSame(const sim_event_t& a, const sim_event_t& b) {
    EXPECT_EQ(a.utime, b.utime);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.action, b.action);
    EXPECT_EQ(a.box_id, b.box_id);
    EXPECT_EQ(a.has_box, b.has_box);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.center_m[i], b.center_m[i]) << i;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.size_m[i], b.size_m[i]) << i;
    EXPECT_EQ(a.yaw_rad, b.yaw_rad);
    EXPECT_EQ(a.trigger, b.trigger);
    EXPECT_EQ(a.at_s, b.at_s);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(a.point_m[i], b.point_m[i]) << i;
    EXPECT_EQ(a.distance_m, b.distance_m);
  }
};

}  // namespace topay::test
