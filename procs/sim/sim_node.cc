#include "procs/sim/sim_node.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "procs/sim/plant_checkpoint.h"
#include "procs/sim/sim_messages.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::simproc {
namespace {

bool Every(std::int64_t n) { return n <= 10 || n % 1000 == 0; }  // log the first 10, then every 1000th
constexpr int kCommandQueueCapacity = 1000;    // commands LCM keeps until handled: 5 s at 200 Hz
constexpr int kMaxMessagesBeforeSteps = 2000;  // handled before a plant wake-up runs its steps

}  // namespace

SimNode::SimNode(procs::ProcessLoop* loop, SimCore* core, const SimNodeOptions& options)
    : loop_(loop),
      core_(core),
      options_(options),
      pacer_(core->plant().step_s(), options.rate, options.max_catch_up_steps) {
  core_->SetListener(this);
  if (options.async_scans && core_->has_lidar()) {
    // The scan thread converts and publishes its clouds itself (a 100 kB message takes about a
    // millisecond to encode and send: not in the plant loop), on an LCM of its own.
    cloud_lcm_ = std::make_unique<lcm::LCM>(loop_->options().lcm_url);
    std::function<void(ScanResult&&)> publish;
    if (cloud_lcm_->good()) publish = [this](ScanResult&& scan) { OnScan(scan); };
    // In real time a scan thread that falls behind skips scans rather than queueing them.
    scan_worker_ = std::make_unique<ScanWorker>(core_->ReleaseScanSensor(), std::move(publish), options.rate > 0.0);
  }
  loop_->Subscribe<control_command_t>(std::string(channels::CONTROL_COMMAND),
                                      [this](const control_command_t& msg) { OnCommand(msg); })
      ->setQueueCapacity(kCommandQueueCapacity);
  if (options.actuator_input) {
    gripper_target_ = core_->plant().state().gripper;
    plant_state_every_steps_ =
        std::max<std::int64_t>(1, std::llround(1.0 / (options.plant_state_rate_hz * core_->plant().step_s())));
    // After a stall the commands of the whole stall are waiting (200 Hz, up to the pacer's
    // catch-up): keep them all for the timeline instead of LCM's 30.
    loop_->Subscribe<control_command_t>(std::string(channels::ACTUATOR_COMMAND),
                                        [this](const control_command_t& msg) { OnActuatorCommand(msg); })
        ->setQueueCapacity(kCommandQueueCapacity);
    loop_->Subscribe<gripper_command_t>(std::string(channels::GRIPPER_COMMAND),
                                        [this](const gripper_command_t& msg) { OnGripperCommand(msg); });
  }
  if (options.follow) {
    follower_ = std::make_unique<TrajectoryFollower>(core_->plant().model().num_joints(), options.follower);
    loop_->Subscribe<poly_trajectory_t>(std::string(channels::TRAJECTORY),
                                        [this](const poly_trajectory_t& msg) { OnTrajectory(msg); });
  }
  loop_->Subscribe<sim_event_t>(std::string(channels::SIM_EVENT), [this](const sim_event_t& msg) { OnSimEvent(msg); });
  loop_->AddScheduledTimer([this] { return OnPlantTimer(); });
  loop_->AddTimer(1.0 / options.status_rate_hz, [this] { OnStatusTimer(); });
  loop_->SetHealth(heartbeat_t::OK, "starting");
}

RealTimePacer::Clock::time_point SimNode::OnPlantTimer() {
  const auto now = RealTimePacer::Clock::now();
  if (!started_) {
    started_ = true;
    pacer_.Start(now);
    steps_at_start_ = core_->steps();
    start_utime_ = options_.start_utime > 0 ? options_.start_utime : procs::NowUtime() - std::llround(core_->time_s() * 1e6);
    last_status_wall_ = now;
    last_status_sim_s_ = core_->time_s();
    started_wall_ = now;
    started_sim_s_ = core_->time_s();
  }
  // What arrived while the process was not running (a stall) first: the commands among it are
  // due at the steps about to catch up (CommandTimeline).
  if (loop_->HandlePending(kMaxMessagesBeforeSteps) < 0) spdlog::error("LCM receive failed");
  const int due = pacer_.StepsDue(now, core_->steps() - steps_at_start_);
  KeepTheWallClock();
  for (int i = 0; i < due; ++i) {
    StepOnce();
    pacer_.RecordStep(RealTimePacer::Clock::now(), core_->steps() - steps_at_start_);
    if (options_.duration_s > 0.0 && core_->time_s() >= options_.duration_s - 1e-9) {
      loop_->Stop();
      stopping_ = true;
      break;
    }
  }
  if (scan_worker_) {
    if (options_.rate <= 0.0 || stopping_) scan_worker_->Drain();  // as fast as possible: scans keep pace
    for (const ScanResult& scan : scan_worker_->TakeCompleted()) OnScan(scan);
  }
  // As fast as possible: at once again (after the loop has handled what LCM has).
  return options_.rate > 0.0 ? pacer_.NextDue(core_->steps() - steps_at_start_) : RealTimePacer::Clock::now();
}

