#include "procs/sim/sim_core.h"

#include <algorithm>
#include <cmath>

#include "core/common/random.h"
#include "sim/events/apply_event.h"

namespace topay::simproc {
namespace {

std::int64_t Every(double rate_hz, double step_s) {
  return std::max<std::int64_t>(1, std::llround(1.0 / (rate_hz * step_s)));
}

}  // namespace

SimCore::SimCore(const RobotModel& model, const SimCoreOptions& options, const Scene& scene,
                 std::vector<sim::SimEvent> scripted_events, std::unique_ptr<ScanSensor> scan,
                 std::unique_ptr<ContactSensor> contact)
    : plant_(model, options.plant, DeriveSeed(options.seed, 1)),
      world_(scene),
      events_(std::move(scripted_events), options.event_seed),
      pose_sensor_(options.pose_noise, DeriveSeed(options.seed, 2)),
      scan_(std::move(scan)),
      contact_(std::move(contact)),
      state_every_steps_(Every(options.state_rate_hz, options.plant.step_s)),
      scan_every_steps_(scan_ ? Every(scan_->rate_hz(), options.plant.step_s) : 1) {
  SyncWorld();
}

std::unique_ptr<ScanSensor> SimCore::ReleaseScanSensor() {
  if (!scan_) return nullptr;
  scan_released_ = true;
  return std::move(scan_);
}

void SimCore::SyncWorld() {
  if (world_.version() == world_version_seen_) return;
  world_version_seen_ = world_.version();
  if (scan_) scan_->SetWorld(world_.present_boxes());
  if (scan_released_ && listener_ != nullptr) listener_->OnWorldChanged(world_.present_boxes());
  if (contact_) contact_->SetWorld(world_.present_boxes());
}

void SimCore::Step() {
  plant_.Step();
  AfterPlantStep();
}

void SimCore::StepTo(const sim::PlantState& target) {
  plant_.StepTo(target);
  AfterPlantStep();
}

void SimCore::AfterPlantStep() {
  const double t_s = plant_.time_s();
  const WholeBodyState& state = plant_.state().state;

  for (const sim::SimEvent& event : events_.Poll(t_s, Eigen::Vector2d(state.x_m, state.y_m))) {
    const std::string error = sim::ApplyEvent(event, &world_);
    ++(error.empty() ? counts_.events_applied : counts_.events_failed);
    if (listener_ != nullptr) listener_->OnEvent(event, t_s, error);
  }
  SyncWorld();

  if (contact_) {
    for (const ContactResult& contact : contact_->Check(state, t_s)) {
      const int box_id = contact.box_index < 0 ? -1 : world_.IdOfPresentIndex(contact.box_index);
      if (listener_ != nullptr) listener_->OnContact(contact, box_id);
    }
  }

  const std::int64_t k = plant_.step_count();
  if (k % state_every_steps_ == 0) {
    StateSample sample;
    sample.t_s = t_s;
    sample.truth = plant_.state();
    sample.measured = plant_.measured();
    sample.pose = pose_sensor_.Measure({state.x_m, state.y_m, state.yaw_rad});
    if (listener_ != nullptr) listener_->OnState(sample);
  }
  if ((scan_ || scan_released_) && k % scan_every_steps_ == 0) {
    ++counts_.scans;
    if (scan_) {
      const ScanResult scan = scan_->Scan(state, t_s);
      if (listener_ != nullptr) listener_->OnScan(scan);
    } else if (listener_ != nullptr) {
      listener_->OnScanDue(state, t_s);
    }
  }
}

}  // namespace topay::simproc
