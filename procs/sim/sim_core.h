#pragma once
// The simulator without a bus or a clock: the world, the plant, the scripted and run-time
// events, the localisation, the LiDAR and the collision monitor, advanced one plant step at a
// time. Its outputs (state at the state rate, scans at the LiDAR rate, every new contact, every
// applied event) go to a SimListener. topay-sim (sim_node.h) paces it in real time and wires
// it to LCM; tests and the lockstep replay (command_replay.h) step it directly.
//
// Deterministic: the same model, options, scene, events and commands given at the same steps
// give the same outputs bit for bit (no clock, no threads, seeded random draws).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/scene.h"
#include "core/robot/robot_model.h"
#include "procs/sim/sim_sensors.h"
#include "sim/events/event_scheduler.h"
#include "sim/localization/pose_sensor.h"
#include "sim/plant/plant.h"
#include "sim/world/sim_world.h"

namespace topay::simproc {

/// One state output: the truth, what the drives measure, what the localisation reports.
struct StateSample {
  double t_s = 0.0;
  sim::PlantState truth;
  sim::MeasuredActuators measured;
  sim::PlanarPose pose;  ///< localisation (truth + bias + noise)
};

class SimListener {
 public:
  virtual ~SimListener() = default;
  virtual void OnState(const StateSample& sample) {}
  virtual void OnScan(const ScanResult& scan) {}
  /// Only after ReleaseScanSensor: a scan is due now of this state (the caller scans it).
  virtual void OnScanDue(const WholeBodyState& state, double t_s) {}
  /// Only after ReleaseScanSensor: the world's present boxes changed (the caller's scanner
  /// must see them before the next OnScanDue).
  virtual void OnWorldChanged(const std::vector<OrientedBox>& boxes) {}
  /// box_id: the world's stable id of the box (-1: self collision).
  virtual void OnContact(const ContactResult& contact, int box_id) {}
  /// error empty: applied; else why it was not (the world is unchanged).
  virtual void OnEvent(const sim::SimEvent& event, double t_s, const std::string& error) {}
};

struct SimCoreOptions {
  sim::PlantOptions plant;
  double state_rate_hz = 100.0;
  sim::PoseNoiseOptions pose_noise;
  std::uint64_t seed = 1;        ///< master seed (plant, localisation; the sensors get theirs from the caller)
  std::uint64_t event_seed = 1;  ///< seed of the event jitter
};

struct SimCounts {
  std::int64_t scans = 0;
  std::int64_t events_applied = 0;
  std::int64_t events_failed = 0;
};

class SimCore {
 public:
  /// `model` must outlive the core. `scan` and `contact` may be null (no LiDAR / no monitor).
  SimCore(const RobotModel& model, const SimCoreOptions& options, const Scene& scene,
          std::vector<sim::SimEvent> scripted_events, std::unique_ptr<ScanSensor> scan,
          std::unique_ptr<ContactSensor> contact);

  void SetListener(SimListener* listener) { listener_ = listener; }

  /// A command to the actuators now (at the current step); "" or why it was rejected.
  std::string Command(const sim::ActuatorCommand& command) { return plant_.Command(command); }
  /// A gripper target alone now (CAN mode: GRIPPER_COMMAND); "" or why it was rejected.
  std::string CommandGripper(double target) { return plant_.CommandGripper(target); }
  /// A run-time event (SIM_EVENT), checked at the next steps.
  void AddEvent(sim::SimEvent event) { events_.Add(std::move(event)); }

  /// One plant step, then due events, the monitor, and the outputs due at the new time.
  void Step();
  /// One plant step to `target` (Plant::StepTo: the ideal follower), then as Step.
  void StepTo(const sim::PlantState& target);
  /// The time the next step reaches, s.
  double next_time_s() const { return static_cast<double>(plant_.step_count() + 1) * plant_.step_s(); }

  double time_s() const { return plant_.time_s(); }
  std::int64_t steps() const { return plant_.step_count(); }
  const sim::Plant& plant() const { return plant_; }
  const sim::SimWorld& world() const { return world_; }
  const sim::EventScheduler& events() const { return events_; }
  const SimCounts& counts() const { return counts_; }
  /// The monitor (null if none).
  const ContactSensor* contact_sensor() const { return contact_.get(); }
  /// Plant steps between two scans (0: no LiDAR).
  std::int64_t steps_per_scan() const { return has_lidar() ? scan_every_steps_ : 0; }
  bool has_lidar() const { return scan_ != nullptr || scan_released_; }
  /// Hands the LiDAR to the caller (e.g. a ScanWorker thread; it has seen the current world):
  /// from now on the core reports OnScanDue and OnWorldChanged instead of scanning, and
  /// counts the scans it asked for. Null if there is no LiDAR.
  std::unique_ptr<ScanSensor> ReleaseScanSensor();

 private:
  void SyncWorld();
  /// After the plant step: due events, the monitor, the outputs.
  void AfterPlantStep();

  sim::Plant plant_;
  sim::SimWorld world_;
  sim::EventScheduler events_;
  sim::PoseSensor pose_sensor_;
  std::unique_ptr<ScanSensor> scan_;
  std::unique_ptr<ContactSensor> contact_;
  SimListener* listener_ = nullptr;
  std::int64_t state_every_steps_;
  std::int64_t scan_every_steps_;
  std::int64_t world_version_seen_ = -1;
  bool scan_released_ = false;
  SimCounts counts_;
};

}  // namespace topay::simproc
