#pragma once
// The base pose estimator: an EKF on SE(2) (state X_WB = (x m, y m, yaw rad), covariance P_WB
// 3 x 3) predicted with wheel odometry (se2_motion.h) and updated with localisation poses
// (pose_update.h), with a history for delayed inputs and outlier gating. docs/estimator.md.
//
// Events. Every accepted input is an event in a time-ordered ring (EventRing, allocated once):
// an odometry sample (t, v, omega) or a pose (t, z). The state after each event is stored with
// it. Applying an event at t to the state before it: predict from the previous event's time to
// t with the odometry in effect (zero-order hold of the latest odometry sample at or before the
// previous event; none yet: v = omega = 0, the diffusion only), then
//   odometry: the new (v, omega) holds from t on;
//   pose: not initialised -> X = z, P = R (initialise); else gate on m2 = nu^T S^-1 nu:
//         m2 <= gate_chi2 -> update; else rejected, and after reinit_after_rejections
//         consecutive rejections X = z, P = R (re-initialise).
// An input stamped before the newest event (a delayed pose; odometry behind a pose) is inserted
// at its time and every later event is re-applied from the stored state before it, so the
// result equals in-order processing exactly. Each stream must be strictly increasing in time
// (else rejected, counted); inputs older than max_delay_s behind the newest event or than the
// oldest event kept are rejected as too old. Non-finite inputs are rejected. Allocation-free
// after construction.

#include <cstdint>

#include <Eigen/Core>

#include "core/estimation/estimator_options.h"
#include "core/estimation/estimator_summary.h"
#include "core/estimation/event_ring.h"

namespace topay {

/// What became of one input.
enum class EstimatorInput : std::int8_t {
  kApplied,            ///< taken in at the newest time
  kAppliedDelayed,     ///< taken in before the newest event (history replayed)
  kRejectedNotFinite,  ///< NaN or infinite value
  kRejectedOutOfOrder, ///< stamp not after the previous one of its stream
  kRejectedTooOld,     ///< older than the history
};
const char* EstimatorInputName(EstimatorInput input);

/// What a pose event did to the filter.
enum class PoseOutcome : std::int8_t { kNone, kInitialised, kAccepted, kGated, kReinitialised };
const char* PoseOutcomeName(PoseOutcome outcome);

/// The filter's state at one time.
struct EstimatorBelief {
  std::int64_t t_us = 0;                                  ///< time of validity, us
  Eigen::Vector3d X_WB = Eigen::Vector3d::Zero();          ///< (x m, y m, yaw rad)
  Eigen::Matrix3d P_WB = Eigen::Matrix3d::Identity();      ///< covariance (m^2, m rad, rad^2)
  bool initialised = false;                                ///< a pose has been taken
  int consecutive_rejections = 0;                          ///< gated poses in a row
  double v_mps = 0.0, omega_radps = 0.0;                   ///< odometry in effect from t_us on
  bool has_odometry = false;
};

/// The estimate at a requested time.
struct PoseEstimate {
  std::int64_t t_us = 0;
  Eigen::Vector3d X_WB = Eigen::Vector3d::Zero();
  Eigen::Matrix3d P_WB = Eigen::Matrix3d::Identity();
};

class Se2Estimator {
 public:
  /// Throws std::invalid_argument if options.Check() does.
  explicit Se2Estimator(const EstimatorOptions& options);

  /// Wheel odometry at t_us: forward speed and yaw rate of B, in B.
  EstimatorInput AddOdometry(std::int64_t t_us, double v_mps, double omega_radps);
  /// A localisation pose z = (x m, y m, yaw rad) valid at t_us.
  EstimatorInput AddPose(std::int64_t t_us, const Eigen::Vector3d& z_WB);
  /// Forgets the history and starts from (X_WB, P_WB) at t_us (initialised); the odometry in
  /// effect and the streams' last stamps are kept.
  void Reset(std::int64_t t_us, const Eigen::Vector3d& X_WB, const Eigen::Matrix3d& P_WB);

  /// The estimate predicted to t_us from the newest event with the odometry in effect (not
  /// moved back if t_us is before it). False if not initialised.
  bool EstimateAt(std::int64_t t_us, PoseEstimate* estimate) const;

  bool initialised() const { return Newest().initialised; }
  /// The state after the newest event.
  const EstimatorBelief& Newest() const;
  /// What the latest pose input did (kNone if it was rejected before the filter).
  PoseOutcome last_pose_outcome() const { return last_pose_outcome_; }
  const EstimatorSummary& summary() const { return summary_; }
  const EstimatorOptions& options() const { return options_; }
  int history_size() const { return events_.size(); }

 private:
  enum class Kind : std::int8_t { kOdometry, kPose };
  struct Event {
    std::int64_t t_us = 0;
    Kind kind = Kind::kOdometry;
    Eigen::Vector3d value = Eigen::Vector3d::Zero();  // (v, omega, 0) or z_WB
    EstimatorBelief after;
    PoseOutcome outcome = PoseOutcome::kNone;
    double mahalanobis2 = 0.0;
  };

  EstimatorInput Insert(const Event& event);
  void Apply(const EstimatorBelief& before, Event* event) const;
  void ApplyPose(Event* event, EstimatorBelief* belief) const;
  void Propagate(std::int64_t t_us, EstimatorBelief* belief) const;
  void Count(const Event& event, int sign);

  EstimatorOptions options_;
  Eigen::Matrix3d R_;
  EventRing<Event> events_;
  EstimatorBelief base_;  // the state before the oldest event kept
  std::int64_t last_odometry_t_us_ = 0;
  std::int64_t last_pose_t_us_ = 0;
  bool any_odometry_ = false, any_pose_ = false;
  PoseOutcome last_pose_outcome_ = PoseOutcome::kNone;
  EstimatorSummary summary_;
};

}  // namespace topay
