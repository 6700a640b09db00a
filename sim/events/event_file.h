#pragma once
// Scripted world events from a YAML file (format: docs/simulator.md, example
// config/sim/events_example.yaml):
//
//   seed: 7                 # optional: seed of the jitter draws (else the simulator's seed)
//   events:
//     - name: crate drops in        # optional
//       at_s: 5.0                   # trigger: sim time, s ...
//       jitter_s: 0.5               # ... optionally + U[0, jitter_s) (seeded)
//       appear: {id: 1000, center: [2.0, 0.0, 0.5], size: [0.5, 0.5, 1.0], yaw: 0.0}
//     - near: {point: [3.0, 0.0], distance_m: 1.5}   # trigger: base within distance of point
//       disappear: {id: 3}
//
// Each event has exactly one trigger (at_s or near) and one action (appear or disappear);
// appear without center/size/yaw makes an existing box present again.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/events/sim_event.h"

namespace topay::sim {

struct EventScript {
  std::optional<std::uint64_t> seed;
  std::vector<SimEvent> events;
};

/// Reads an event file. Throws ConfigError("<path>", "events[2].appear.size", "...") for a
/// missing or malformed file, an unknown key, a missing or doubled trigger or action, a wrong
/// type, a non-finite number, a negative id, a non-positive size or distance, a negative time
/// or jitter.
EventScript LoadEventFile(const std::string& path);

/// The same from YAML text; `source` names the file in errors.
EventScript ParseEventScript(const std::string& text, const std::string& source);

}  // namespace topay::sim
