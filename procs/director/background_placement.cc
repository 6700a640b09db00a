#include "procs/director/background_placement.h"

#include <chrono>
#include <stdexcept>
#include <utility>

namespace topay::director {

BackgroundPlacement::~BackgroundPlacement() { Wait(); }

void BackgroundPlacement::Start(const PlacementTag& tag, const RouteQuery& route, const Scene& scene,
                                const Kinematics& kinematics, const RouteBoxOptions& options, const Rng& rng) {
  if (busy()) throw std::logic_error("BackgroundPlacement::Start: an attempt is still running or not taken");
  future_ = std::async(std::launch::async, [tag, route, scene, &kinematics, options, rng]() mutable {
    PlacementResult result{tag, std::nullopt, rng};
    result.box = PlaceRouteBox(route, scene, kinematics, options, &result.rng);
    return result;
  });
}

std::optional<PlacementResult> BackgroundPlacement::TakeIfDone() {
  if (!busy() || future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  return future_.get();
}

void BackgroundPlacement::Wait() const {
  if (busy()) future_.wait();
}

}  // namespace topay::director
