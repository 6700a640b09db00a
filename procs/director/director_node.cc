#include "procs/director/director_node.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace topay::director {
namespace {

constexpr int kFirstAutomaticBoxId = 1000;

}  // namespace

DirectorNode::DirectorNode(DirectorOptions options, Scene scene, const Kinematics& kinematics,
                           DirectorOutputs outputs)
    : options_(std::move(options)),
      scene_(std::move(scene)),
      kinematics_(kinematics),
      outputs_(std::move(outputs)),
      rng_(options_.seed) {
  const int first_free = std::max(kFirstAutomaticBoxId, static_cast<int>(scene_.boxes.size()));
  for (std::size_t i = 0; i < options_.events.size(); ++i) {
    Pending p;
    p.event = options_.events[i];
    p.box_id = p.event.box_id >= 0 ? p.event.box_id : first_free + static_cast<int>(i);
    pending_.push_back(p);
  }
  if (!pending_.empty()) status_ = "waiting for step " + pending_.front().event.during_step;
}

void DirectorNode::OnMissionStatus(const mission_status_t& msg) { mission_ = msg; }

void DirectorNode::OnTrajectory(const poly_trajectory_t& msg) {
  std::string error;
  std::optional<BasePath> path = SampleBasePath(msg, options_.path_sample_s, &error);
  if (!path) {
    Log(true, "trajectory " + std::to_string(msg.trajectory_id) + " ignored: " + error);
    return;
  }
  path_ = std::move(path);
}

void DirectorNode::OnRobotState(const robot_state_t& msg) {
  std::string error;
  const std::optional<msgs::RobotStateEstimate> estimate = state_intake_.Take(msg, &error);
  if (!estimate) {
    if (state_intake_.LogRefusal()) spdlog::warn("ROBOT_STATE ignored (#{}): {}", state_intake_.refused(), error);
    return;
  }
  p_WR_m_ = Eigen::Vector2d(estimate->state.x_m, estimate->state.y_m);
  speed_mps_ = std::abs(estimate->v_mps);
}

bool DirectorNode::all_done() const {
  return std::all_of(pending_.begin(), pending_.end(), [](const Pending& p) { return p.done; });
}

bool DirectorNode::StepRunning(const Pending& p) const {
  return mission_ && mission_->state == mission_status_t::RUNNING &&
         (mission_->step == "goto " + p.event.during_step || mission_->step == p.event.during_step);
}

bool DirectorNode::RobotDriving(const Pending& p) const { return p_WR_m_ && speed_mps_ >= p.event.min_speed_mps; }

std::optional<RouteQuery> DirectorNode::Route(std::int64_t now_utime) const {
  if (!path_ || !p_WR_m_) return std::nullopt;
  const std::optional<std::size_t> index = path_->IndexAt(now_utime);
  if (!index) return std::nullopt;  // a replan not joined yet
  RouteQuery route;
  route.path_W_m = path_->p_W_m;
  route.robot_index = *index;
  route.p_WR_m = *p_WR_m_;
  return route;
}

void DirectorNode::Tick(std::int64_t now_utime) {
  TakePlacement(now_utime);
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    Pending& p = pending_[i];
    if (p.done) continue;
    const std::string box = "box " + std::to_string(p.box_id);
    if (StepRunning(p)) {
      p.step_seen = true;
      if (!placement_.busy() && RobotDriving(p) && now_utime >= p.next_attempt_utime) StartPlacement(i, now_utime);
      status_ = "step " + p.event.during_step + " runs: " + (placement_.busy() ? "checking" : "waiting for") +
                " a place for " + box;
    } else if (p.step_seen) {
      p.done = true;  // a running attempt's result is dropped when it comes
      ++given_up_;
      status_ = "no place for " + box + " before step " + p.event.during_step + " ended";
      Log(true, p.event.name + ": " + status_ + "; nothing published");
    } else {
      status_ = "waiting for step " + p.event.during_step;
    }
    return;  // one event at a time, in order
  }
}

void DirectorNode::StartPlacement(std::size_t event_index, std::int64_t now_utime) {
  const std::optional<RouteQuery> route = Route(now_utime);
  if (!route) return;
  const PlacementTag tag{path_->trajectory_id, event_index};
  placement_.Start(tag, *route, scene_, kinematics_, pending_[event_index].event.box, rng_);
}

void DirectorNode::TakePlacement(std::int64_t now_utime) {
  const std::optional<PlacementResult> result = placement_.TakeIfDone();
  if (!result) return;
  rng_ = result->rng;  // the draws go on from where the attempt left them
  Pending& p = pending_[result->tag.event_index];
  if (p.done) return;  // its step ended meanwhile
  if (!result->box) {
    p.next_attempt_utime = now_utime + static_cast<std::int64_t>(options_.retry_period_s * 1e6);
    return;
  }
  // The robot drove on while the room was checked: the box again against where it is now.
  if (!path_ || path_->trajectory_id != result->tag.trajectory_id || !StepRunning(p)) return;
  const std::optional<RouteQuery> now = Route(now_utime);
  if (!now) return;
  const std::optional<RouteBox> checked = RecheckRouteBox(*result->box, *now, p.event.box);
  if (!checked) return;
  Publish(p, *checked, now_utime);
  p.done = true;
}

void DirectorNode::Publish(const Pending& p, const RouteBox& placed, std::int64_t now_utime) {
  sim_event_t m{};
  m.utime = now_utime;
  m.name = p.event.name;
  m.action = sim_event_t::APPEAR;
  m.box_id = p.box_id;
  m.has_box = true;
  for (int a = 0; a < 3; ++a) {
    m.center_m[a] = placed.box.center_W_m[a];
    m.size_m[a] = placed.box.size_m[a];
  }
  m.yaw_rad = placed.box.yaw_rad;
  m.trigger = sim_event_t::NOW;
  if (outputs_.event) outputs_.event(m);
  scene_.boxes.push_back(placed.box);  // later events keep clear of it
  ++boxes_placed_;
  status_ = fmt::format("box {} placed at ({:.2f}, {:.2f}) {:.1f} m ahead", p.box_id, placed.box.center_W_m.x(),
                        placed.box.center_W_m.y(), placed.ahead_m);
  Log(false, p.event.name + ": " + status_ + fmt::format(" (side {:.2f} m, robot at {:.1f} m/s)",
                                                         placed.box.size_m.x(), speed_mps_));
}

void DirectorNode::Log(bool warning, const std::string& line) {
  if (outputs_.log) outputs_.log(warning, line);
}

}  // namespace topay::director