void SimNode::StepOnce() {
  if (!follower_) {
    ApplyDueCommands();
    core_->Step();
    if (options_.actuator_input && core_->steps() % plant_state_every_steps_ == 0) PublishPlantState();
    return;
  }
  const std::int64_t utime = SimUtime(start_utime_, core_->next_time_s());
  core_->StepTo(follower_->StateAt(utime, core_->plant().state()));
}

std::int64_t SimNode::NowSimUtime() const {
  if (started_) return SimUtime(start_utime_, core_->time_s());
  return options_.start_utime > 0 ? SimUtime(options_.start_utime, core_->time_s()) : procs::NowUtime();
}

void SimNode::OnTrajectory(const poly_trajectory_t& msg) {
  const std::string why = follower_->Accept(msg, NowSimUtime(), core_->plant().state());
  if (why.empty()) {
    spdlog::info("TRAJECTORY {} (goal {}) accepted: {} pieces, starts in {:.3f} s", msg.trajectory_id, msg.goal_id,
                 msg.num_pieces, static_cast<double>(msg.start_utime - NowSimUtime()) * 1e-6);
  } else if (Every(follower_->counts().rejected)) {
    spdlog::warn("rejected TRAJECTORY {} (#{}): {}; ignored", msg.trajectory_id,
                 follower_->counts().rejected, why);
  }
}

void SimNode::OnCommand(const control_command_t& msg) {
  if (follower_ || options_.actuator_input) {
    if (++commands_ignored_ == 1) {
      spdlog::info("{}: CONTROL_COMMAND ignored (counted)", follower_ ? "follow mode" : "CAN mode (ACTUATOR_COMMAND drives the plant)");
    }
    return;
  }
  Schedule(msg);
}

void SimNode::OnActuatorCommand(const control_command_t& msg) { Schedule(msg); }

void SimNode::Schedule(const control_command_t& msg) {
  const std::string why = commands_.Push(msg.utime, ToActuatorCommand(msg), NowSimUtime(), procs::NowUtime());
  if (!why.empty() && Every(++commands_dropped_)) {
    spdlog::warn("dropped {} (#{} dropped): {}", options_.actuator_input ? "ACTUATOR_COMMAND" : "CONTROL_COMMAND",
                 commands_dropped_, why);
  }
}

void SimNode::ApplyDueCommands() {
  commands_.TakeDue(SimUtime(start_utime_, core_->next_time_s()), &due_commands_);
  for (sim::ActuatorCommand& command : due_commands_) {
    // CAN mode: the gripper is not on the motors' bus; its target is GRIPPER_COMMAND's.
    if (options_.actuator_input) command.gripper = gripper_target_;
    const std::string why = core_->Command(command);
    if (!why.empty() && Every(core_->plant().counts().commands_rejected)) {
      spdlog::warn("rejected {} (#{} rejected: {}): the drives brake",
                   options_.actuator_input ? "ACTUATOR_COMMAND" : "CONTROL_COMMAND",
                   core_->plant().counts().commands_rejected, why);
    }
  }
}

void SimNode::OnGripperCommand(const gripper_command_t& msg) {
  const std::string why = core_->CommandGripper(msg.position);
  if (!why.empty()) {
    spdlog::warn("rejected GRIPPER_COMMAND from '{}': {}", msg.source, why);
    return;
  }
  gripper_target_ = msg.position;
}

void SimNode::PublishPlantState() {
  const std::int64_t utime = SimUtime(start_utime_, core_->time_s());
  const sim::MeasuredActuators measured = core_->plant().measured();
  const robot_state_t state = ToPlantStateMessage(core_->plant().state(), measured, utime, options_.joint_names);
  loop_->lcm().publish(std::string(channels::SIM_PLANT_STATE), &state);
  const joint_state_t gripper = ToGripperState(measured.gripper, utime);
  loop_->lcm().publish(std::string(channels::GRIPPER_STATE), &gripper);
  ++plant_states_published_;
}

void SimNode::OnSimEvent(const sim_event_t& msg) {
  std::string error;
  std::optional<sim::SimEvent> event = FromEventMessage(msg, &error);
  if (!event) {
    ++bad_events_;
    spdlog::warn("ignored SIM_EVENT '{}': {}", msg.name, error);
    return;
  }
  spdlog::info("SIM_EVENT queued: {}", sim::Describe(*event));
  core_->AddEvent(std::move(*event));
}

