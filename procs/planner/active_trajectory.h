#pragma once
// The trajectory the planner last published (the one the robot is on), with what the planner
// asks of it: the state at a time (where a replan starts), the robot's drift from it, and
// the region its rest sweeps (what the map check looks at).

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>

#include <Eigen/Geometry>

#include "core/control/tracked_robot_prediction.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/planner/standing_robot.h"

namespace topay::planner {

struct ActiveTrajectory {
  std::int64_t trajectory_id = 0;
  std::int64_t goal_id = 0;
  std::int64_t start_utime = 0;  ///< t = 0, us since the Unix epoch
  std::shared_ptr<const ArcYawTrajectory> trajectory;
  bool stopping = false;         ///< a stopping trajectory (safe stop), not a plan to the goal
  /// A plan from rest (or a stop braking from one): the robot where it started, whose own
  /// voxels the map checks leave out as its validation did (StandingRobot).
  std::optional<StandingRobot> standing;

  /// Time along the trajectory (s) at `utime`, not clamped.
  double TimeAt(std::int64_t utime) const { return 1e-6 * static_cast<double>(utime - start_utime); }
  std::int64_t end_utime() const;
  bool EndedBy(std::int64_t utime) const { return utime >= end_utime(); }
  /// Every quantity at `utime` (clamped to the trajectory: before its start the start, after
  /// its end the end, at rest).
  TrajectorySample SampleAt(std::int64_t utime) const;
};

/// The trajectory the robot is on at `utime` (null: none yet): the newest published one whose
/// start has come, `newest` first (null: none), then `replaced` from its back (published
/// earlier, oldest first). The tracker follows them the same way (a newer trajectory takes
/// over at its start; one not started yet leaves the robot on the one before). A replan starts
/// on it at its t0, and a safe stop brakes from it: the newest may still be waiting for its
/// start.
const ActiveTrajectory* TrajectoryOnAt(const ActiveTrajectory* newest, const std::deque<ActiveTrajectory>& replaced,
                                       std::int64_t utime);

/// How far the robot is from where the trajectory says it should be at the state's time.
struct Drift {
  double position_m = 0.0;
  double yaw_rad = 0.0;    ///< wrapped, absolute
  double joint_rad = 0.0;  ///< the largest joint error
};
Drift MeasureDrift(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot);

/// The robot carried along `active` with its error at robot.utime: the trajectory's state at
/// a time with that error added (the base offset rotated by the trajectory's turn since the
/// state's time, the yaw and joint offsets as they are; the rates and accelerations the
/// trajectory's). The tracker keeps following the trajectory until a new one starts, so a
/// robot that drifted off it moves as it does and keeps its error. Not the measured state
/// extrapolated at constant rates: that runs straight off a turning trajectory (1 s at
/// 0.5 rad/s puts it ~0.12 m off the arc), and drift replans that started there drove the
/// demo's robot into a box. Joint offsets are not clamped to limits. Holds a reference to
/// `active`, which must outlive it.
class DriftedRobot {
 public:
  DriftedRobot(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot);
  /// The drifted robot at t_s along the trajectory (clamped to it) into `sample` (made by the
  /// trajectory's MakePoint).
  void Evaluate(double t_s, TrajectorySample* sample) const;
  /// Time along the trajectory (s) of the robot's state (not clamped).
  double state_time_s() const { return state_time_s_; }
  const ActiveTrajectory& active() const { return active_; }

 private:
  const ActiveTrajectory& active_;
  double state_time_s_ = 0.0;
  double yaw_ref_rad_ = 0.0;       // the trajectory's yaw at the state's time
  Eigen::Vector2d p_offset_W_m_;   // robot minus trajectory, base position, at the state's time
  double yaw_offset_rad_ = 0.0;    // wrapped
  Eigen::VectorXd q_offset_rad_;   // empty when the joint counts differ
};

/// Where a robot that drifted off `active` will be at t0_utime (DriftedRobot at t0): where a
/// drift replan starts.
TrajectorySample PredictDriftedStart(const ActiveTrajectory& active, const msgs::RobotStateEstimate& robot,
                                     std::int64_t t0_utime);

/// Where the tracker will have brought a robot that drifted off `active` by t0_utime: the
/// tracker's closed loop (TrackedRobotPredictor) from the robot's measured state and rates (no
/// joint rates, or the wrong number: taken as 0) along `active`: where a drift replan starts
/// (triggers.drift_start tracked). t0_utime before robot.utime: the robot as it is. The start's
/// accelerations are clamped into `plan_limits` (the plans' are a share of the robot's,
/// limits.acceleration_share, and the tracker may use all of the robot's). *summary
/// (optional): the prediction's. Throws std::invalid_argument for a robot whose joint count is
/// not the predictor's or with non-finite values.
TrajectorySample PredictTrackedStart(TrackedRobotPredictor* predictor, const ActiveTrajectory& active,
                                     const msgs::RobotStateEstimate& robot, std::int64_t t0_utime,
                                     const TrackerLimits& plan_limits,
                                     TrackedRobotPredictionSummary* summary = nullptr);

/// A world box that holds the robot over [t_from_s, t_to_s] of the trajectory: the base
/// positions (every 0.05 s) grown by `reach_m` (the robot's extent around its base axis)
/// plus 0.1 m in x and y, from the floor to `height_m`.
Eigen::AlignedBox3d SweptRegion(const ArcYawTrajectory& trajectory, double t_from_s, double t_to_s,
                                double reach_m, double height_m);

}  // namespace topay::planner
