#include "procs/estimator/estimator_node.h"

#include <spdlog/spdlog.h>

#include <cmath>
#include <limits>

#include "core/common/stamp_difference.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::estimator {
namespace {

constexpr double kUsPerS = 1e6;

std::int64_t Micros(double seconds) { return static_cast<std::int64_t>(std::llround(seconds * kUsPerS)); }

// "12 ms" or "none".
std::string Age(const std::optional<std::int64_t>& utime, std::int64_t now_utime) {
  if (!utime) return "none";
  return fmt::format("{:.0f} ms", static_cast<double>(StampDifferenceUs(now_utime, *utime)) * 1e-3);
}

}  // namespace

const char* ValidityName(Validity validity) {
  switch (validity) {
    case Validity::kValid: return "valid";
    case Validity::kNoPose: return "no pose yet";
    case Validity::kPoseStale: return "pose stale";
    case Validity::kNoOdometry: return "no odometry yet";
    case Validity::kOdometryStale: return "odometry stale";
    case Validity::kNoJoints: return "no joint state yet";
    case Validity::kJointsStale: return "joint state stale";
  }
  return "?";
}

std::int64_t EstimatorCounts::total_faults() const {
  std::int64_t total = 0;
  for (const std::int64_t n : faults) total += n;
  return total;
}

EstimatorNode::EstimatorNode(const EstimatorProcessOptions& options)
    : options_((CheckProcessOptions(options), options)), filter_(options.filter) {}

bool EstimatorNode::Future(std::int64_t utime, std::int64_t now_utime) const {
  return StampDifferenceUs(utime, now_utime) > Micros(options_.max_future_s);
}

void EstimatorNode::Fault(InputFault fault) {
  std::int64_t& n = counts_.faults[static_cast<int>(fault)];
  if (++n == 1) spdlog::warn("ignored: {} (logged once per kind, counted)", InputFaultName(fault));
}

void EstimatorNode::OnPose(const base_pose_t& msg, std::int64_t now_utime) {
  ++counts_.poses;
  if (const std::optional<InputFault> fault = CheckPose(msg)) return Fault(*fault);
  if (Future(msg.utime, now_utime)) return Fault(InputFault::kPoseFuture);
  switch (filter_.AddPose(msg.utime, Eigen::Vector3d(msg.x_m, msg.y_m, msg.yaw_rad))) {
    case EstimatorInput::kRejectedNotFinite: return Fault(InputFault::kPoseNotFinite);
    case EstimatorInput::kRejectedOutOfOrder: return Fault(InputFault::kPoseOutOfOrder);
    case EstimatorInput::kRejectedTooOld: return Fault(InputFault::kPoseTooOld);
    case EstimatorInput::kApplied:
    case EstimatorInput::kAppliedDelayed: break;
  }
  pose_utime_ = msg.utime;
  const PoseOutcome outcome = filter_.last_pose_outcome();
  if (outcome == PoseOutcome::kInitialised) {
    spdlog::info("initialised from BASE_POSE ({:.3f}, {:.3f}, {:.3f} rad)", msg.x_m, msg.y_m, msg.yaw_rad);
  } else if (outcome == PoseOutcome::kReinitialised) {
    spdlog::warn("re-initialised from BASE_POSE ({:.3f}, {:.3f}, {:.3f} rad) after {} poses in a row outside the "
                 "gate (#{})",
                 msg.x_m, msg.y_m, msg.yaw_rad, options_.filter.reinit_after_rejections,
                 filter_.summary().reinitialisations);
  }
}

