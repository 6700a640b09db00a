#include "fault_injector.h"

#include <signal.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <lcm/lcm-cpp.hpp>

#include "graph_processes.h"
#include "obstacle_goal.h"
#include "procs/msgs/convert_goal.h"
#include "tools/topay_missions/child_command.h"
#include "topay/base_pose_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/goal_t.hpp"
#include "topay/motorsim_fault_t.hpp"
#include "topay_msgs/checked_decode.h"
#include "topay_msgs/channels.h"

namespace topay::tools {
namespace {

std::int64_t NowMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Channels whose messages lcm-reorder re-sends late: the state and command streams.
const std::vector<std::string> kReorderedChannels = {"ROBOT_STATE", "CONTROL_COMMAND", "BASE_POSE",
                                                     "BASE_VELOCITY", "JOINT_STATE", "TRAJECTORY"};
constexpr double kReorderDelayS = 0.030;
constexpr double kFloodPeriodS = 0.001;        // lcm-goal-flood: 1 kHz
constexpr double kGoalChangePeriodS = 0.050;   // goal-every-50ms
constexpr double kDelayBurstPeriodS = 1.0;     // can-delay: a burst every second
constexpr int kDelayBursts = 3;
constexpr double kHostileChannelPeriodS = 0.04;  // hostile-payloads: one channel every 40 ms (a round per s)
constexpr int kHostileRounds = 3;
constexpr std::size_t kOversizedBytes = 256 * 1024;

// nftables: one table of the tool's own in the graph's namespace (removed by End).
constexpr const char* kTable = "inet topay_faults";

// nftables rules that drop every datagram of one LCM channel (name up to 15 characters): its
// name + NUL is the channel field of a short message (UDP payload offset 8, after the magic and
// the sequence number) and of a fragmented message's first fragment (offset 20, after magic,
// sequence number, size, offset, fragment number and count); without its first fragment a
// fragmented message is never assembled. @th counts bits from the UDP header (8 bytes).
std::string DropChannelRules(int port, const std::string& channel) {
  std::string hex = "0x";
  for (char c : channel + '\0') hex += fmt::format("{:02x}", static_cast<unsigned char>(c));
  const std::size_t bits = 8 * (channel.size() + 1);
  return fmt::format("udp dport {0} @th,{1},{2} {3} drop\n    udp dport {0} @th,{4},{2} {3} drop", port, 64 + 8 * 8,
                     bits, hex, 64 + 20 * 8);
}

bool SimulatorChannel(const std::string& channel) {
  for (std::string_view c : {channels::SIM_EVENT, channels::ACTUATOR_COMMAND, channels::SIM_PLANT_STATE,
                             channels::SIM_CONTACT, channels::SIM_STATUS, channels::MOTORSIM_FAULT}) {
    if (channel == c) return true;
  }
  return false;
}

// Identifies a re-sent copy when it comes back from the bus.
std::size_t CopyKey(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
  return std::hash<std::string>{}(channel) ^
         (std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size())) << 1);
}

}  // namespace

FaultInjector::FaultInjector(const FaultInjectorOptions& options, GraphMonitor* monitor)
    : options_(options), monitor_(monitor), lcm_(std::make_unique<lcm::LCM>(options.lcm_url)), random_(options.seed) {
  if (!lcm_->good()) throw std::runtime_error("topay-faults: cannot publish on the LCM bus " + options.lcm_url);
  monitor_->SetTap([this](const std::string& channel, const std::vector<std::uint8_t>& bytes, double time_s) {
    std::lock_guard<std::mutex> lock(delayed_mutex_);
    if (!reordering_) return;
    const auto own = own_copies_.find(CopyKey(channel, bytes));
    if (own != own_copies_.end()) {  // a copy this injector sent: not copied again
      own_copies_.erase(own);
      return;
    }
    for (const std::string& c : kReorderedChannels) {
      if (c == channel) delayed_.push_back({time_s + kReorderDelayS, channel, bytes});
    }
  });
}

FaultInjector::~FaultInjector() {
  monitor_->SetTap(nullptr);
  End();
}

