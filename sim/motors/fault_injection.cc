#include "sim/motors/fault_injection.h"

#include <linux/can/error.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace topay::sim::motors {
namespace {

struct KindName {
  FaultKind kind;
  const char* name;
};
constexpr KindName kKindNames[] = {
    {FaultKind::kClear, "clear"},         {FaultKind::kDriveFault, "drive_fault"},
    {FaultKind::kHeartbeatLoss, "heartbeat_loss"}, {FaultKind::kBusOff, "bus_off"},
    {FaultKind::kRxLoss, "rx_loss"},      {FaultKind::kTxLoss, "tx_loss"},
    {FaultKind::kDelay, "delay"},         {FaultKind::kBaseFault, "base_fault"},
};

bool Finite(double x) { return std::isfinite(x); }

std::string CheckPercent(double percent, const char* what) {
  if (!Finite(percent) || percent < 0.0 || percent > 100.0) {
    return std::string(what) + " " + std::to_string(percent) + " is outside 0..100 percent";
  }
  return "";
}

}  // namespace

const char* FaultKindName(FaultKind kind) {
  for (const KindName& k : kKindNames) {
    if (k.kind == kind) return k.name;
  }
  return "unknown";
}

bool ParseFaultKind(const std::string& name, FaultKind* kind) {
  for (const KindName& k : kKindNames) {
    if (name == k.name) {
      *kind = k.kind;
      return true;
    }
  }
  return false;
}

std::string CheckFaultEvent(const FaultEvent& e, int num_joints) {
  if (!Finite(e.at_s) || e.at_s < 0.0) return "at_s must be a finite time >= 0";
  if (!Finite(e.duration_s) || e.duration_s < 0.0) return "duration_s must be finite and >= 0";
  const bool needs_joint = e.kind == FaultKind::kDriveFault || e.kind == FaultKind::kHeartbeatLoss;
  if (needs_joint && (e.joint < 1 || e.joint > num_joints)) {
    return "joint " + std::to_string(e.joint) + " is outside 1.." + std::to_string(num_joints);
  }
  switch (e.kind) {
    case FaultKind::kBusOff:
      if (!(e.duration_s > 0.0)) return "bus_off needs duration_s > 0";
      return "";
    case FaultKind::kRxLoss:
    case FaultKind::kTxLoss:
      return CheckPercent(e.value, "loss");
    case FaultKind::kDelay:
      if (!Finite(e.value) || e.value < 0.0) return "delay value (ms) must be finite and >= 0";
      return "";
    case FaultKind::kBaseFault:
      if (e.code < 1 || e.code > 10) return "base fault code " + std::to_string(e.code) + " is outside 1..10";
      return "";
    case FaultKind::kDriveFault:
      if (e.code < 0 || e.code > 0xFFFF) return "EMCY code " + std::to_string(e.code) + " is outside 0..0xFFFF";
      return "";
    default:
      return "";
  }
}

std::string CheckFaultInjectionOptions(const FaultInjectionOptions& o, int num_joints) {
  if (std::string bad = CheckPercent(o.rx_loss_percent, "rx_loss_percent"); !bad.empty()) return bad;
  if (std::string bad = CheckPercent(o.tx_loss_percent, "tx_loss_percent"); !bad.empty()) return bad;
  if (!Finite(o.delay_ms) || o.delay_ms < 0.0) return "delay_ms must be finite and >= 0";
  if (!Finite(o.delay_burst_s) || o.delay_burst_s < 0.0) return "delay_burst_s must be finite and >= 0";
  if (o.delay_burst_s > 0.0 && !(o.delay_period_s > o.delay_burst_s && Finite(o.delay_period_s))) {
    return "delay_period_s must be finite and > delay_burst_s";
  }
  for (std::size_t i = 0; i < o.events.size(); ++i) {
    if (o.events[i].kind == FaultKind::kClear) return "events[" + std::to_string(i) + "]: clear is a run-time request only";
    if (std::string bad = CheckFaultEvent(o.events[i], num_joints); !bad.empty()) {
      return "events[" + std::to_string(i) + "]: " + bad;
    }
  }
  return "";
}

// --- FrameLink ---

void FrameLink::Push(const can::CanFrame& frame, double now_s, double loss_fraction, double delay_s) {
  if (loss_fraction > 0.0 && rng_.Uniform01() < loss_fraction) {
    ++counts_.lost;
    return;
  }
  // FIFO: a frame never overtakes an earlier one, also when the delay shrinks.
  const double due_s = std::max(now_s + delay_s, last_due_s_);
  last_due_s_ = due_s;
  if (due_s > now_s) ++counts_.delayed;
  queue_.push_back({due_s, frame});
}

std::vector<can::CanFrame> FrameLink::TakeDue(double now_s) {
  std::vector<can::CanFrame> due;
  while (!queue_.empty() && queue_.front().due_s <= now_s + 1e-12) {
    due.push_back(queue_.front().frame);
    queue_.pop_front();
    ++counts_.passed;
  }
  return due;
}

void FrameLink::Silence() {
  counts_.silenced += static_cast<std::int64_t>(queue_.size());
  queue_.clear();
}

// --- FaultInjector ---

