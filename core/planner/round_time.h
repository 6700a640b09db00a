#pragma once

#include <chrono>

// The time of a plan's retry rounds (WholeBodyPlanner, PlanRetryOptions): a round that may be
// followed by another ends at its share of the time left, unless what would be left after it
// could not hold another round.

namespace topay {

using RoundClock = std::chrono::steady_clock;  ///< The planner's clock (Stopwatch::Clock).

/// The end of a round that may be followed by another: `share` (in (0, 1]) of the time from
/// `now` to `plan_end`. No limit (plan_end = max) or a share of 1 gives plan_end; a plan_end
/// already past, `now`.
RoundClock::time_point RoundShareEnd(RoundClock::time_point now, RoundClock::time_point plan_end,
                                     double share);

/// Decided once a round's front end is done: true when the time from `round_end` (its share's
/// end) to `plan_end` is shorter than another round would need, taken as a front end as long as
/// this one's (front_end_s) plus min_time_left_s to optimize. The round then keeps the plan's
/// time: cutting its optimization would leave only a round that cannot finish.
bool RoundKeepsThePlanTime(RoundClock::time_point round_end, RoundClock::time_point plan_end,
                           double front_end_s, double min_time_left_s);

}  // namespace topay