void SimNode::OnState(const StateSample& sample) {
  const robot_state_t state = ToRobotState(sample, start_utime_, options_.joint_names);
  if (!options_.actuator_input) loop_->lcm().publish(std::string(channels::ROBOT_STATE), &state);  // CAN mode: the estimator's
  loop_->lcm().publish(std::string(channels::BASE_POSE), &state.pose);
}

void SimNode::OnScan(const ScanResult& scan) {
  const point_cloud_t cloud = ToPointCloud(scan, start_utime_, options_.lidar_frame);
  lcm::LCM& lcm = cloud_lcm_ && cloud_lcm_->good() ? *cloud_lcm_ : loop_->lcm();
  lcm.publish(std::string(channels::POINT_CLOUD), &cloud);
  ++scans_published_;
}

void SimNode::KeepTheWallClock() {
  const std::int64_t slipped_us = std::llround(static_cast<double>(pacer_.slipped_steps()) * core_->plant().step_s() * 1e6);
  if (slipped_us == slipped_us_) return;
  // The process stalled longer than the pacer catches up: the world paused meanwhile, and its
  // clock (start + sim time) would stay behind the wall clock the other processes stamp with
  // for good (the estimator then took every BASE_POSE for too old and held the robot). The
  // stamps jump forward by the stall instead.
  start_utime_ += slipped_us - slipped_us_;
  spdlog::warn("the simulator stalled: {:.3f} s of sim time skipped to keep the wall clock ({:.3f} s in all, {} "
               "resets); the world paused meanwhile",
               1e-6 * static_cast<double>(slipped_us - slipped_us_), 1e-6 * static_cast<double>(slipped_us),
               pacer_.schedule_resets());
  slipped_us_ = slipped_us;
}

std::int64_t SimNode::ScansDropped() const { return scan_worker_ ? scan_worker_->dropped() : 0; }

void SimNode::ReportDroppedScans() {
  const std::int64_t dropped = ScansDropped();
  if (dropped == scans_dropped_reported_) return;
  scans_dropped_reported_ = dropped;
  if (Every(++scan_drop_reports_)) {
    spdlog::warn("the LiDAR thread fell behind (a loaded machine): {} scans dropped unscanned in all, so that the "
                 "published ones stay at most a scan time late",
                 dropped);
  }
}

void SimNode::OnScanDue(const WholeBodyState& state, double t_s) { scan_worker_->Request(state, t_s); }

void SimNode::OnWorldChanged(const std::vector<OrientedBox>& boxes) { scan_worker_->SetWorld(boxes); }

void SimNode::OnContact(const ContactResult& contact, int box_id) {
  const sim_contact_t msg = ToContactMessage(contact, box_id, start_utime_);
  loop_->lcm().publish(std::string(channels::SIM_CONTACT), &msg);
  // Self and chassis contacts involve no box (id -1): the body ("chassis: sphere 11 (link
  // link7)", "self: sphere 3 - sphere 9") names both parts.
  const std::string with = box_id < 0 ? "" : fmt::format(" with box {}", box_id);
  spdlog::error("CONTACT at t={:.3f} s: {}{}, depth {:.4f} m", contact.t_s, contact.body, with, contact.depth_m);
}

void SimNode::OnEvent(const sim::SimEvent& event, double t_s, const std::string& error) {
  if (error.empty()) {
    spdlog::info("event at t={:.3f} s: {} ({} boxes present)", t_s, sim::Describe(event), core_->world().num_present());
  } else {
    spdlog::warn("event at t={:.3f} s not applied: {}: {}", t_s, sim::Describe(event), error);
  }
}

