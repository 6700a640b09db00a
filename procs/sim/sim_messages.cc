#include "procs/sim/sim_messages.h"

#include <cmath>
#include <limits>

#include "procs/msgs/convert_robot_state.h"

namespace topay::simproc {

std::int64_t SimUtime(std::int64_t start_utime, double t_s) { return start_utime + std::llround(t_s * 1e6); }

sim::ActuatorCommand ToActuatorCommand(const control_command_t& msg) {
  sim::ActuatorCommand c;
  c.v_mps = msg.v_mps;
  c.omega_radps = msg.omega_radps;
  c.gripper = msg.gripper;
  if (msg.num_joints >= 0 && static_cast<std::size_t>(msg.num_joints) == msg.qdot_radps.size()) {
    c.qdot_radps = Eigen::Map<const Eigen::VectorXd>(msg.qdot_radps.data(), msg.num_joints);
  }
  return c;
}

robot_state_t ToRobotState(const StateSample& sample, std::int64_t start_utime,
                           const std::vector<std::string>& joint_names) {
  // The localisation's pose with the measured joints and wheel-odometry velocity, encoded by
  // the graph's one robot-state conversion (procs/msgs).
  msgs::RobotStateEstimate estimate;
  estimate.utime = SimUtime(start_utime, sample.t_s);
  estimate.state.x_m = sample.pose.x_m;
  estimate.state.y_m = sample.pose.y_m;
  estimate.state.yaw_rad = sample.pose.yaw_rad;
  estimate.state.q_rad = sample.measured.q_rad;
  estimate.v_mps = sample.measured.v_mps;
  estimate.omega_radps = sample.measured.omega_radps;
  estimate.qdot_radps = sample.measured.qdot_radps;
  estimate.joint_names = joint_names;
  estimate.gripper = sample.measured.gripper;
  return msgs::ToMessage(estimate);
}

robot_state_t ToPlantStateMessage(const sim::PlantState& truth, const sim::MeasuredActuators& measured,
                                  std::int64_t utime, const std::vector<std::string>& joint_names) {
  msgs::RobotStateEstimate estimate;
  estimate.utime = utime;
  estimate.state = truth.state;
  estimate.v_mps = measured.v_mps;
  estimate.omega_radps = measured.omega_radps;
  estimate.qdot_radps = truth.qdot_radps;
  estimate.joint_names = joint_names;
  estimate.gripper = truth.gripper;
  return msgs::ToMessage(estimate);
}

joint_state_t ToGripperState(double gripper, std::int64_t utime) {
  joint_state_t m;
  m.utime = utime;
  m.num_joints = 1;
  m.names = {"gripper"};
  m.position_rad = {gripper};
  m.velocity_radps = {std::numeric_limits<double>::quiet_NaN()};
  m.effort_Nm = {std::numeric_limits<double>::quiet_NaN()};
  return m;
}

point_cloud_t ToPointCloud(const ScanResult& scan, std::int64_t start_utime, const std::string& frame) {
  point_cloud_t m;
  m.utime = SimUtime(start_utime, scan.t_s);
  m.sensor_frame = frame;
  const Eigen::Vector3d p = scan.X_WS.translation();
  const Eigen::Quaterniond q(scan.X_WS.rotation());
  for (int i = 0; i < 3; ++i) m.p_WS[i] = p[i];
  m.quat_WS[0] = q.w();
  m.quat_WS[1] = q.x();
  m.quat_WS[2] = q.y();
  m.quat_WS[3] = q.z();
  m.num_coords = static_cast<std::int32_t>(3 * scan.p_SP.size());
  m.p_SP.resize(m.num_coords);
  for (std::size_t i = 0; i < scan.p_SP.size(); ++i) {
    m.p_SP[3 * i] = scan.p_SP[i].x();
    m.p_SP[3 * i + 1] = scan.p_SP[i].y();
    m.p_SP[3 * i + 2] = scan.p_SP[i].z();
  }
  return m;
}

sim_contact_t ToContactMessage(const ContactResult& contact, int box_id, std::int64_t start_utime) {
  sim_contact_t m;
  m.utime = SimUtime(start_utime, contact.t_s);
  m.body = contact.body;
  m.box_id = box_id;
  m.depth_m = contact.depth_m;
  return m;
}

std::optional<sim::SimEvent> FromEventMessage(const sim_event_t& msg, std::string* error) {
  sim::SimEvent e;
  e.name = msg.name.empty() ? "SIM_EVENT" : msg.name;
  if (msg.action == sim_event_t::APPEAR) {
    e.action = sim::SimEvent::Action::kAppear;
  } else if (msg.action == sim_event_t::DISAPPEAR) {
    e.action = sim::SimEvent::Action::kDisappear;
  } else {
    *error = "action: unknown value " + std::to_string(msg.action);
    return std::nullopt;
  }
  if (msg.box_id < 0) {
    *error = "box_id: must be >= 0";
    return std::nullopt;
  }
  e.box_id = msg.box_id;
  if (msg.has_box) {
    OrientedBox box;
    box.center_W_m = Eigen::Vector3d(msg.center_m[0], msg.center_m[1], msg.center_m[2]);
    box.size_m = Eigen::Vector3d(msg.size_m[0], msg.size_m[1], msg.size_m[2]);
    box.yaw_rad = msg.yaw_rad;
    const std::string why = sim::CheckBox(box);
    if (!why.empty()) {
      *error = "box: " + why;
      return std::nullopt;
    }
    e.box = box;
  }
  switch (msg.trigger) {
    case sim_event_t::NOW:
      e.trigger = sim::SimEvent::Trigger::kNow;
      break;
    case sim_event_t::AT_TIME:
      e.trigger = sim::SimEvent::Trigger::kAtTime;
      e.at_s = msg.at_s;
      if (!std::isfinite(msg.at_s)) {
        *error = "at_s: must be finite";
        return std::nullopt;
      }
      break;
    case sim_event_t::NEAR_POINT:
      e.trigger = sim::SimEvent::Trigger::kNearPoint;
      e.point_W_m = Eigen::Vector2d(msg.point_m[0], msg.point_m[1]);
      e.distance_m = msg.distance_m;
      if (!e.point_W_m.allFinite() || !(msg.distance_m > 0.0) || !std::isfinite(msg.distance_m)) {
        *error = "point_m / distance_m: must be finite, distance > 0";
        return std::nullopt;
      }
      break;
    default:
      *error = "trigger: unknown value " + std::to_string(msg.trigger);
      return std::nullopt;
  }
  return e;
}

sim_event_t ToEventMessage(const sim::SimEvent& event, std::int64_t utime) {
  sim_event_t m{};
  m.utime = utime;
  m.name = event.name;
  m.action = event.action == sim::SimEvent::Action::kAppear ? sim_event_t::APPEAR : sim_event_t::DISAPPEAR;
  m.box_id = event.box_id;
  m.has_box = event.box.has_value();
  if (event.box) {
    for (int i = 0; i < 3; ++i) m.center_m[i] = event.box->center_W_m[i];
    for (int i = 0; i < 3; ++i) m.size_m[i] = event.box->size_m[i];
    m.yaw_rad = event.box->yaw_rad;
  }
  m.trigger = event.trigger == sim::SimEvent::Trigger::kNow      ? sim_event_t::NOW
              : event.trigger == sim::SimEvent::Trigger::kAtTime ? sim_event_t::AT_TIME
                                                                 : sim_event_t::NEAR_POINT;
  m.at_s = event.at_s;
  m.point_m[0] = event.point_W_m.x();
  m.point_m[1] = event.point_W_m.y();
  m.distance_m = event.distance_m;
  return m;
}

}  // namespace topay::simproc