FaultInjector::FaultInjector(const FaultInjectionOptions& options, int num_joints)
    : options_(options),
      num_joints_(num_joints),
      scripted_(options.events),
      rx_(DeriveSeed(options.seed, 1)),
      tx_(DeriveSeed(options.seed, 2)),
      rx_loss_(options.rx_loss_percent / 100.0),
      tx_loss_(options.tx_loss_percent / 100.0),
      heartbeat_lost_until_s_(static_cast<std::size_t>(num_joints), -1.0) {
  if (std::string bad = CheckFaultInjectionOptions(options, num_joints); !bad.empty()) {
    throw std::invalid_argument("FaultInjectionOptions: " + bad);
  }
  std::stable_sort(scripted_.begin(), scripted_.end(),
                   [](const FaultEvent& a, const FaultEvent& b) { return a.at_s < b.at_s; });
}

std::string FaultInjector::Inject(FaultEvent event, double now_s) {
  event.at_s = 0.0;
  if (std::string bad = CheckFaultEvent(event, num_joints_); !bad.empty()) {
    ++counts_.rejected;
    return std::string(FaultKindName(event.kind)) + ": " + bad;
  }
  event.at_s = now_s;
  pending_runtime_.push_back(event);
  return "";
}

FaultInjector::Actions FaultInjector::Advance(double now_s) {
  Actions actions;
  if (bus_off_ && now_s >= bus_off_until_s_) {
    bus_off_ = false;
    actions.error_frames.push_back(can::MakeCanErrorFrame(CAN_ERR_RESTARTED));
  }
  while (next_scripted_ < scripted_.size() && scripted_[next_scripted_].at_s <= now_s) {
    Apply(scripted_[next_scripted_++], now_s, &actions);
  }
  for (const FaultEvent& e : pending_runtime_) Apply(e, now_s, &actions);
  pending_runtime_.clear();
  if (runtime_delay_s_ >= 0.0 && runtime_delay_until_s_ > 0.0 && now_s >= runtime_delay_until_s_) {
    runtime_delay_s_ = -1.0;
  }
  return actions;
}

void FaultInjector::Apply(const FaultEvent& e, double now_s, Actions* actions) {
  const double until_s = e.duration_s > 0.0 ? now_s + e.duration_s : 0.0;
  switch (e.kind) {
    case FaultKind::kClear:
      rx_loss_ = tx_loss_ = 0.0;
      runtime_delay_s_ = 0.0;  // also switches the options' bursts off
      runtime_delay_until_s_ = 0.0;
      std::fill(heartbeat_lost_until_s_.begin(), heartbeat_lost_until_s_.end(), -1.0);
      ++counts_.link_changes;
      return;
    case FaultKind::kDriveFault:
      ++counts_.drive_faults;
      actions->node_faults.push_back(e);
      return;
    case FaultKind::kBaseFault:
      ++counts_.base_faults;
      actions->node_faults.push_back(e);
      return;
    case FaultKind::kHeartbeatLoss:
      ++counts_.heartbeat_losses;
      heartbeat_lost_until_s_[static_cast<std::size_t>(e.joint - 1)] = until_s;
      return;
    case FaultKind::kBusOff:
      ++counts_.bus_offs;
      if (!bus_off_) actions->error_frames.push_back(can::MakeCanErrorFrame(CAN_ERR_BUSOFF));
      bus_off_ = true;
      bus_off_until_s_ = std::max(bus_off_until_s_, now_s + e.duration_s);
      rx_.Silence();
      tx_.Silence();
      return;
    case FaultKind::kRxLoss:
      rx_loss_ = e.value / 100.0;
      ++counts_.link_changes;
      return;
    case FaultKind::kTxLoss:
      tx_loss_ = e.value / 100.0;
      ++counts_.link_changes;
      return;
    case FaultKind::kDelay:
      runtime_delay_s_ = e.value * 1e-3;
      runtime_delay_until_s_ = until_s;
      ++counts_.link_changes;
      return;
  }
}

bool FaultInjector::HeartbeatSuppressed(int joint, double now_s) const {
  if (joint < 1 || joint > num_joints_) return false;
  const double until_s = heartbeat_lost_until_s_[static_cast<std::size_t>(joint - 1)];
  return until_s == 0.0 || (until_s > 0.0 && now_s < until_s);
}

double FaultInjector::delay_s(double now_s) const {
  if (runtime_delay_s_ >= 0.0) return runtime_delay_s_;
  if (options_.delay_ms <= 0.0) return 0.0;
  if (options_.delay_burst_s <= 0.0) return options_.delay_ms * 1e-3;
  const double phase = std::fmod(now_s, options_.delay_period_s);
  return phase < options_.delay_burst_s ? options_.delay_ms * 1e-3 : 0.0;
}

void FaultInjector::PushReceived(const can::CanFrame& frame, double now_s) {
  if (bus_off_) {
    rx_.CountSilenced();
    return;
  }
  rx_.Push(frame, now_s, rx_loss_, delay_s(now_s));
}

void FaultInjector::PushSent(const can::CanFrame& frame, double now_s) {
  if (bus_off_) {
    tx_.CountSilenced();
    return;
  }
  tx_.Push(frame, now_s, tx_loss_, delay_s(now_s));
}

}  // namespace topay::sim::motors
