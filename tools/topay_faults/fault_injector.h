#pragma once
// Injects one fault of the catalogue into the running graph and clears it again: kill -9 of a
// graph process, MOTORSIM_FAULT requests, nftables rules in the graph's private network
// namespace, and messages the tool publishes itself (goals, delayed copies, hostile payloads).
// Begin() starts the fault, Tick() keeps a lasting one going (floods, bursts, an operator's
// FAULT_RESET), End() clears it; what was done is in Notes().

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "fault_catalog.h"
#include "graph_monitor.h"

namespace lcm {
class LCM;
}

namespace topay::tools {

struct FaultInjectorOptions {
  std::string lcm_url;         ///< the graph's bus (publishing)
  int lcm_port = 7667;         ///< its UDP port (the nftables rules match it)
  std::string work_dir;        ///< where rule files and nft's output go
  pid_t graph_ancestor = 0;    ///< the graph's processes descend from it (this tool)
  Eigen::Vector3d room_min_m = Eigen::Vector3d::Zero();  ///< the room's extent (random goals)
  Eigen::Vector3d room_max_m = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> box_centers_m;            ///< goals inside obstacles
  std::uint64_t seed = 1;      ///< random goals, payloads, drives
};

class FaultInjector {
 public:
  /// Throws std::runtime_error naming the URL if it cannot publish on the bus.
  FaultInjector(const FaultInjectorOptions& options, GraphMonitor* monitor);
  ~FaultInjector();

  /// Starts `fault` now. Returns false (Notes() says why) if it could not be injected (e.g.
  /// the process to kill is not running).
  bool Begin(const FaultSpec& fault);
  /// Keeps a lasting fault going; call often (every 1 ms for the 1 kHz flood).
  void Tick();
  /// Clears the fault (rules removed, MOTORSIM_FAULT CLEAR, copies stopped). Idempotent.
  void End();
  /// Sends FAULT_RESET on DRIVE_COMMAND (as an operator would).
  void SendFaultReset();
  const std::string& Notes() const { return notes_; }
  /// The pid killed by a kKill fault (0 otherwise).
  pid_t KilledPid() const { return killed_pid_; }

 private:
  bool BeginKill(const FaultSpec& fault);
  bool BeginCan(const FaultSpec& fault);
  bool BeginLcm(const FaultSpec& fault);
  bool BeginGoal(const FaultSpec& fault);
  void SendMotorsimFault(int kind, int joint, double duration_s, double value, int code);
  bool ApplyRules(const std::string& rules);
  void RemoveRules();
  void PublishGoal(const Eigen::Vector3d& p_WE, double yaw_rad);
  // The robot's base position in the simulator's last BASE_POSE on the bus (nullopt: none or bad).
  std::optional<Eigen::Vector2d> RobotPosition() const;
  Eigen::Vector3d RandomPointInRoom();
  void SendHostilePayloads(int step);
  void SendDelayedCopies();

  FaultInjectorOptions options_;
  GraphMonitor* monitor_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::mt19937_64 random_;
  FaultSpec fault_;
  bool active_ = false;
  double begin_s_ = 0.0;
  double last_tick_action_s_ = -1.0;
  int tick_actions_ = 0;
  int hostile_sent_ = 0;
  bool rules_applied_ = false;
  pid_t killed_pid_ = 0;
  std::string notes_;
  std::int64_t next_goal_id_ = 900000000;
  struct Delayed {
    double due_s;
    std::string channel;
    std::vector<std::uint8_t> bytes;
  };
  std::mutex delayed_mutex_;            // guards active_, reordering_, delayed_, own_copies_
  bool reordering_ = false;
  std::deque<Delayed> delayed_;
  std::unordered_multiset<std::size_t> own_copies_;
};

}  // namespace topay::tools
