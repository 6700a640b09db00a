#pragma once
// The simulator core's ContactSensor over sim/monitor's CollisionMonitor.

#include "core/robot/kinematics.h"
#include "procs/sim/sim_sensors.h"
#include "sim/monitor/collision_monitor.h"

namespace topay::simproc {

class MonitorAdapter : public ContactSensor {
 public:
  explicit MonitorAdapter(const Kinematics& kinematics, const sim::CollisionMonitorOptions& options = {})
      : monitor_(kinematics, options) {}
  void SetWorld(const std::vector<OrientedBox>& boxes) override { monitor_.SetWorld(boxes); }
  std::vector<ContactResult> Check(const WholeBodyState& state, double t_s) override;
  int active() const override { return static_cast<int>(monitor_.active().size()); }
  ContactCounts counts() const override;
  std::string Report() const override { return monitor_.Report(); }

 private:
  sim::CollisionMonitor monitor_;
};

}  // namespace topay::simproc
