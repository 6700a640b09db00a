#pragma once
// The paper's pick-and-place task in a seeded Tables room the robot has never seen (issue 19's
// demo): from the start (the origin), reach a pickup pose above one table top, deliver to a
// drop-off pose above another across the room, return to the start.

#include <cstdint>

#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "sim/scenarios/pick_place_options.h"
#include "sim/scenarios/table_top_goal.h"
#include "sim/scenes/generated_scene.h"

namespace topay {

struct PickPlaceScenario {
  std::uint64_t seed = 0;
  GeneratedScene room;       ///< UnseenTablesRoom(seed, keep_out_radius_m): what topay-sim runs
  Eigen::Vector2d p_W_start_m = Eigen::Vector2d::Zero();  ///< where the simulator puts the base
  TableTopGoal pickup;
  TableTopGoal dropoff;
};

/// The scenario of `seed`: the room, then from Rng(DeriveSeed(seed, 19)) up to max_pickups
/// pickup goals (TableTopGoalSampler: base reached from the start through passages
/// kSensedPassageClearanceM wider than the robot, at least pickup_distance_min_m from it), each
/// followed by a drop-off search (another table top, base at least dropoff_distance_min_m from
/// the pickup's and reached from it likewise); the first pair found. Deterministic: same
/// options, seed and robot, same scenario. Throws ConfigError for bad options
/// (CheckPickPlaceScenarioOptions), std::runtime_error naming the seed if the room cannot be
/// made or no pair is found.
PickPlaceScenario MakePickPlaceScenario(const PickPlaceScenarioOptions& options, std::uint64_t seed,
                                        const Kinematics& kinematics);

}  // namespace topay