bool FaultInjector::Begin(const FaultSpec& fault) {
  End();
  fault_ = fault;
  notes_.clear();
  killed_pid_ = 0;
  tick_actions_ = 0;
  begin_s_ = monitor_->Now();
  last_tick_action_s_ = begin_s_;
  bool started = false;
  switch (fault.family) {
    case FaultFamily::kKill: started = BeginKill(fault); break;
    case FaultFamily::kCan: started = BeginCan(fault); break;
    case FaultFamily::kLcm: started = BeginLcm(fault); break;
    case FaultFamily::kGoal: started = BeginGoal(fault); break;
    case FaultFamily::kHostile:
      hostile_sent_ = 0;
      SendHostilePayloads(0);
      tick_actions_ = 1;
      started = true;
      break;
  }
  std::lock_guard<std::mutex> lock(delayed_mutex_);
  active_ = started;
  reordering_ = started && fault.name == "lcm-reorder";
  return started;
}

bool FaultInjector::BeginKill(const FaultSpec& fault) {
  const std::string comm = CommandNameOf(fault.target);
  const auto processes = DescendantProcesses(options_.graph_ancestor);
  const auto it = processes.find(comm);
  if (it == processes.end()) {
    notes_ = comm + " is not running";
    return false;
  }
  killed_pid_ = it->second;
  if (kill(killed_pid_, SIGKILL) != 0) {
    notes_ = fmt::format("kill -9 {} ({}) failed", killed_pid_, comm);
    return false;
  }
  notes_ = fmt::format("kill -9 {} ({})", killed_pid_, comm);
  return true;
}

bool FaultInjector::BeginCan(const FaultSpec& fault) {
  std::uniform_int_distribution<int> joint(1, 7);
  if (fault.name == "can-loss") {
    SendMotorsimFault(motorsim_fault_t::RX_LOSS, 0, 0.0, 10.0, 0);
    SendMotorsimFault(motorsim_fault_t::TX_LOSS, 0, 0.0, 10.0, 0);
  } else if (fault.name == "can-delay") {
    SendMotorsimFault(motorsim_fault_t::DELAY, 0, 0.5, 20.0, 0);
    tick_actions_ = 1;
  } else if (fault.name == "can-drive-fault") {
    SendMotorsimFault(motorsim_fault_t::DRIVE_FAULT, joint(random_), 0.0, 0.0, 0x5000);
  } else if (fault.name == "can-heartbeat-loss") {
    SendMotorsimFault(motorsim_fault_t::HEARTBEAT_LOSS, joint(random_), fault.hold_s, 0.0, 0);
  } else if (fault.name == "can-bus-off") {
    SendMotorsimFault(motorsim_fault_t::BUS_OFF, 0, fault.hold_s, 0.0, 0);
  } else if (fault.name == "can-base-fault") {
    SendMotorsimFault(motorsim_fault_t::BASE_FAULT, 0, 0.0, 0.0, 1);
  } else {
    notes_ = "no CAN fault " + fault.name;
    return false;
  }
  return true;
}

bool FaultInjector::BeginLcm(const FaultSpec& fault) {
  if (fault.name == "lcm-drop") {
    return ApplyRules(fmt::format("udp dport {} numgen random mod 100 < 10 drop", options_.lcm_port));
  }
  if (fault.name == "lcm-stale-localisation") return ApplyRules(DropChannelRules(options_.lcm_port, "BASE_POSE"));
  if (fault.name == "lcm-map-frozen") return ApplyRules(DropChannelRules(options_.lcm_port, "MAP_UPDATE"));
  if (fault.name == "lcm-reorder") {
    notes_ = "copies of " + std::to_string(kReorderedChannels.size()) + " channels re-sent 30 ms late";
    return true;
  }
  if (fault.name == "lcm-goal-flood") {
    if (monitor_->LastMessage(std::string(channels::GOAL)).empty()) {
      notes_ = "no GOAL on the bus yet";
      return false;
    }
    notes_ = "the last GOAL re-sent every 1 ms";
    return true;
  }
  notes_ = "no LCM fault " + fault.name;
  return false;
}

bool FaultInjector::BeginGoal(const FaultSpec& fault) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (fault.name == "goal-nan") {
    PublishGoal(Eigen::Vector3d(nan, 1.0, nan), 0.0);
  } else if (fault.name == "goal-unreachable") {
    PublishGoal(options_.room_max_m + Eigen::Vector3d(100.0, 100.0, 0.0), 0.0);
  } else if (fault.name == "goal-in-obstacle") {
    if (options_.box_centers_m.empty()) {
      notes_ = "the room has no box";
      return false;
    }
    // A box near the robot: one it has seen (obstacle_goal.h).
    constexpr double kNearRobot_m = 4.0;
    PublishGoal(ChooseObstacleGoal(options_.box_centers_m, RobotPosition(), kNearRobot_m, &random_), 0.0);
  } else if (fault.name == "goal-every-50ms") {
    PublishGoal(RandomPointInRoom(), 0.0);
  } else {
    notes_ = "no goal fault " + fault.name;
    return false;
  }
  return true;
}

