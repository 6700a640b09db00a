#include "procs/sim/trajectory_follower.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/common/angles.h"

namespace topay::simproc {
namespace {

// Largest |start_utime - now| and duration accepted, s (11.6 days; keeps utimes far from overflow).
constexpr double kMaxTimeS = 1e6;

double Seconds(std::int64_t from_utime, std::int64_t to_utime) { return static_cast<double>(to_utime - from_utime) * 1e-6; }

sim::PlantState FromSample(const TrajectorySample& sample, double gripper) {
  sim::PlantState s;
  s.state = sample.state;
  s.v_mps = sample.v_mps;
  s.omega_radps = sample.omega_radps;
  s.qdot_radps = sample.qd_radps;
  s.gripper = gripper;
  return s;
}

/// "" if `start` is within the tolerances of `robot`, else how far it is.
std::string StartOffset(const WholeBodyState& start, const WholeBodyState& robot, const TrajectoryFollowerOptions& o) {
  std::ostringstream why;
  why.precision(3);
  const double distance_m = std::hypot(start.x_m - robot.x_m, start.y_m - robot.y_m);
  const double yaw_rad = std::abs(WrapAngle(start.yaw_rad - robot.yaw_rad));
  const double joint_rad = start.q_rad.size() == 0 ? 0.0 : (start.q_rad - robot.q_rad).cwiseAbs().maxCoeff();
  if (!(distance_m <= o.max_start_offset_m)) {
    why << "starts " << distance_m << " m from the robot (tolerance " << o.max_start_offset_m << " m)";
  } else if (!(yaw_rad <= o.max_start_offset_rad)) {
    why << "starts " << yaw_rad << " rad of yaw from the robot (tolerance " << o.max_start_offset_rad << " rad)";
  } else if (!(joint_rad <= o.max_start_offset_rad)) {
    why << "starts a joint " << joint_rad << " rad from the robot's (tolerance " << o.max_start_offset_rad << " rad)";
  }
  return why.str();
}

}  // namespace

sim::PlantState AtRest(sim::PlantState state) {
  state.v_mps = 0.0;
  state.omega_radps = 0.0;
  state.qdot_radps.setZero();
  return state;
}

TrajectoryFollower::TrajectoryFollower(int num_joints, const TrajectoryFollowerOptions& options)
    : num_joints_(num_joints), options_(options), sample_(MakeTrajectorySample(num_joints)) {
  sample_.jerk.setZero(num_joints + 2);
}

std::optional<std::int64_t> TrajectoryFollower::active_id() const {
  if (!active_) return std::nullopt;
  return active_->id;
}

std::string TrajectoryFollower::Accept(const poly_trajectory_t& msg, std::int64_t now_utime,
                                       const sim::PlantState& current) {
  std::optional<Followed> followed;
  const std::string why = Check(msg, now_utime, current, &followed);
  if (!why.empty()) {
    ++counts_.rejected;
    return why;
  }
  ++counts_.accepted;
  waiting_ = std::move(followed);
  return "";
}

std::string TrajectoryFollower::Check(const poly_trajectory_t& msg, std::int64_t now_utime,
                                      const sim::PlantState& current, std::optional<Followed>* followed) {
  if (msg.num_joints != num_joints_) {
    return "num_joints " + std::to_string(msg.num_joints) + ", the robot has " + std::to_string(num_joints_);
  }
  const double start_in_s = (static_cast<double>(msg.start_utime) - static_cast<double>(now_utime)) * 1e-6;
  if (!(std::abs(start_in_s) <= kMaxTimeS)) {
    return "start_utime " + std::to_string(msg.start_utime) + " is " + std::to_string(start_in_s) +
           " s from the sim's time (at most 1e6 s)";
  }
  std::string error;
  const std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(msg, &error);
  if (!poly) return error;
  std::optional<ArcYawTrajectory> trajectory = msgs::ToArcYaw(*poly, options_.rebuild, &error);
  if (!trajectory) return error;
  if (!(trajectory->duration_s() <= kMaxTimeS)) {
    return "lasts " + std::to_string(trajectory->duration_s()) + " s (at most 1e6 s)";
  }
  const std::int64_t end_utime = msg.start_utime + std::llround(trajectory->duration_s() * 1e6);
  if (end_utime < now_utime) {
    return "ended " + std::to_string(Seconds(end_utime, now_utime)) + " s before it arrived";
  }
  trajectory->Evaluate(0.0, &sample_);
  const sim::PlantState robot_at_start = Along(msg.start_utime, current);
  const std::string offset = StartOffset(sample_.state, robot_at_start.state, options_);
  if (!offset.empty()) return offset;
  followed->emplace(Followed{msg.trajectory_id, msg.start_utime, std::move(*trajectory)});
  return "";
}

sim::PlantState TrajectoryFollower::StateAt(std::int64_t utime, const sim::PlantState& current) {
  if (waiting_ && utime >= waiting_->start_utime) {
    active_ = std::move(waiting_);
    waiting_.reset();
    ++counts_.started;
  }
  return Along(utime, current);
}

sim::PlantState TrajectoryFollower::Along(std::int64_t utime, const sim::PlantState& current) {
  if (!active_ || utime < active_->start_utime) return AtRest(current);
  const double t_s = Seconds(active_->start_utime, utime);
  const double end_s = active_->trajectory.duration_s();
  active_->trajectory.Evaluate(std::min(t_s, end_s), &sample_);
  const sim::PlantState state = FromSample(sample_, current.gripper);
  return t_s >= end_s ? AtRest(state) : state;
}

}  // namespace topay::simproc
