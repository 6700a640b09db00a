#pragma once
// The planned trajectory as the viewer draws and plots it (docs/viewer.md: Trajectory,
// PlotSample): a TRAJECTORY message rebuilt into the core trajectory (msgs::ToArcYaw), sampled
// once per trajectory id for the base and end-effector paths and the planned v, omega, a, beta,
// q; and the active trajectory evaluated at a robot state's time for the plots.

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"
#include "procs/viz/robot_view.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::viz {

struct TrajectoryViewOptions {
  double sample_dt_s = 0.05;  ///< Sampling step of the paths and series.
  int max_samples = 2000;     ///< The step grows for longer trajectories.
};

class TrajectoryView {
 public:
  TrajectoryView(const RobotView& robot, const TrajectoryViewOptions& options);

  /// Rebuilds a new trajectory and returns its Trajectory payload; nullopt if its id is the
  /// active one (sent once per id) or, with *error naming the id and the reason, if it cannot
  /// be rebuilt (the active trajectory is then unchanged).
  std::optional<nlohmann::json> Accept(const poly_trajectory_t& msg, std::string* error);

  /// The active trajectory's sample at utime (clamped to its span); nullptr if none.
  const TrajectorySample* PlannedAt(std::int64_t utime);
  std::int64_t active_id() const { return active_id_; }

 private:
  nlohmann::json Payload(const poly_trajectory_t& msg);

  const RobotView* robot_;
  TrajectoryViewOptions options_;
  std::optional<ArcYawTrajectory> active_;
  std::int64_t active_id_ = 0;
  std::int64_t start_utime_ = 0;
  TrajectorySample point_;
};

}  // namespace topay::viz
