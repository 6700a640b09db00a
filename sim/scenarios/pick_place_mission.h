#pragma once
// The pick-and-place scenario as a topay-mission task list (procs/mission/mission_spec.h,
// docs/mission.md).

#include <string>

#include "sim/scenarios/pick_place_options.h"
#include "sim/scenarios/pick_place_scenario.h"

namespace topay {

/// The mission YAML text (name pick_and_place): goto `pickup` (position_m, quat_wxyz of the
/// goal's X_WE, its state as the hint), gripper close, goto `dropoff` (likewise), gripper
/// open, wait options.wait_s, home. Numbers in shortest round-trip form: loading the text
/// gives back the goals' doubles.
std::string PickPlaceMissionYaml(const PickPlaceScenario& scenario, const PickPlaceScenarioOptions& options);

}  // namespace topay
