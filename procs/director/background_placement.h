#pragma once
// One box placement (PlaceRouteBox) on a worker thread, so that topay-director's loop goes on
// (heartbeats, the robot's states) while it checks the room: each draw is a flood fill over
// the room (~0.08 s on an idle 2-core machine for a 20 m Tables room, seconds for 20 draws on
// a loaded one), and a loop blocked for 4 s is a dead process to the launcher (finding 31,
// docs/reliability.md).

#include <cstddef>
#include <cstdint>
#include <future>
#include <optional>

#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "sim/scenarios/route_box.h"

namespace topay::director {

/// What the route was when an attempt started: the result is for that trajectory and event.
struct PlacementTag {
  std::int64_t trajectory_id = 0;
  std::size_t event_index = 0;  ///< The director's event (its script's order).
};

struct PlacementResult {
  PlacementTag tag;
  std::optional<RouteBox> box;  ///< nullopt: every draw was rejected.
  Rng rng;                      ///< The generator after the attempt's draws.
};

/// At most one attempt at a time. Not thread-safe itself: one thread (the loop) calls it.
class BackgroundPlacement {
 public:
  BackgroundPlacement() = default;
  BackgroundPlacement(const BackgroundPlacement&) = delete;
  BackgroundPlacement& operator=(const BackgroundPlacement&) = delete;
  /// Waits for a running attempt (a few seconds at most) and drops its result.
  ~BackgroundPlacement();

  /// Starts PlaceRouteBox on copies of `route`, `scene` and `rng` (the generator's draws go on
  /// from its state and come back in the result). The kinematics must outlive the attempt;
  /// they are only read. Throws std::logic_error if an attempt is running or not yet taken.
  void Start(const PlacementTag& tag, const RouteQuery& route, const Scene& scene, const Kinematics& kinematics,
             const RouteBoxOptions& options, const Rng& rng);
  /// An attempt started and its result not yet taken.
  bool busy() const { return future_.valid(); }
  /// The finished attempt's result (once); nullopt while it runs or if none started. An
  /// exception of the attempt (options out of range) is rethrown here.
  std::optional<PlacementResult> TakeIfDone();
  /// Blocks until the running attempt (if any) is done; for tests.
  void Wait() const;

 private:
  std::future<PlacementResult> future_;
};

}  // namespace topay::director
