#include "sim/scenarios/pick_place_scenario.h"

#include <optional>
#include <stdexcept>
#include <string>

#include "core/common/random.h"
#include "sim/scenarios/sensed_reachability.h"
#include "sim/scenarios/unseen_room.h"

namespace topay {
namespace {

constexpr std::uint64_t kGoalStream = 19;  // DeriveSeed index of the goals' generator

// The drop-off for `pickup`, or nullopt.
std::optional<TableTopGoal> DrawDropoff(const PickPlaceScenario& s, const TableTopGoalSampler& sampler,
                                        const Kinematics& kinematics, const PickPlaceScenarioOptions& options,
                                        Rng* rng) {
  const Eigen::Vector2d p_WB_pickup(s.pickup.state.x_m, s.pickup.state.y_m);
  const ProvenBaseRegion from_pickup = SensedReachableRegion(s.room.scene, kinematics, p_WB_pickup);
  TableTopGoalQuery query;
  query.reachable = &from_pickup;
  query.p_W_from_m = p_WB_pickup;
  query.min_base_distance_m = options.dropoff_distance_min_m;
  query.exclude_table_top = s.pickup.table_top;
  return sampler.Draw(query, rng);
}

}  // namespace

PickPlaceScenario MakePickPlaceScenario(const PickPlaceScenarioOptions& options, std::uint64_t seed,
                                        const Kinematics& kinematics) {
  CheckPickPlaceScenarioOptions(options, options.source.empty() ? "pick-and-place options" : options.source);
  PickPlaceScenario s;
  s.seed = seed;
  s.room = UnseenTablesRoom(seed, options.keep_out_radius_m);
  const TableTopGoalSampler sampler(s.room, kinematics, options);
  const ProvenBaseRegion from_start = SensedReachableRegion(s.room.scene, kinematics, s.p_W_start_m);
  TableTopGoalQuery pickup_query;
  pickup_query.reachable = &from_start;
  pickup_query.p_W_from_m = s.p_W_start_m;
  pickup_query.min_base_distance_m = options.pickup_distance_min_m;
  Rng rng(DeriveSeed(seed, kGoalStream));
  for (int k = 0; k < options.max_pickups; ++k) {
    const std::optional<TableTopGoal> pickup = sampler.Draw(pickup_query, &rng);
    if (!pickup) continue;
    s.pickup = *pickup;
    if (const std::optional<TableTopGoal> dropoff = DrawDropoff(s, sampler, kinematics, options, &rng)) {
      s.dropoff = *dropoff;
      return s;
    }
  }
  throw std::runtime_error("pick-and-place scenario: no pickup and drop-off found for seed " + std::to_string(seed) +
                           " in " + std::to_string(options.max_pickups) + " pickups of " +
                           std::to_string(options.max_targets) + " targets each");
}

}  // namespace topay
