#pragma once
// topay-director's logic, free of the bus: the mission's status, the active trajectory and the
// robot's state in, SIM_EVENTs out through a callback (docs/director.md).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "procs/director/background_placement.h"
#include "procs/director/base_path.h"
#include "procs/director/director_options.h"
#include "procs/msgs/robot_state_intake.h"
#include "topay/mission_status_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_event_t.hpp"

namespace topay::director {

struct DirectorOutputs {
  std::function<void(const sim_event_t&)> event;  ///< publishes SIM_EVENT
  /// A line for the log (placements, give-ups); may be empty.
  std::function<void(bool warning, const std::string&)> log;
};

class DirectorNode {
 public:
  /// `scene`: the room the simulator runs (the same scene JSON). The kinematics must outlive
  /// the node.
  DirectorNode(DirectorOptions options, Scene scene, const Kinematics& kinematics, DirectorOutputs outputs);

  void OnMissionStatus(const mission_status_t& msg);
  /// A trajectory that cannot be rebuilt is logged and ignored.
  void OnTrajectory(const poly_trajectory_t& msg);
  void OnRobotState(const robot_state_t& msg);
  /// The first pending event: gives up once its step has run and ended; else, while its step
  /// runs and the robot drives at min_speed_mps, starts an attempt to place its box on the
  /// active trajectory ahead of the robot (PlaceRouteBox on a worker thread: the flood fills
  /// take seconds on a loaded machine and the loop must go on). A later tick takes the
  /// attempt's result, re-checks the box against where the robot is then (RecheckRouteBox)
  /// and publishes it (APPEAR, NOW); an attempt whose draws were all rejected is tried again
  /// retry_period_s later. Returns at once.
  void Tick(std::int64_t now_utime);
  /// Blocks until a running placement attempt is done (its result is taken by the next
  /// Tick); for tests.
  void WaitForPlacement() const { placement_.Wait(); }

  /// A placement attempt runs (or its result waits for the next Tick).
  bool placing() const { return placement_.busy(); }
  int boxes_placed() const { return boxes_placed_; }
  int events_given_up() const { return given_up_; }
  bool all_done() const;
  /// For the heartbeat: "box 1 placed at (x, y) 3.1 m ahead", "waiting for step dropoff", ...
  const std::string& StatusLine() const { return status_; }

 private:
  struct Pending {
    BoxOnRouteEvent event;
    int box_id = 0;
    bool step_seen = false;
    bool done = false;
    std::int64_t next_attempt_utime = 0;  // after an attempt for this event whose draws were all rejected
  };
  bool StepRunning(const Pending& p) const;
  bool RobotDriving(const Pending& p) const;
  std::optional<RouteQuery> Route(std::int64_t now_utime) const;
  void StartPlacement(std::size_t event_index, std::int64_t now_utime);
  void TakePlacement(std::int64_t now_utime);
  void Publish(const Pending& p, const RouteBox& placed, std::int64_t now_utime);
  void Log(bool warning, const std::string& line);

  DirectorOptions options_;
  Scene scene_;
  const Kinematics& kinematics_;
  DirectorOutputs outputs_;
  Rng rng_;
  std::vector<Pending> pending_;
  std::optional<mission_status_t> mission_;
  std::optional<BasePath> path_;
  msgs::RobotStateIntake state_intake_{0};  // decode, continuity gate
  std::optional<Eigen::Vector2d> p_WR_m_;
  double speed_mps_ = 0.0;
  int boxes_placed_ = 0;
  int given_up_ = 0;
  std::string status_ = "waiting for the mission";
  BackgroundPlacement placement_;  // last: its destructor waits for a running attempt
};

}  // namespace topay::director
