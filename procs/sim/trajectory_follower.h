#pragma once
// The ideal trajectory follower of topay-sim --follow (docs/simulator.md): the plant's state at
// every step is the newest valid TRAJECTORY evaluated at the sim's time, velocities included.
//
// A trajectory is checked when it arrives (Accept) and followed from its start_utime on: until
// then the robot keeps doing what it did (following the previous trajectory, or holding its
// state at rest), after its end it holds the end state at rest. Times are utimes of the sim's
// clock (start_utime of sim time 0 + the sim time), the base the planner stamps start_utime in.

#include <cstdint>
#include <optional>
#include <string>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "procs/msgs/trajectory_from_message.h"
#include "sim/plant/plant_state.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::simproc {

struct TrajectoryFollowerOptions {
  /// Largest distance of a trajectory's start position from where the robot is at its
  /// start_utime (the planner starts trajectories where the robot is), m.
  double max_start_offset_m = 0.3;
  /// The same for yaw (wrapped difference) and every joint, rad.
  double max_start_offset_rad = 0.3;
  /// The message -> trajectory rebuild (Simpson panels, coefficient and yaw0 tolerances).
  msgs::TrajectoryRebuildOptions rebuild;
};

struct FollowerCounts {
  std::int64_t accepted = 0;
  std::int64_t rejected = 0;
  std::int64_t started = 0;  ///< accepted trajectories whose start_utime was reached
};

class TrajectoryFollower {
 public:
  TrajectoryFollower(int num_joints, const TrajectoryFollowerOptions& options);

  /// "" if `msg` is accepted (it waits for its start_utime, replacing any other waiting one),
  /// else why not (counted): a wrong joint count, a start_utime or a duration beyond 1e6 s from
  /// now, a malformed message (msgs::FromMessage), not a MINCO trajectory (msgs::ToArcYaw),
  /// already ended at now_utime, or starting further than
  /// the options allow from where the robot is at its start_utime (`current`, the plant's state
  /// at now_utime, carried along the trajectory followed now).
  std::string Accept(const poly_trajectory_t& msg, std::int64_t now_utime, const sim::PlantState& current);

  /// The plant's state at `utime` (non-decreasing from call to call): the trajectory followed
  /// evaluated there, with its velocities; `current` at rest before any trajectory has started;
  /// the end state at rest after the end. The gripper is current's.
  sim::PlantState StateAt(std::int64_t utime, const sim::PlantState& current);

  const FollowerCounts& counts() const { return counts_; }
  /// The id of the trajectory followed (nullopt: none has started).
  std::optional<std::int64_t> active_id() const;

 private:
  struct Followed {
    std::int64_t id = 0;
    std::int64_t start_utime = 0;
    ArcYawTrajectory trajectory;
  };
  std::string Check(const poly_trajectory_t& msg, std::int64_t now_utime, const sim::PlantState& current,
                    std::optional<Followed>* followed);
  /// The state at `utime` along the active trajectory (no switching).
  sim::PlantState Along(std::int64_t utime, const sim::PlantState& current);

  int num_joints_;
  TrajectoryFollowerOptions options_;
  std::optional<Followed> active_, waiting_;
  TrajectorySample sample_;  // scratch of Along
  FollowerCounts counts_;
};

/// `state` with every velocity zero.
sim::PlantState AtRest(sim::PlantState state);

}  // namespace topay::simproc
