#pragma once
// The actuator lag of one drive channel: a first-order system y' = (u - y) / tau, discretised
// exactly for a fixed step (zero-order hold on u): y[k+1] = y[k] + (1 - exp(-dt / tau)) (u - y[k]).
// The response to a step of u from y0 is y(t) = u + (y0 - u) exp(-t / tau) at every step time.

namespace topay::sim {

class FirstOrderLag {
 public:
  /// tau_s <= 0: no lag (y follows u at once). dt_s > 0.
  FirstOrderLag(double tau_s, double dt_s);

  double Next(double y, double u) const { return y + alpha_ * (u - y); }
  /// The fraction of the gap closed per step, 1 - exp(-dt / tau).
  double alpha() const { return alpha_; }

 private:
  double alpha_;
};

/// `to`, moved no further than max_change from `from` (the rate limit of a drive).
double LimitChange(double from, double to, double max_change);

}  // namespace topay::sim
