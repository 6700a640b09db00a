#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <stop_token>
#include <vector>

#include "core/planning/base_free_space.h"

namespace topay {

/// Options of BuildVisibilityPrm (defaults: the authors' code's front-end
/// figures).
struct VisibilityPrmOptions {
  /// Samples are drawn uniformly in a rectangle centred between start and goal,
  /// its long axis along goal - start, with half-length |goal - start| / 2 +
  /// sample_margin_length_m ...
  double sample_margin_length_m = 1.5;
  /// ... and half-width sample_half_width_m. Samples outside the field's grid
  /// are discarded.
  double sample_half_width_m = 4.0;
  /// Stop after this many samples (free or not) ...
  int max_samples = 5000;
  /// ... or after this much wall-clock time (steady clock), whichever comes
  /// first. <= 0: no time limit (then a seed fully determines the graph).
  double max_time_s = 0.010;
  /// Seed of the topay::Rng that draws the samples.
  std::uint64_t seed = 1;
  /// UVD resolution (m) of the connector equivalence test (see
  /// uvd_equivalence.h); <= 0: the field's cell size.
  double uvd_resolution_m = 0.0;
};

/// A node of the visibility roadmap.
struct PrmNode {
  enum class Kind { kGuard, kConnector };
  Eigen::Vector2d p_W_m = Eigen::Vector2d::Zero();
  Kind kind = Kind::kGuard;
  std::vector<int> neighbors;  ///< Indices into VisibilityPrmGraph::nodes (undirected edges).
};

/// The roadmap: node 0 is the start, node 1 the goal (both guards). Every edge
/// joins a guard and a connector and is a free segment.
struct VisibilityPrmGraph {
  std::vector<PrmNode> nodes;
  int num_guards = 0;
  int num_connectors = 0;
  int num_samples = 0;  ///< Samples drawn (free or not).
  int num_free_samples = 0;
  bool cancelled = false;       ///< The stop token was triggered during sampling.
  bool time_limit_hit = false;  ///< Sampling stopped on max_time_s rather than max_samples.
};

/// Visibility PRM with guards and connectors (Simeon, Laumond, Nissoux 2000,
/// with the topology-preserving connector rule of topological PRM, Zhou et al.
/// 2020):
/// - a free sample that sees no guard becomes a new guard;
/// - a free sample that sees exactly two guards g1, g2 becomes a connector
/// between them,
///   unless a connector c of g1 and g2 already exists whose path g1-c-g2 is
///   UVD-equivalent to g1-sample-g2: then the shorter of the two is kept (c is
///   moved to the sample if shorter);
/// - other samples are dropped.
/// Start and goal must be free (the caller checks). The stop token is polled
/// every sample.
VisibilityPrmGraph BuildVisibilityPrm(const BaseFreeSpace& free_space,
                                      const Eigen::Vector2d& start_W_m,
                                      const Eigen::Vector2d& goal_W_m,
                                      const VisibilityPrmOptions& options,
                                      std::stop_token stop = {});

/// Removes (in place) nodes other than start and goal that have fewer than two
/// neighbours, repeatedly: they cannot lie on a simple start-goal path. Node
/// indices are compacted; start and goal stay 0 and 1.
void PruneDeadEnds(VisibilityPrmGraph* graph);

}  // namespace topay