void SimNode::OnStatusTimer() {
  if (!started_) return;
  const auto now = RealTimePacer::Clock::now();
  const double wall_s = std::chrono::duration<double>(now - last_status_wall_).count();
  const double sim_s = core_->time_s() - last_status_sim_s_;
  last_status_wall_ = now;
  last_status_sim_s_ = core_->time_s();
  const RealTimePacer::Lateness lateness = pacer_.TakeLateness();
  worst_p99_us_ = std::max(worst_p99_us_, lateness.p99_us);

  sim_status_t s{};
  s.utime = SimUtime(start_utime_, core_->time_s());
  s.sim_time_s = core_->time_s();
  s.real_time_factor = wall_s > 0.0 ? sim_s / wall_s : 0.0;
  s.target_rate = options_.rate;
  const sim::PlantCounts& plant = core_->plant().counts();
  s.plant_steps = plant.steps;
  s.late_steps = pacer_.late_steps();
  s.step_lateness_p99_us = lateness.p99_us;
  s.commands_accepted = plant.commands_accepted;
  s.commands_rejected = plant.commands_rejected;
  s.command_timeouts = plant.command_timeouts;
  if (const ContactSensor* monitor = core_->contact_sensor()) {
    const ContactCounts c = monitor->counts();
    s.contact_events = c.events;
    s.contact_steps = c.steps_in_contact;
    s.max_depth_m = c.max_depth_m;
    s.in_contact = monitor->active() > 0;
  }
  s.scans = core_->counts().scans - ScansDropped();
  ReportDroppedScans();
  s.events_applied = core_->counts().events_applied;
  s.boxes_present = core_->world().num_present();
  last_status_ = s;
  loop_->lcm().publish(std::string(channels::SIM_STATUS), &s);
  WriteCheckpoint(s.utime);

  const bool rejected = s.commands_rejected > 0 || (follower_ && follower_->counts().rejected > 0);
  const std::int8_t health = s.in_contact                         ? heartbeat_t::ERROR
                             : (s.contact_events > 0 || rejected) ? heartbeat_t::WARN
                                                                  : heartbeat_t::OK;
  loop_->SetHealth(health, fmt::format("t {:.1f} s, rtf {:.2f}, contacts {}{}, scans {}, {}, step p99 late {:.0f} us",
                                       s.sim_time_s, s.real_time_factor, s.contact_events,
                                       s.in_contact ? " (IN CONTACT)" : "", s.scans,
                                       follower_ ? FollowReport()
                                                 : fmt::format("commands {} (rejected {}, timeouts {})",
                                                               s.commands_accepted, s.commands_rejected,
                                                               s.command_timeouts),
                                       s.step_lateness_p99_us));
}

void SimNode::WriteCheckpoint(std::int64_t utime) {
  if (options_.checkpoint_file.empty()) return;
  const std::string error =
      WritePlantCheckpoint(options_.checkpoint_file, CheckpointOf(core_->plant().state(), utime));
  if (!error.empty() && ++checkpoint_failures_ == 1) spdlog::warn("plant checkpoint: {} (logged once)", error);
}

void SimNode::Finish() {
  if (!scan_worker_) return;
  scan_worker_->Drain();
  for (const ScanResult& scan : scan_worker_->TakeCompleted()) OnScan(scan);
}

std::string SimNode::FollowReport() const {
  const FollowerCounts& c = follower_->counts();
  const std::optional<std::int64_t> id = follower_->active_id();
  return fmt::format("follow: trajectories {} accepted / {} rejected / {} started (following {}), {} commands ignored",
                     c.accepted, c.rejected, c.started, id ? std::to_string(*id) : std::string("none"),
                     commands_ignored_);
}

std::string SimNode::FinalReport() const {
  const sim::PlantCounts& plant = core_->plant().counts();
  const RealTimePacer::Lateness lateness = pacer_.RunLateness();
  const double wall_s = std::chrono::duration<double>(RealTimePacer::Clock::now() - started_wall_).count();
  std::string text = fmt::format(
      "final: sim time {:.3f} s in {:.3f} s wall (real-time factor {:.3f}, target {}), plant steps {}\n"
      "final: step lateness p50 {:.0f} us, p99 {:.0f} us, max {:.0f} us over {} steps; late steps (> 1 period) {}, "
      "schedule resets {}\n"
      "final: commands {} accepted / {} rejected / {} timeouts, scans {} requested / {} published / {} dropped "
      "(the scan thread behind), events {} applied / {} failed / {} bad SIM_EVENT",
      core_->time_s(), wall_s, started_ ? (core_->time_s() - started_sim_s_) / wall_s : 0.0, options_.rate,
      plant.steps, lateness.p50_us, lateness.p99_us, lateness.max_us, lateness.count, pacer_.late_steps(),
      pacer_.schedule_resets(), plant.commands_accepted, plant.commands_rejected, plant.command_timeouts,
      core_->counts().scans, scans_published_.load(), ScansDropped(), core_->counts().events_applied, core_->counts().events_failed,
      bad_events_);
  if (follower_) text += "\nfinal: " + FollowReport();
  if (!follower_) text += "\nfinal: timeline: " + commands_.Report();
  if (options_.actuator_input) {
    text += fmt::format("\nfinal: CAN mode: {} SIM_PLANT_STATE published, {} CONTROL_COMMAND ignored",
                        plant_states_published_, commands_ignored_);
  }
  if (const ContactSensor* monitor = core_->contact_sensor()) {
    const ContactCounts c = monitor->counts();
    text += fmt::format("\nfinal: contacts {} events, {} of {} steps in contact, max depth {:.4f} m\n{}", c.events,
                        c.steps_in_contact, c.steps, c.max_depth_m, monitor->Report());
  } else {
    text += "\nfinal: no collision monitor";
  }
  return text;
}

}  // namespace topay::simproc
