#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <stop_token>
#include <vector>

#include "core/planning/visibility_prm.h"

namespace topay {

/// Options of EnumerateRawPaths.
struct RawPathEnumerationOptions {
  int max_raw_paths = 300;    ///< DFS stops after this many start-goal paths.
  int keep_fewest_hops = 25;  ///< Of those, keep this many with the fewest edges.
  /// Safety cap on DFS node expansions (dense graphs have exponentially many
  /// simple paths).
  std::int64_t max_expansions = 2'000'000;
};

/// What EnumerateRawPaths found.
struct RawPathEnumeration {
  std::vector<std::vector<Eigen::Vector2d>> paths_W_m;  ///< Fewest hops first (stable).
  int num_found = 0;  ///< Simple paths found by the DFS (<= max_raw_paths).
  bool expansion_cap_hit = false;
  bool cancelled = false;
};

/// Depth-first enumeration of simple paths from node 0 (start) to node 1 (goal)
/// of the roadmap, up to max_raw_paths, then a stable sort by hop count keeping
/// keep_fewest_hops. Deterministic for a given graph. The stop token is polled
/// every 1024 expansions.
RawPathEnumeration EnumerateRawPaths(const VisibilityPrmGraph& graph,
                                     const RawPathEnumerationOptions& options,
                                     std::stop_token stop = {});

}  // namespace topay
