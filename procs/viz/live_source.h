#pragma once
// The live graph as the viewer's source: every LCM channel (the regex ".*") handed raw to the
// VizFeed with its receive time. topay-viz never publishes anything but its heartbeat.

#include <lcm/lcm-cpp.hpp>

#include "procs/viz/viz_feed.h"

namespace topay::viz {

/// Subscribes `feed` to every channel of `lcm` (the subscription lives as long as `lcm`).
/// Returns the subscription; its LCM queue keeps `queue_capacity` messages not yet handled (a
/// burst beyond that is dropped by LCM, never blocking the senders).
lcm::Subscription* SubscribeAllChannels(lcm::LCM* lcm, VizFeed* feed, int queue_capacity = 200);

}  // namespace topay::viz
