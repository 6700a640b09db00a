#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/collision/scene_clearance.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of the exact zones (ExactZones): where the planner trusts the exact geometry over
/// the distance fields.
struct ExactZoneOptions {
  /// A state lies in a zone when its base position is at most this far (m) from the zone's
  /// centre (a start's or a goal's base position). 1 m: a base of radius 0.4 m standing
  /// partly under a table top drives clear of its projection within it.
  double radius_m = 1.0;
  /// Exact clearances a state in a zone needs (SceneClearance::IsCollisionFree): the
  /// planner sets them to its validator's, so a state accepted here passes the validator.
  double obstacle_margin_m = 0.0;
  double self_margin_m = 0.0;
};

/// Throws std::invalid_argument naming the first option out of range (radius finite and
/// >= 0, margins finite and >= 0 for the obstacle one, finite for the self one).
void CheckExactZoneOptions(const ExactZoneOptions& options);

/// The neighbourhoods of a start and a goal that the fields reject although the exact scene
/// accepts them (the fields are conservative: the 2D field projects floating obstacles over
/// the arm's rigid shoulder, the 3D field has its exactness margin). In a zone, a state the
/// fields reject is checked again exactly (WholeBodyValidity::Check), so the planner can plan
/// out of such a start and into such a goal; outside every zone the fields alone decide.
/// Empty (no centre, or no checker): the fields alone decide everywhere.
/// The checker (and its scene) must outlive this object.
struct ExactZones {
  const SceneClearanceChecker* checker = nullptr;
  ExactZoneOptions options;
  std::vector<Eigen::Vector2d> centres_W_m;  ///< Base positions (x, y) of the zones.

  bool empty() const { return checker == nullptr || centres_W_m.empty(); }
  /// True if p_WB is within options.radius_m of a centre.
  bool Contains(const Eigen::Vector2d& p_WB) const;
  bool Contains(const WholeBodyState& state) const {
    return Contains(Eigen::Vector2d(state.x_m, state.y_m));
  }
};

}  // namespace topay