std::optional<Eigen::Vector2d> FaultInjector::RobotPosition() const {
  const std::vector<std::uint8_t> last = monitor_->LastMessage(std::string(channels::BASE_POSE));
  const auto pose = CheckedDecode<base_pose_t>(last.data(), static_cast<int>(last.size()), nullptr);
  if (!pose || !std::isfinite(pose->x_m) || !std::isfinite(pose->y_m)) return std::nullopt;
  return Eigen::Vector2d(pose->x_m, pose->y_m);
}

void FaultInjector::Tick() {
  if (!active_) return;
  const double now = monitor_->Now();
  const double since_action = now - last_tick_action_s_;
  if (fault_.name == "lcm-goal-flood" && since_action >= kFloodPeriodS) {
    const std::vector<std::uint8_t> goal = monitor_->LastMessage(std::string(channels::GOAL));
    lcm_->publish(std::string(channels::GOAL), goal.data(), static_cast<unsigned>(goal.size()));
    last_tick_action_s_ = now, ++tick_actions_;
  } else if (fault_.name == "goal-every-50ms" && since_action >= kGoalChangePeriodS) {
    PublishGoal(RandomPointInRoom(), std::uniform_real_distribution<double>(-M_PI, M_PI)(random_));
    last_tick_action_s_ = now, ++tick_actions_;
  } else if (fault_.name == "can-delay" && tick_actions_ < kDelayBursts && since_action >= kDelayBurstPeriodS) {
    SendMotorsimFault(motorsim_fault_t::DELAY, 0, 0.5, 20.0, 0);
    last_tick_action_s_ = now, ++tick_actions_;
  } else if (fault_.name == "hostile-payloads" &&
             tick_actions_ < kHostileRounds * static_cast<int>(channels::kAll.size()) &&
             since_action >= kHostileChannelPeriodS) {
    SendHostilePayloads(tick_actions_);
    last_tick_action_s_ = now, ++tick_actions_;
  }
  if (fault_.name == "lcm-reorder") SendDelayedCopies();
}

void FaultInjector::End() {
  {
    std::lock_guard<std::mutex> lock(delayed_mutex_);
    if (!active_) return;
    active_ = false;
    reordering_ = false;
    delayed_.clear();
    own_copies_.clear();
  }
  if (fault_.family == FaultFamily::kCan && fault_.hold_s > 0.0) {
    SendMotorsimFault(motorsim_fault_t::CLEAR, 0, 0.0, 0.0, 0);
  }
  if (rules_applied_) RemoveRules();
  if (tick_actions_ > 1 && fault_.family != FaultFamily::kHostile) {
    notes_ += fmt::format("; {} repeated actions", tick_actions_);
  }
}

void FaultInjector::SendFaultReset() {
  drive_command_t command{};
  command.utime = NowMicros();
  command.command = drive_command_t::FAULT_RESET;
  command.source = "topay-faults (operator)";
  lcm_->publish(std::string(channels::DRIVE_COMMAND), &command);
}

void FaultInjector::SendMotorsimFault(int kind, int joint, double duration_s, double value, int code) {
  motorsim_fault_t fault{};
  fault.utime = NowMicros();
  fault.kind = static_cast<std::int8_t>(kind);
  fault.joint = joint;
  fault.duration_s = duration_s;
  fault.value = value;
  fault.code = code;
  lcm_->publish(std::string(channels::MOTORSIM_FAULT), &fault);
  notes_ += fmt::format("{}MOTORSIM_FAULT kind {} joint {} {} s value {} code {:#x}", notes_.empty() ? "" : "; ",
                        kind, joint, duration_s, value, code);
}

bool FaultInjector::ApplyRules(const std::string& rule) {
  const std::string path = options_.work_dir + "/faults.nft";
  std::ofstream(path) << "table " << kTable << " {\n  chain out {\n    type filter hook output priority 0;\n    "
                      << rule << "\n  }\n}\n";
  ChildCommandOptions child;
  child.output_path = options_.work_dir + "/nft.out";
  const ChildCommandResult r = RunChildCommand({"nft", "-f", path}, child);
  rules_applied_ = r.exit_code == 0;
  notes_ = rules_applied_ ? "nft: " + rule
                          : fmt::format("nft -f {} failed (exit code {}, see {}){}", path, r.exit_code,
                                        child.output_path, r.error.empty() ? "" : ": " + r.error);
  return rules_applied_;
}

