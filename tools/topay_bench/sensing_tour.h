#pragma once
// The robot states from which topay-bench's sensed-map runs scan a task's scene (--sensed-map):
// the LiDAR sees the room from these poses before the planner plans on the mapped result.

#include <optional>
#include <string_view>
#include <vector>

#include "core/geometry/scene.h"
#include "core/robot/whole_body_state.h"
#include "sim/scenes/planning_task.h"

namespace topay::bench {

enum class SensingTourKind {
  /// "line": along the straight start-goal base line, as a robot driving towards the goal
  /// would see the room (what lies off the line stays partly unseen).
  kLine,
  /// "tour": the line plus a grid of poses over the whole room (a scripted tour before the
  /// task: most of the room seen).
  kTour,
};

std::string_view SensingTourKindName(SensingTourKind kind);
std::optional<SensingTourKind> ParseSensingTourKind(std::string_view name);

struct SensingTourOptions {
  SensingTourKind kind = SensingTourKind::kLine;
  /// Spacing of the poses along the start-goal line, m (the start and the goal poses always).
  double line_step_m = 1.0;
  /// kTour: grid poses per axis over the room, inset by grid_inset_m from its bounds.
  int grid_per_axis = 4;
  double grid_inset_m = 2.0;
  /// A pose is used only if the base's footprint circle of this radius (m) is clear of every
  /// box that reaches below the top of the robot (pose_clear_height_m): the robot can stand
  /// there. The start and the goal poses are always used.
  double footprint_radius_m = 0.35;
  double pose_clear_height_m = 1.6;
};

/// The tour's states, in order: the start, the line's poses (heading along the line), the
/// goal's base pose (with the start's arm), then (kTour) the grid poses row by row. Every state
/// but the start has the start's arm configuration.
std::vector<WholeBodyState> SensingTourStates(const Scene& scene, const PlanningTask& task,
                                              const SensingTourOptions& options);

}  // namespace topay::bench