void EstimatorNode::OnVelocity(const base_velocity_t& msg, std::int64_t now_utime) {
  ++counts_.velocities;
  if (const std::optional<InputFault> fault = CheckVelocity(msg, options_.max_speed_mps, options_.max_yaw_rate_radps)) {
    return Fault(*fault);
  }
  if (Future(msg.utime, now_utime)) return Fault(InputFault::kVelocityFuture);
  switch (filter_.AddOdometry(msg.utime, msg.v_mps, msg.omega_radps)) {
    case EstimatorInput::kRejectedNotFinite: return Fault(InputFault::kVelocityNotFinite);
    case EstimatorInput::kRejectedOutOfOrder: return Fault(InputFault::kVelocityOutOfOrder);
    case EstimatorInput::kRejectedTooOld: return Fault(InputFault::kVelocityTooOld);
    case EstimatorInput::kApplied:
    case EstimatorInput::kAppliedDelayed: break;
  }
  velocity_ = msg;  // stamps increase within the stream (else rejected above)
}

void EstimatorNode::OnJoints(const joint_state_t& msg, std::int64_t now_utime) {
  ++counts_.joints;
  if (const std::optional<InputFault> fault = CheckJoints(msg, options_.num_joints)) return Fault(*fault);
  if (Future(msg.utime, now_utime)) return Fault(InputFault::kJointsFuture);
  if (joints_ && msg.utime <= joints_->utime) return Fault(InputFault::kJointsOutOfOrder);
  WholeBodyState arm;  // the base stays at the origin: the gate judges q alone
  arm.q_rad = Eigen::Map<const Eigen::VectorXd>(msg.position_rad.data(), msg.num_joints);
  if (!Taken(joints_gate_.Check(msg.utime, arm))) return Fault(InputFault::kJointsJump);
  joints_ = msg;
  joints_->effort_Nm.resize(msg.num_joints, std::numeric_limits<double>::quiet_NaN());
}

void EstimatorNode::OnGripper(const joint_state_t& msg, std::int64_t now_utime) {
  ++counts_.grippers;
  double position = 0.0;
  if (const std::optional<InputFault> fault = GripperPosition(msg, &position)) return Fault(*fault);
  if (Future(msg.utime, now_utime)) return Fault(InputFault::kGripperFuture);
  if (gripper_utime_ && msg.utime <= *gripper_utime_) return Fault(InputFault::kGripperOutOfOrder);
  gripper_utime_ = msg.utime;
  gripper_ = position;
}

Validity EstimatorNode::Evaluate(std::int64_t now_utime) const {
  if (!filter_.initialised() || !pose_utime_) return Validity::kNoPose;
  if (StampDifferenceUs(now_utime, *pose_utime_) > Micros(options_.pose_timeout_s)) return Validity::kPoseStale;
  if (!velocity_) return Validity::kNoOdometry;
  if (StampDifferenceUs(now_utime, velocity_->utime) > Micros(options_.odometry_timeout_s)) {
    return Validity::kOdometryStale;
  }
  if (!joints_) return Validity::kNoJoints;
  if (StampDifferenceUs(now_utime, joints_->utime) > Micros(options_.joints_timeout_s)) return Validity::kJointsStale;
  return Validity::kValid;
}

const robot_state_t* EstimatorNode::Step(std::int64_t now_utime) {
  ++counts_.cycles;
  const Validity validity = Evaluate(now_utime);
  if (validity != validity_) {
    if (validity == Validity::kValid) {
      spdlog::info("estimate valid: publishing ROBOT_STATE");
    } else {
      spdlog::warn("estimate not valid ({}): ROBOT_STATE held", ValidityName(validity));
      if (validity_ == Validity::kValid) ++counts_.invalidations;
    }
    validity_ = validity;
  }
  if (validity != Validity::kValid) {
    ++counts_.held;
    return nullptr;
  }
  Fill(now_utime);
  ++counts_.published;
  return &out_;
}

void EstimatorNode::Fill(std::int64_t now_utime) {
  PoseEstimate estimate;
  filter_.EstimateAt(now_utime, &estimate);  // initialised: checked by Evaluate
  out_.utime = now_utime;
  out_.pose.utime = estimate.t_us;
  out_.pose.x_m = estimate.X_WB.x();
  out_.pose.y_m = estimate.X_WB.y();
  out_.pose.yaw_rad = estimate.X_WB.z();
  out_.velocity = *velocity_;
  out_.joints = *joints_;
  const bool gripper_fresh =
      gripper_utime_ && StampDifferenceUs(now_utime, *gripper_utime_) <= Micros(options_.gripper_timeout_s);
  out_.gripper = gripper_fresh ? gripper_ : std::numeric_limits<double>::quiet_NaN();
}