void FaultInjector::RemoveRules() {
  ChildCommandOptions child;
  child.output_path = options_.work_dir + "/nft.out";
  RunChildCommand({"nft", "delete", "table", "inet", "topay_faults"}, child);
  rules_applied_ = false;
}

void FaultInjector::PublishGoal(const Eigen::Vector3d& p_WE, double yaw_rad) {
  // Built as the mission sequencer builds its goals (procs/msgs/convert_goal.h), no hint.
  msgs::PlanGoal plan_goal;
  plan_goal.utime = NowMicros();
  plan_goal.goal_id = ++next_goal_id_;
  plan_goal.X_WE = Eigen::Translation3d(p_WE) * Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ());
  const goal_t goal = msgs::ToMessage(plan_goal);
  lcm_->publish(std::string(channels::GOAL), &goal);
  if (notes_.empty()) notes_ = fmt::format("GOAL {} at ({:.2f}, {:.2f}, {:.2f})", goal.goal_id, p_WE.x(), p_WE.y(), p_WE.z());
}

Eigen::Vector3d FaultInjector::RandomPointInRoom() {
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    p[i] = std::uniform_real_distribution<double>(options_.room_min_m[i], options_.room_max_m[i])(random_);
  }
  return p;
}

// Step k of the hostile rounds: on channel k mod 25, two random payloads, one oversized payload
// that starts like the channel's messages (its fingerprint), a truncated and two bit-flipped
// copies of its last message. No bit-flipped copy (it may still decode) on the simulator's own
// channels: there a message that decodes is not input to the robot's software but a change of
// the simulated world (a box appearing, the motors' physical output, the plant's true state,
// the ground truth, a fault request).
void FaultInjector::SendHostilePayloads(int step) {
  const std::string channel(channels::kAll[static_cast<std::size_t>(step) % channels::kAll.size()]);
  std::uniform_int_distribution<int> byte(0, 255);
  const auto random_bytes = [&](std::size_t n) {
    std::vector<std::uint8_t> bytes(n);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(byte(random_));
    return bytes;
  };
  std::vector<std::vector<std::uint8_t>> payloads = {random_bytes(1 + random_() % 300),
                                                     random_bytes(1 + random_() % 300), random_bytes(kOversizedBytes)};
  const std::vector<std::uint8_t> last = monitor_->LastMessage(channel);
  if (last.size() >= 8) {
    std::copy(last.begin(), last.begin() + 8, payloads.back().begin());
    payloads.emplace_back(last.begin(), last.begin() + static_cast<std::ptrdiff_t>(last.size() / 2));
    for (int copy = 0; copy < 2 && !SimulatorChannel(channel); ++copy) {
      std::vector<std::uint8_t> flipped = last;
      for (int k = 0; k < 1 + copy * 3 && flipped.size() > 8; ++k) {
        flipped[8 + random_() % (flipped.size() - 8)] ^= static_cast<std::uint8_t>(1 << (random_() % 8));
      }
      payloads.push_back(std::move(flipped));
    }
  }
  for (const auto& p : payloads) lcm_->publish(channel, p.data(), static_cast<unsigned>(p.size()));
  hostile_sent_ += static_cast<int>(payloads.size());
  notes_ = fmt::format("{} hostile payloads on {} channels", hostile_sent_,
                       std::min<std::size_t>(static_cast<std::size_t>(step) + 1, channels::kAll.size()));
}

void FaultInjector::SendDelayedCopies() {
  std::vector<Delayed> due;
  {
    std::lock_guard<std::mutex> lock(delayed_mutex_);
    const double now = monitor_->Now();
    while (!delayed_.empty() && delayed_.front().due_s <= now) {
      own_copies_.insert(CopyKey(delayed_.front().channel, delayed_.front().bytes));
      due.push_back(std::move(delayed_.front()));
      delayed_.pop_front();
    }
  }
  for (const Delayed& d : due) lcm_->publish(d.channel, d.bytes.data(), static_cast<unsigned>(d.bytes.size()));
}

}  // namespace topay::tools
