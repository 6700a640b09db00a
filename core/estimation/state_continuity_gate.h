#pragma once
// The continuity gate on a stream of whole-body state estimates (ROBOT_STATE as each consumer
// takes it: planner, tracker, mapper, mission, director; docs/reliability.md finding 9). A
// state is taken only if it continues the last state taken: stamped later, by at most
// max_gap_s, and reached from it within the robot's speed limits (plus a slack for estimate
// noise). Anything else (an older or repeated stamp, a jump) is refused, so a stray or
// corrupted message cannot move the robot's state. The stream may jump for a real reason (the
// estimator re-initialised, the simulator restarted, a log replay started over): refused states
// are followed as candidate streams (kCandidateStreams, the least recently extended replaced),
// and the newest state of a candidate stream `reanchor_after` states long becomes the new
// anchor. Stray states interleaved with such a stream start candidates of their own, so they
// neither block it nor ever re-anchor (they do not continue each other). Pure: no clock, the
// stamps alone.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "core/robot/whole_body_state.h"

namespace topay {

struct StateContinuityGateOptions {
  /// Fastest base motion believed, m/s (the robot: v_max 1.0 m/s, config/robot/topay_mm.yaml; twice for noise). > 0.
  double max_speed_mps = 2.0;
  /// Fastest yaw rate believed, rad/s (the robot: omega_max 0.9 rad/s). > 0.
  double max_yaw_rate_radps = 4.0;
  /// Fastest joint rate believed, rad/s (the arm: 2.35 rad/s, the URDF). > 0.
  double max_joint_rate_radps = 4.0;
  /// Allowed on top of speed x dt: base position (m), yaw (rad), each joint (rad). >= 0.
  double slack_position_m = 0.1;
  double slack_yaw_rad = 0.1;
  double slack_joint_rad = 0.1;
  /// A state stamped more than this after the last one taken does not continue it (s): a
  /// stamp pushed far ahead cannot block the stream. > 0.
  double max_gap_s = 1.0;
  /// The length of a candidate stream of refused states (each continuing the one before) that
  /// becomes the new anchor. At 100 Hz, 5 = 50 ms. >= 1.
  int reanchor_after = 5;

  /// Throws std::invalid_argument naming the first field out of range.
  void Check() const;
};

/// What the gate did with one state.
enum class ContinuityVerdict : std::int8_t {
  kTaken,          ///< continues the anchor (or the first state): the new anchor
  kReanchored,     ///< completes a candidate stream of reanchor_after refused states
  kRefusedStale,   ///< stamped at or before the anchor
  kRefusedGap,     ///< stamped more than max_gap_s after the anchor
  kRefusedJump,    ///< moved farther than the limits allow since the anchor
  kRefusedJoints,  ///< a different joint count from the anchor's
  kRefusedNotFinite,
};
const char* ContinuityVerdictName(ContinuityVerdict verdict);
inline bool Taken(ContinuityVerdict v) { return v == ContinuityVerdict::kTaken || v == ContinuityVerdict::kReanchored; }

struct StateContinuityGateSummary {
  std::int64_t taken = 0;
  std::int64_t reanchored = 0;
  std::int64_t refused_stale = 0;
  std::int64_t refused_gap = 0;
  std::int64_t refused_jump = 0;
  std::int64_t refused_joints = 0;
  std::int64_t refused_not_finite = 0;
  std::int64_t refused() const;
};
/// "1234 taken, 1 re-anchored; refused: 3 stale, 0 gap, 2 jump, 0 joints, 0 not finite".
std::string FormatStateContinuitySummary(const StateContinuityGateSummary& summary);

class StateContinuityGate {
 public:
  /// Candidate streams followed at once (more than the stray states expected between two states
  /// of a real stream).
  static constexpr int kCandidateStreams = 8;

  /// Throws std::invalid_argument for bad options.
  explicit StateContinuityGate(const StateContinuityGateOptions& options = {});

  /// Judges the state stamped t_us (us). A taken state becomes the anchor.
  ContinuityVerdict Check(std::int64_t t_us, const WholeBodyState& state);
  /// The last refusal's reason in words (e.g. "moved 3.2 m in 0.010 s, at most 0.12 m"), "" if
  /// the last state was taken.
  const std::string& last_reason() const { return last_reason_; }
  const StateContinuityGateSummary& summary() const { return summary_; }

 private:
  struct Stamped {
    std::int64_t t_us = 0;
    WholeBodyState state;
  };
  struct Candidate {
    Stamped newest;
    int length = 0;                 // 0: unused
    std::int64_t last_extended = 0; // the gate's message counter when it last grew
  };
  // Whether `next` continues `from`; otherwise the verdict and *reason.
  std::optional<ContinuityVerdict> Discontinuity(const Stamped& from, const Stamped& next, std::string* reason) const;
  // A refused state: extends the candidate stream it continues (or starts one); a stream that
  // reaches reanchor_after becomes the anchor.
  ContinuityVerdict Refuse(ContinuityVerdict verdict, const Stamped& next);
  Candidate* Extended(const Stamped& next);
  void Count(ContinuityVerdict verdict);

  StateContinuityGateOptions options_;
  std::optional<Stamped> anchor_;
  std::array<Candidate, kCandidateStreams> candidates_{};
  std::int64_t messages_ = 0;
  std::string last_reason_;
  StateContinuityGateSummary summary_;
};

}  // namespace topay
