#pragma once
// LCM channel names of the TopAY process graph, one per stream. lcmtypes/README.md lists the
// message type, publisher and subscribers of each.

#include <array>
#include <string_view>

namespace topay::channels {

inline constexpr std::string_view BASE_POSE = "BASE_POSE";              // base_pose_t
inline constexpr std::string_view BASE_VELOCITY = "BASE_VELOCITY";      // base_velocity_t
inline constexpr std::string_view JOINT_STATE = "JOINT_STATE";          // joint_state_t
inline constexpr std::string_view ROBOT_STATE = "ROBOT_STATE";          // robot_state_t
inline constexpr std::string_view POINT_CLOUD = "POINT_CLOUD";          // point_cloud_t
inline constexpr std::string_view MAP_UPDATE = "MAP_UPDATE";            // map_update_t
inline constexpr std::string_view GOAL = "GOAL";                        // goal_t
inline constexpr std::string_view TRAJECTORY = "TRAJECTORY";            // poly_trajectory_t
inline constexpr std::string_view CONTROL_COMMAND = "CONTROL_COMMAND";  // control_command_t
inline constexpr std::string_view PLANNER_STATUS = "PLANNER_STATUS";    // planner_status_t
inline constexpr std::string_view PLANNER_PATHS = "PLANNER_PATHS";      // planner_paths_t
inline constexpr std::string_view TRACKER_STATUS = "TRACKER_STATUS";    // tracker_status_t
inline constexpr std::string_view HEARTBEAT = "HEARTBEAT";              // heartbeat_t
inline constexpr std::string_view GRAPH_STATUS = "GRAPH_STATUS";        // graph_status_t
inline constexpr std::string_view SIM_CONTACT = "SIM_CONTACT";          // sim_contact_t
inline constexpr std::string_view SIM_STATUS = "SIM_STATUS";            // sim_status_t
inline constexpr std::string_view SIM_EVENT = "SIM_EVENT";              // sim_event_t
inline constexpr std::string_view GRIPPER_COMMAND = "GRIPPER_COMMAND";  // gripper_command_t
inline constexpr std::string_view MISSION_STATUS = "MISSION_STATUS";    // mission_status_t
inline constexpr std::string_view DRIVE_STATUS = "DRIVE_STATUS";        // drive_status_t
inline constexpr std::string_view DRIVE_COMMAND = "DRIVE_COMMAND";      // drive_command_t
// The CAN closed loop (docs/motorsim.md, docs/simulator.md "CAN mode").
inline constexpr std::string_view ACTUATOR_COMMAND = "ACTUATOR_COMMAND";  // control_command_t (motorsim -> sim)
inline constexpr std::string_view SIM_PLANT_STATE = "SIM_PLANT_STATE";    // robot_state_t (sim -> motorsim)
inline constexpr std::string_view GRIPPER_STATE = "GRIPPER_STATE";        // joint_state_t ("gripper")
inline constexpr std::string_view MOTORSIM_FAULT = "MOTORSIM_FAULT";      // motorsim_fault_t

// Every channel above, e.g. for a logger's or a bridge's channel list.
inline constexpr std::array<std::string_view, 25> kAll = {
    BASE_POSE,   BASE_VELOCITY, JOINT_STATE,     ROBOT_STATE,     POINT_CLOUD, MAP_UPDATE,
    GOAL,        TRAJECTORY,    CONTROL_COMMAND, PLANNER_STATUS,  HEARTBEAT,   GRAPH_STATUS,
    SIM_CONTACT, SIM_STATUS,    SIM_EVENT,       TRACKER_STATUS,  GRIPPER_COMMAND, MISSION_STATUS,
    DRIVE_STATUS, DRIVE_COMMAND, ACTUATOR_COMMAND, SIM_PLANT_STATE, GRIPPER_STATE, MOTORSIM_FAULT,
    PLANNER_PATHS};

}  // namespace topay::channels
