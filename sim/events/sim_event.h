#pragma once
// A world event of the simulator: a box appears or disappears, now, at a sim time, or when the
// robot's base comes within a distance of a point. Scripted in an event file (event_file.h) or
// sent at run time on SIM_EVENT (sim_event_t).

#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"

namespace topay::sim {

struct SimEvent {
  enum class Action { kAppear, kDisappear };
  enum class Trigger { kNow, kAtTime, kNearPoint };

  std::string name;                      ///< for logs (the file's `name`, else "event <i>")
  Action action = Action::kAppear;
  int box_id = -1;                       ///< stable box id (SimWorld)
  std::optional<OrientedBox> box;        ///< appear: the box's geometry (absent: re-appear box_id)
  Trigger trigger = Trigger::kNow;
  double at_s = 0.0;                     ///< kAtTime: sim time since the start, s
  double jitter_s = 0.0;                 ///< kAtTime: fires at at_s + U[0, jitter_s) (seeded)
  Eigen::Vector2d point_W_m = Eigen::Vector2d::Zero();  ///< kNearPoint: (x, y) in W, m
  double distance_m = 0.0;               ///< kNearPoint: fires when |p_WB - point| <= distance_m
};

/// "appear box 1000 at t=5.000 s" etc., for logs.
std::string Describe(const SimEvent& event);

}  // namespace topay::sim
