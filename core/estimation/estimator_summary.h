#pragma once
// What the base pose estimator counted (Se2Estimator::summary()): the process's heartbeat and
// exit report print it.

#include <cstdint>
#include <string>

namespace topay {

struct EstimatorSummary {
  std::int64_t odometry_applied = 0;       ///< odometry samples taken into the history
  std::int64_t odometry_not_finite = 0;    ///< rejected: NaN or infinite v or omega
  std::int64_t odometry_out_of_order = 0;  ///< rejected: stamp not after the previous odometry's
  std::int64_t odometry_too_old = 0;       ///< rejected: older than the history (max_delay_s)
  std::int64_t poses_not_finite = 0;       ///< rejected: NaN or infinite x, y or yaw
  std::int64_t poses_out_of_order = 0;     ///< rejected: stamp not after the previous pose's
  std::int64_t poses_too_old = 0;          ///< rejected: older than the history (max_delay_s)
  // The outcome of every pose in the history (a replay after a delayed input may change an
  // outcome; the counts follow it).
  std::int64_t poses_initialised = 0;      ///< the first pose (the filter starts from it)
  std::int64_t poses_accepted = 0;         ///< passed the gate, applied
  std::int64_t poses_gated = 0;            ///< rejected by the Mahalanobis gate
  std::int64_t reinitialisations = 0;      ///< poses adopted after reinit_after_rejections rejections
  std::int64_t delayed_inputs = 0;         ///< inputs stamped before the newest event (history replayed)
  std::int64_t replayed_events = 0;        ///< events re-applied after them
  double last_mahalanobis2 = 0.0;          ///< squared Mahalanobis distance of the latest pose
};

/// One line: "odometry N (bad B), poses A accepted, G gated, R reinit, ...".
std::string FormatEstimatorSummary(const EstimatorSummary& summary);

}  // namespace topay