std::int8_t EstimatorNode::Health() const {
  return validity_ == Validity::kValid ? heartbeat_t::OK : heartbeat_t::WARN;
}

std::string EstimatorNode::StatusLine(std::int64_t now_utime) const {
  const EstimatorSummary& s = filter_.summary();
  const std::optional<std::int64_t> velocity = velocity_ ? std::optional(velocity_->utime) : std::nullopt;
  const std::optional<std::int64_t> joints = joints_ ? std::optional(joints_->utime) : std::nullopt;
  return fmt::format("{}; ages: pose {}, odometry {}, joints {}, gripper {}; poses {} accepted, {} gated, {} reinit; "
                     "{} bad inputs",
                     validity_ == Validity::kValid ? "publishing" : fmt::format("held ({})", ValidityName(validity_)),
                     Age(pose_utime_, now_utime), Age(velocity, now_utime), Age(joints, now_utime),
                     Age(gripper_utime_, now_utime), s.poses_accepted + s.poses_initialised, s.poses_gated,
                     s.reinitialisations, counts_.total_faults());
}

std::string EstimatorNode::Report() const {
  const EstimatorCounts& c = counts_;
  std::string faults;
  for (int k = 0; k < kNumInputFaults; ++k) {
    if (c.faults[k] > 0) faults += fmt::format("{}{} {}", faults.empty() ? "" : ", ", c.faults[k],
                                               InputFaultName(static_cast<InputFault>(k)));
  }
  std::string covariance = "none";
  if (filter_.initialised()) {
    const Eigen::Matrix3d& P = filter_.Newest().P_WB;
    covariance = fmt::format("std dev x {:.4f} m, y {:.4f} m, yaw {:.4f} rad", std::sqrt(P(0, 0)),
                             std::sqrt(P(1, 1)), std::sqrt(P(2, 2)));
  }
  return fmt::format(
      "topay-estimator: {} cycles, {} ROBOT_STATE published, {} held, {} invalidations; last state {}\n"
      "  inputs: {} BASE_POSE, {} BASE_VELOCITY, {} JOINT_STATE, {} GRIPPER_STATE\n"
      "  filter: {}\n"
      "  final estimate: {}\n"
      "  bad inputs: {}\n",
      c.cycles, c.published, c.held, c.invalidations, ValidityName(validity_), c.poses, c.velocities, c.joints,
      c.grippers, FormatEstimatorSummary(filter_.summary()), covariance, faults.empty() ? "none" : faults);
}

void ConnectEstimatorNode(procs::ProcessLoop* loop, EstimatorNode* node, double period_s) {
  loop->Subscribe<base_pose_t>(std::string(channels::BASE_POSE),
                               [node](const base_pose_t& m) { node->OnPose(m, procs::NowUtime()); });
  loop->Subscribe<base_velocity_t>(std::string(channels::BASE_VELOCITY),
                                   [node](const base_velocity_t& m) { node->OnVelocity(m, procs::NowUtime()); });
  loop->Subscribe<joint_state_t>(std::string(channels::JOINT_STATE),
                                 [node](const joint_state_t& m) { node->OnJoints(m, procs::NowUtime()); });
  loop->Subscribe<joint_state_t>(std::string(channels::GRIPPER_STATE),
                                 [node](const joint_state_t& m) { node->OnGripper(m, procs::NowUtime()); });
  loop->AddTimer(period_s, [loop, node] {
    const std::int64_t now = procs::NowUtime();
    if (const robot_state_t* state = node->Step(now)) loop->lcm().publish(std::string(channels::ROBOT_STATE), state);
    loop->SetHealth(node->Health(), node->StatusLine(now));
  });
}

}  // namespace topay::estimator
