#pragma once
// A mission: a named list of steps for topay-mission (docs/mission.md): go to an end-effector
// pose, open / close the gripper, wait, go home (the start pose). Loaded from YAML with errors
// that name the file, the step and the field.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/robot/whole_body_state.h"

namespace topay::mission {

enum class StepType { kGoto, kGripper, kWait, kHome };
const char* ToString(StepType type);

/// When a goto (or home) counts as arrived: the measured end effector within both.
struct ArrivalTolerance {
  double position_m = 0.03;      ///< |p_WE - p_WE,target|, m
  double orientation_rad = 0.1;  ///< angle of R_WE,target^T R_WE, rad
};

/// One step. Fields not of its type are unused.
struct MissionStep {
  StepType type = StepType::kWait;
  std::string label;  ///< the optional `name` of the step, for logs and MISSION_STATUS
  // goto
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();  ///< target end-effector pose in W
  std::optional<WholeBodyState> hint;                      ///< whole-body hint for the planner
  // goto and home
  std::optional<ArrivalTolerance> tolerance;  ///< nullopt: the process's default
  std::optional<double> timeout_s;            ///< nullopt: the process's step timeout
  // gripper
  double gripper_position = 0.0;    ///< 0 open .. 1 closed
  std::optional<double> settle_s;   ///< wait after the command; nullopt: the process's default
  // wait
  double duration_s = 0.0;

  /// Readable description, e.g. "goto pickup", "gripper close", "wait 2.0 s", "home".
  std::string Describe() const;
};

struct Mission {
  std::string name;
  std::string source;  ///< the file it came from
  std::vector<MissionStep> steps;
};

/// Loads a mission YAML. Throws ConfigError ("<file>: steps[i].<field>: <what>") for an
/// unreadable file, a missing name or steps, an unknown step type or field, a non-finite
/// number, a non-unit quaternion (|1 - |q|| > 1e-3), both or neither of rpy_rad and quat_wxyz,
/// a gripper value outside 0..1, a negative duration or tolerance.
Mission LoadMission(const std::string& path);
/// Same from YAML text; `source` names it in errors.
Mission ParseMission(const std::string& yaml_text, const std::string& source);

/// Throws ConfigError naming the step if a hint's joint count differs from the robot's.
void CheckMissionForRobot(const Mission& mission, int num_joints);

}  // namespace topay::mission
