#include "graph_monitor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "topay/control_command_t.hpp"
#include "topay/drive_status_t.hpp"
#include "topay/heartbeat_t.hpp"
#include "topay/mission_status_t.hpp"
#include "topay/planner_status_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay/tracker_status_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay::tools {
namespace {

// The largest magnitude of a drive command's axes (base and joints); inf for a non-finite one.
// v, omega and the joint rates of an ACTUATOR_COMMAND, into *axes (its capacity kept).
void Axes(const control_command_t& c, std::vector<double>* axes) {
  axes->assign({c.v_mps, c.omega_radps});
  axes->insert(axes->end(), c.qdot_radps.begin(), c.qdot_radps.end());
}

// The largest |axis|; INFINITY when one is not finite.
double LargestAxis(const std::vector<double>& axes) {
  double largest = 0.0;
  for (double a : axes) {
    if (!std::isfinite(a)) return INFINITY;
    largest = std::max(largest, std::abs(a));
  }
  return largest;
}

}  // namespace

GraphMonitor::GraphMonitor(const std::string& lcm_url)
    : lcm_(std::make_unique<lcm::LCM>(lcm_url)), start_(std::chrono::steady_clock::now()) {
  if (!lcm_->good()) throw std::runtime_error("topay-faults: cannot join the LCM bus " + lcm_url);
  raw_ = std::make_unique<RawHandler>(RawHandler{this});
  lcm_->subscribe(".*", &RawHandler::On, raw_.get());
  thread_ = std::thread([this] { Run(); });
}

GraphMonitor::~GraphMonitor() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  thread_.join();
}

void GraphMonitor::RawHandler::On(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  self->OnMessage(channel, static_cast<const std::uint8_t*>(rbuf->data), rbuf->data_size);
}

double GraphMonitor::Now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void GraphMonitor::Run() {
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_) return;
    }
    lcm_->handleTimeout(20);
  }
}

GraphView GraphMonitor::View() const {
  std::lock_guard<std::mutex> lock(mutex_);
  GraphView view = view_;
  view.now_s = Now();
  return view;
}

std::vector<std::uint8_t> GraphMonitor::LastMessage(const std::string& channel) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = last_.find(channel);
  return it == last_.end() ? std::vector<std::uint8_t>{} : it->second;
}

std::vector<std::string> GraphMonitor::Channels() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> channels;
  for (const auto& [channel, bytes] : last_) channels.push_back(channel);
  return channels;
}

void GraphMonitor::Reset() {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto heartbeat_s = view_.heartbeat_s;
  const auto heartbeat_pid = view_.heartbeat_pid;
  view_ = GraphView{};
  braking_ = BrakingRun(kZeroThreshold);
  view_.heartbeat_s = heartbeat_s;
  view_.heartbeat_pid = heartbeat_pid;
}

void GraphMonitor::SetTap(MessageTap tap) {
  std::lock_guard<std::mutex> lock(tap_mutex_);  // waits for a call of the old tap to end
  tap_ = std::move(tap);
}

void GraphMonitor::OnMessage(const std::string& channel, const std::uint8_t* data, std::size_t size) {
  const double t = Now();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    GraphView& v = view_;
    ++v.messages;
    last_[channel].assign(data, data + size);
    if (channel == channels::CONTROL_COMMAND) {
      if (CheckedDecode<control_command_t>(data, size, nullptr)) v.last_control_command_s = t;
    } else if (channel == channels::ACTUATOR_COMMAND) {
      if (const auto c = CheckedDecode<control_command_t>(data, size, nullptr)) {
        Axes(*c, &axes_);
        const double largest = LargestAxis(axes_);
        const bool zero = largest < kZeroThreshold;
        if (zero && (!v.actuator_zero || v.actuator_zero_since_s < 0.0)) v.actuator_zero_since_s = t;
        v.actuator_zero = zero;
        if (largest >= kMovingThreshold) v.last_moving_s = t;
        v.actuator_braking_since_s = braking_.Add(axes_, t);
        v.last_actuator_s = t;
      }
    } else if (channel == channels::DRIVE_STATUS) {
      if (const auto s = CheckedDecode<drive_status_t>(data, size, nullptr)) {
        if (v.drive_changes.empty() || v.drive_changes.back().state != s->state ||
            v.drive_changes.back().stop_reason != s->stop_reason) {
          v.drive_changes.push_back({t, s->state, s->stop_reason});
        }
        v.drive_state = s->state;
        v.last_drive_status_s = t;
      }
    } else if (channel == channels::MISSION_STATUS) {
      if (const auto m = CheckedDecode<mission_status_t>(data, size, nullptr)) {
        v.mission_state = m->state;
        v.mission_step = m->step_index;
        v.mission_goal_id = m->goal_id;
        v.mission_detail = m->detail;
        v.last_mission_status_s = t;
      }
    } else if (channel == channels::PLANNER_STATUS) {
      if (const auto p = CheckedDecode<planner_status_t>(data, size, nullptr)) {
        if (v.planner_changes.empty() || v.planner_changes.back().goal_id != p->goal_id ||
            v.planner_changes.back().state != p->state) {
          if (v.planner_changes.size() == GraphView::kMaxPlannerChanges) v.planner_changes.erase(v.planner_changes.begin());
          v.planner_changes.push_back({t, p->goal_id, p->state, p->failure_reason});
        }
      }
    } else if (channel == channels::TRACKER_STATUS) {
      if (const auto s = CheckedDecode<tracker_status_t>(data, size, nullptr)) {
        const bool held = s->state == tracker_status_t::HELD;
        if (held && !v.tracker_held) v.tracker_held_starts_s.push_back(t);
        v.tracker_held = held;
      }
    } else if (channel == channels::SIM_CONTACT) {
      if (CheckedDecode<sim_contact_t>(data, size, nullptr)) ++v.contacts;
    } else if (channel == channels::HEARTBEAT) {
      if (const auto h = CheckedDecode<heartbeat_t>(data, size, nullptr)) {
        v.heartbeat_s[h->process_name] = t;
        v.heartbeat_pid[h->process_name] = h->pid;
      }
    }
  }
  std::lock_guard<std::mutex> lock(tap_mutex_);
  if (tap_) tap_(channel, std::vector<std::uint8_t>(data, data + size), t);
}

}  // namespace topay::tools
