#pragma once
// topay-faults' view of a running graph: every LCM message of the graph's bus is received on a
// thread of its own and stamped on the steady clock on receipt; what the fault episodes need is
// kept (the bridge's state changes, whether the drives are commanded to move, the last command,
// the mission's state, ground-truth contacts, heartbeats) with the last raw message of every
// channel (for hostile copies and reordering). Times are seconds on the monitor's clock.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "braking_run.h"

namespace lcm {
class LCM;
struct ReceiveBuffer;
}

namespace topay::tools {

/// One change of the bridge's state (DRIVE_STATUS), as received.
struct DriveStateChange {
  double time_s = 0.0;
  int state = -1;           ///< drive_status_t state constant
  std::string stop_reason;  ///< the bridge's reason ("" when running)
};

/// One change of the planner's goal or state (PLANNER_STATUS), as received.
struct PlannerStatusChange {
  double time_s = 0.0;
  std::int64_t goal_id = 0;
  int state = -1;              ///< planner_status_t state constant
  std::string failure_reason;  ///< FAILED: why
};

/// What the monitor has seen so far (a copy: consistent at one instant).
struct GraphView {
  double now_s = 0.0;
  double last_control_command_s = -1.0;   ///< CONTROL_COMMAND receipt (-1: none yet)
  double last_actuator_s = -1.0;          ///< ACTUATOR_COMMAND receipt
  bool actuator_zero = true;              ///< the last ACTUATOR_COMMAND commands every axis to 0
  double actuator_zero_since_s = -1.0;    ///< receipt of the first of the current run of zero commands
  /// Receipt of the first of the current run of ACTUATOR_COMMANDs in which every axis is at 0 or
  /// smaller than in the one before (the drives braking: their own stop ramps); -1 when the last
  /// one was not such a command.
  double actuator_braking_since_s = -1.0;
  double last_moving_s = -1.0;            ///< last ACTUATOR_COMMAND with an axis above the moving threshold
  int drive_state = -1;                   ///< the bridge's last state (-1: no DRIVE_STATUS yet)
  double last_drive_status_s = -1.0;
  std::vector<DriveStateChange> drive_changes;  ///< every change of state or stop reason
  int mission_state = -1;                 ///< mission_status_t state (-1: none yet)
  int mission_step = -1;
  std::int64_t mission_goal_id = 0;
  std::string mission_detail;
  double last_mission_status_s = -1.0;
  /// Every change of the planner's goal or state, the last kMaxPlannerChanges: a refusal the
  /// next goal's status followed within a poll is still seen (the last status alone hid one).
  std::vector<PlannerStatusChange> planner_changes;
  static constexpr std::size_t kMaxPlannerChanges = 64;
  /// The goal of the planner's last status (0: none yet).
  std::int64_t planner_goal_id() const { return planner_changes.empty() ? 0 : planner_changes.back().goal_id; }
  std::int64_t contacts = 0;              ///< SIM_CONTACT messages that decode (contact starts)
  bool tracker_held = false;              ///< the last TRACKER_STATUS was HELD
  std::vector<double> tracker_held_starts_s;  ///< receipts of a TRACKER_STATUS HELD after one that was not
  std::map<std::string, double> heartbeat_s;      ///< process name -> last HEARTBEAT receipt
  std::map<std::string, int> heartbeat_pid;       ///< process name -> pid in its last HEARTBEAT
  std::int64_t messages = 0;              ///< every message received
};

/// A copy of every received message, for injectors that re-send traffic (reordering).
using MessageTap = std::function<void(const std::string& channel, const std::vector<std::uint8_t>& bytes, double time_s)>;

class GraphMonitor {
 public:
  /// Joins the graph's bus (`lcm_url`; call inside the graph's private network namespace).
  /// Throws std::runtime_error naming the URL if LCM cannot be initialised.
  explicit GraphMonitor(const std::string& lcm_url);
  ~GraphMonitor();
  GraphMonitor(const GraphMonitor&) = delete;
  GraphMonitor& operator=(const GraphMonitor&) = delete;

  double Now() const;
  GraphView View() const;
  /// The last message received on `channel` (empty: none yet).
  std::vector<std::uint8_t> LastMessage(const std::string& channel) const;
  /// Channels seen so far.
  std::vector<std::string> Channels() const;
  /// Forgets what belongs to one mission (bridge changes, mission, planner, contacts).
  void Reset();
  /// Calls `tap` (on the monitor's thread) with every message from now on; nullptr: none.
  void SetTap(MessageTap tap);

  /// An axis of ACTUATOR_COMMAND at or above this (m/s, rad/s) counts as moving.
  static constexpr double kMovingThreshold = 0.02;
  /// Every axis below this counts as commanded to zero.
  static constexpr double kZeroThreshold = 1e-3;

 private:
  // LCM's untyped subscription calls a member of a handler object.
  struct RawHandler {
    GraphMonitor* self;
    void On(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  };

  void Run();
  void OnMessage(const std::string& channel, const std::uint8_t* data, std::size_t size);

  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<RawHandler> raw_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  GraphView view_;
  std::map<std::string, std::vector<std::uint8_t>> last_;
  BrakingRun braking_{kZeroThreshold};  // over ACTUATOR_COMMAND (under mutex_)
  std::vector<double> axes_;            // its scratch
  std::mutex tap_mutex_;  // held while the tap runs: SetTap(nullptr) returns only once it is not running
  MessageTap tap_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace topay::tools
