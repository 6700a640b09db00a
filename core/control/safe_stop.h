#pragma once

#include "core/control/control_command.h"
#include "core/control/nmpc_options.h"
#include "core/control/tracker_limits.h"

namespace topay {

/// What the tracker does this cycle.
enum class TrackerMode {
  kTrack,               ///< Solve the NMPC against the reference.
  kStopNoReference,     ///< No trajectory: decelerate to a stop.
  kStopReferenceEnded,  ///< The trajectory ended (plus end_settle_s): decelerate to a stop.
  kStopStaleState,      ///< The robot state is older than stale_state_s: decelerate to a stop.
};

const char* TrackerModeName(TrackerMode mode);

/// What ChooseTrackerMode looks at.
struct TrackerSituation {
  bool has_reference = false;
  double t_along_s = 0.0;             ///< Time along the reference (now - its start).
  double reference_duration_s = 0.0;
  double state_age_s = 0.0;           ///< Now - the robot state's time.
};

/// Pure logic: a stale (or future-dated by more than stale_state_s, or NaN) state first,
/// then no reference, then an ended one (t_along > duration + end_settle_s), else track.
TrackerMode ChooseTrackerMode(const TrackerSituation& situation, const NmpcOptions& options);

/// One step of the stop: every input moved towards zero by at most its acceleration limit
/// times dt_s (a_max, beta_max, qdd_max), never past zero. Magnitudes only shrink, so a last
/// command within the speed and coupled limits stays within them. *next sized like last.
void StopStep(const ControlCommand& last, double dt_s, const TrackerLimits& limits,
              ControlCommand* next);

/// The stop as a sequence: column k = StopStep applied k + 1 times from `last` (dt_s apart).
/// Sized by the caller (InputSequence::Zero); zero once every input has stopped.
void StopSequence(const ControlCommand& last, double dt_s, const TrackerLimits& limits,
                  InputSequence* sequence);

/// Time the stop from `last` takes at the acceleration limits: the largest of |v| / a_max,
/// |omega| / beta_max and |qd_j| / qdd_max,j.
double StopDurationS(const ControlCommand& last, const TrackerLimits& limits);

}  // namespace topay
