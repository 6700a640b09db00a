#include "core/planner/round_time.h"

namespace topay {

RoundClock::time_point RoundShareEnd(RoundClock::time_point now, RoundClock::time_point plan_end,
                                     double share) {
  // No limit: no share either; a share of 1: the plan's end itself.
  if (plan_end == RoundClock::time_point::max() || share >= 1.0) return plan_end;
  if (plan_end <= now) return now;
  return now + std::chrono::duration_cast<RoundClock::duration>((plan_end - now) * share);
}

bool RoundKeepsThePlanTime(RoundClock::time_point round_end, RoundClock::time_point plan_end,
                           double front_end_s, double min_time_left_s) {
  if (round_end >= plan_end) return false;  // the round already has the plan's time
  const std::chrono::duration<double> next_round_s(front_end_s + min_time_left_s);
  return plan_end - round_end < next_round_s;
}

}  // namespace topay
