#pragma once
// Whether the drives are stopping: a run of ACTUATOR_COMMANDs (what the drives drive) in which
// every axis is at zero or smaller in magnitude than in the message before, i.e. every device is
// on its own stop ramp (the wheel controller's quick stop, the arm drives' fault reaction) or
// stopped. The start of such a run is when the robot began to be commanded to stop, which a
// fault's safe state is timed by; the run reaching all zeros is when the stop ended.

#include <vector>

namespace topay::tools {

class BrakingRun {
 public:
  /// `zero_threshold`: an axis below this (m/s, rad/s) counts as at zero.
  explicit BrakingRun(double zero_threshold) : zero_threshold_(zero_threshold) {}

  /// The next message's axes (v, omega, the joint rates; signs do not matter) received at
  /// time_s. Returns the start of the current run (its first message's time), -1 when this
  /// message ended it or none has begun (the first message has nothing to compare with).
  double Add(const std::vector<double>& axes, double time_s);

 private:
  double zero_threshold_;
  std::vector<double> previous_abs_;
  double since_s_ = -1.0;
};

}  // namespace topay::tools
