#pragma once
// The simulator's LCM messages <-> its own types: CONTROL_COMMAND -> actuator command,
// SIM_EVENT <-> event, and the outputs (ROBOT_STATE, BASE_POSE, POINT_CLOUD, SIM_CONTACT).
// utime = start_utime + the sim time in microseconds (the simulator's time base,
// docs/simulator.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "procs/sim/sim_core.h"
#include "topay/control_command_t.hpp"
#include "topay/joint_state_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/sim_event_t.hpp"

namespace topay::simproc {

/// utime of sim time t_s: start_utime + round(t_s * 1e6).
std::int64_t SimUtime(std::int64_t start_utime, double t_s);

/// The command's fields (no check: the plant checks and may reject it). A num_joints that
/// disagrees with the array (cannot come from a decoded message) gives an empty joint vector.
sim::ActuatorCommand ToActuatorCommand(const control_command_t& msg);

/// ROBOT_STATE: the localisation's pose, the wheels' odometry (v, omega), the measured joints
/// and gripper; every nested utime is the sample's (BASE_POSE is its pose).
robot_state_t ToRobotState(const StateSample& sample, std::int64_t start_utime,
                           const std::vector<std::string>& joint_names);
/// SIM_PLANT_STATE (CAN mode, for topay-motorsim): the plant's true pose, the wheels' v, omega (what
/// the wheel encoders see: wheel slip excluded), the true joints and rates, the gripper; at `utime`.
robot_state_t ToPlantStateMessage(const sim::PlantState& truth, const sim::MeasuredActuators& measured,
                                  std::int64_t utime, const std::vector<std::string>& joint_names);
/// GRIPPER_STATE (CAN mode): one joint named "gripper", position 0 open .. 1 closed, its rate
/// and effort NaN (not measured).
joint_state_t ToGripperState(double gripper, std::int64_t utime);
point_cloud_t ToPointCloud(const ScanResult& scan, std::int64_t start_utime, const std::string& frame);
sim_contact_t ToContactMessage(const ContactResult& contact, int box_id, std::int64_t start_utime);

/// A run-time event from SIM_EVENT; nullopt with *error (naming the field) for an unknown
/// action or trigger, a negative id, non-finite numbers, a non-positive size or distance.
std::optional<sim::SimEvent> FromEventMessage(const sim_event_t& msg, std::string* error);
sim_event_t ToEventMessage(const sim::SimEvent& event, std::int64_t utime);

}  // namespace topay::simproc
