#pragma once
// topay-sim on the bus: paces a SimCore in real time (or faster, or as fast as possible) on the
// process loop's timers, feeds it CONTROL_COMMAND and SIM_EVENT, publishes ROBOT_STATE,
// BASE_POSE, POINT_CLOUD, SIM_CONTACT as the core produces them and SIM_STATUS at the status
// rate, and keeps the heartbeat's health: ERROR while in contact, WARN after a contact or a
// rejected command or trajectory, else OK. With `follow` (topay-sim --follow) the plant follows
// TRAJECTORY exactly (TrajectoryFollower) instead of integrating CONTROL_COMMAND (ignored,
// counted); everything else runs as without.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "procs/runtime/process_loop.h"
#include "procs/sim/command_timeline.h"
#include "procs/sim/real_time_pacer.h"
#include "procs/sim/scan_worker.h"
#include "procs/sim/sim_core.h"
#include "procs/sim/trajectory_follower.h"
#include "topay/control_command_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/sim_event_t.hpp"
#include "topay/sim_status_t.hpp"

namespace topay::simproc {

struct SimNodeOptions {
  std::int64_t start_utime = 0;     ///< utime of sim time 0 (0: the wall clock when stepping starts)
  double rate = 1.0;                ///< real-time factor (0: as fast as possible)
  int max_catch_up_steps = 500;
  double status_rate_hz = 10.0;     ///< SIM_STATUS and the health, Hz (wall)
  double duration_s = 0.0;          ///< stop after this much sim time (0: run until stopped)
  std::string lidar_frame = "lidar";
  bool async_scans = true;          ///< scan on a thread of its own (ScanWorker) instead of in the plant loop
  std::vector<std::string> joint_names;
  bool follow = false;              ///< follow TRAJECTORY (TrajectoryFollower) instead of CONTROL_COMMAND
  TrajectoryFollowerOptions follower;
  /// The CAN mode (plant_input: actuators): base and joints from ACTUATOR_COMMAND (topay-motorsim),
  /// the gripper from GRIPPER_COMMAND; SIM_PLANT_STATE and GRIPPER_STATE at plant_state_rate_hz,
  /// BASE_POSE as always, no ROBOT_STATE; CONTROL_COMMAND ignored (counted).
  bool actuator_input = false;
  double plant_state_rate_hz = 250.0;
  /// The plant's checkpoint, written every status period (procs/sim/plant_checkpoint.h); "" = none.
  std::string checkpoint_file;
};

class SimNode : public SimListener {
 public:
  /// Subscribes and adds the timers to *loop (call before loop->Run()). loop and core outlive it.
  SimNode(procs::ProcessLoop* loop, SimCore* core, const SimNodeOptions& options);

  /// The status now (real_time_factor over the last status period).
  sim_status_t Status() const { return last_status_; }
  /// Publishes the scans still being made (call after the loop ends).
  void Finish();
  /// The final counts, printed on exit.
  std::string FinalReport() const;
  std::int64_t start_utime() const { return start_utime_; }

  void OnState(const StateSample& sample) override;
  void OnScan(const ScanResult& scan) override;
  void OnScanDue(const WholeBodyState& state, double t_s) override;
  void OnWorldChanged(const std::vector<OrientedBox>& boxes) override;
  void OnContact(const ContactResult& contact, int box_id) override;
  void OnEvent(const sim::SimEvent& event, double t_s, const std::string& error) override;

 private:
  /// Runs the steps due; returns when the next one is due.
  RealTimePacer::Clock::time_point OnPlantTimer();
  void OnStatusTimer();
  /// Moves the stamps' origin forward by what the pacer skipped (a stall): the sim's clock stays the wall clock.
  void KeepTheWallClock();
  std::int64_t ScansDropped() const;
  void ReportDroppedScans();  // a warning when the scan thread dropped scans since the last one
  /// The plant's checkpoint (options_.checkpoint_file), if one is kept.
  void WriteCheckpoint(std::int64_t utime);
  /// One plant step: to the follower's state at the step's time (follow), else Step.
  void StepOnce();
  /// utime of the sim's clock now (before the first step: of the time stepping will start).
  std::int64_t NowSimUtime() const;
  void OnCommand(const control_command_t& msg);
  /// Keeps a command for the step of its stamp (CommandTimeline).
  void Schedule(const control_command_t& msg);
  /// Hands the commands due at the next step to the plant.
  void ApplyDueCommands();
  void OnActuatorCommand(const control_command_t& msg);
  void OnGripperCommand(const gripper_command_t& msg);
  /// CAN mode: SIM_PLANT_STATE and GRIPPER_STATE when due after a step.
  void PublishPlantState();
  void OnTrajectory(const poly_trajectory_t& msg);
  std::string FollowReport() const;
  void OnSimEvent(const sim_event_t& msg);

  procs::ProcessLoop* loop_;
  SimCore* core_;
  SimNodeOptions options_;
  RealTimePacer pacer_;
  RealTimePacer::Clock::time_point started_wall_{};
  double started_sim_s_ = 0.0;
  bool started_ = false;
  bool stopping_ = false;
  // utime of sim time 0; read by the LiDAR's thread too (its clouds' stamps), moved by KeepTheWallClock.
  std::atomic<std::int64_t> start_utime_{0};
  std::int64_t slipped_us_ = 0;  // the pacer's skipped time, already added to start_utime_
  std::int64_t steps_at_start_ = 0;
  std::int64_t bad_events_ = 0;
  std::unique_ptr<TrajectoryFollower> follower_;  // follow mode only
  std::int64_t commands_ignored_ = 0;             // CONTROL_COMMANDs in follow mode or CAN mode
  CommandTimeline commands_;                      // the plant's commands (CONTROL_ or ACTUATOR_COMMAND) on their own time
  std::vector<sim::ActuatorCommand> due_commands_;
  std::int64_t commands_dropped_ = 0;             // out of order (CommandTimeline)
  double gripper_target_ = 0.0;                   // CAN mode: the latest GRIPPER_COMMAND
  std::int64_t plant_state_every_steps_ = 1;      // CAN mode: SIM_PLANT_STATE period in plant steps
  std::int64_t plant_states_published_ = 0;
  std::atomic<std::int64_t> scans_published_{0};
  std::int64_t checkpoint_failures_ = 0;
  std::int64_t scans_dropped_reported_ = 0;  // the scan thread's drops at the last warning
  std::int64_t scan_drop_reports_ = 0;
  // Status period bookkeeping.
  RealTimePacer::Clock::time_point last_status_wall_{};
  double last_status_sim_s_ = 0.0;
  sim_status_t last_status_{};
  double worst_p99_us_ = 0.0;
  // Last: the LiDAR's thread is joined (finishing its jobs, which use the members above)
  // before anything else is destroyed.
  std::unique_ptr<lcm::LCM> cloud_lcm_;       // async_scans: the LiDAR thread's own LCM (publishes POINT_CLOUD)
  std::unique_ptr<ScanWorker> scan_worker_;  // async_scans: the LiDAR's thread (declared after cloud_lcm_)
};

}  // namespace topay::simproc
