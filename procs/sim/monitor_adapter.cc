#include "procs/sim/monitor_adapter.h"

#include <cmath>

namespace topay::simproc {

std::vector<ContactResult> MonitorAdapter::Check(const WholeBodyState& state, double t_s) {
  std::vector<ContactResult> out;
  for (const sim::Contact& c : monitor_.Check(state, t_s)) out.push_back({c.t_s, c.body, c.box, c.depth_m});
  return out;
}

ContactCounts MonitorAdapter::counts() const {
  const sim::CollisionMonitor::Counts& c = monitor_.counts();
  ContactCounts r;
  r.events = c.events;
  r.steps_in_contact = c.steps_in_contact;
  r.steps = c.steps;
  r.max_depth_m = c.max_depth_m;
  r.first_contact_t_s = std::isnan(c.first_contact_t_s) ? -1.0 : c.first_contact_t_s;
  return r;
}

}  // namespace topay::simproc
