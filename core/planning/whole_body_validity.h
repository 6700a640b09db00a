#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/collision/scene_clearance.h"
#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/planning/exact_zones.h"
#include "core/robot/kinematics.h"
#include "core/robot/self_collision.h"
#include "core/robot/whole_body_state.h"

namespace topay {

/// Options of WholeBodyValidity.
struct WholeBodyValidityOptions {
  /// Clearance (m) the base cylinder needs beyond its radius on the 2D base field:
  /// field2(p_WB) >= radius + base_margin_m. Unset: the field's exactness_margin_m(), the
  /// largest amount by which the interpolated field can exceed the exact 2D distance
  /// (sqrt(2) x the cell size for an EDT field, proof in whole_body_validity.cc; cell size /
  /// sqrt(2) for exact footprint distances), so a field-valid base is exactly clear.
  std::optional<double> base_margin_m;
  /// Same for every arm sphere on the 3D field: field3(p_WS) >= r_S + arm_margin_m.
  /// Unset: the 3D field's exactness_margin_m() (same proof in 3D: sqrt(3) x the cell size
  /// for an EDT field, sqrt(3) / 2 x it for exact box distances, BuildBoxDistanceField).
  std::optional<double> arm_margin_m;
  /// Self-collision: every self pair distance and every chassis margin must exceed this (m).
  /// Exact (no field). Note the TopAY arm's lowest sphere sits a constant 5 mm above the
  /// chassis top, so values >= 0.005 reject every state.
  double self_margin_m = 0.0;
  /// Edge interpolation: consecutive checked states differ by at most this much in base
  /// position (m) and in yaw and every joint (rad). Defaults: 1 cm and 0.01 rad.
  double max_edge_step_m = 0.01;
  double max_edge_step_rad = 0.01;
};

/// Throws std::invalid_argument naming the first option out of range (margins, when set,
/// finite and >= 0; self_margin_m finite; edge steps > 0). The WholeBodyValidity constructor
/// calls it; the planner YAML loader too.
void CheckWholeBodyValidityOptions(const WholeBodyValidityOptions& options);

/// Why a state is invalid.
enum class ValidityFailure {
  kNone,
  kMalformed,      ///< Wrong joint count or a non-finite value.
  kJointLimit,     ///< A joint outside [q_min, q_max].
  kBaseCollision,  ///< Base cylinder too close on the 2D field.
  kArmCollision,   ///< An arm sphere too close on the 3D field.
  kSelfCollision,  ///< A self-collision pair too close.
  kChassis,        ///< An arm sphere not above the chassis top.
  /// In an exact zone (ExactZones): the fields rejected the state and the exact scene too.
  kExactCollision,
};
std::string_view ToString(ValidityFailure failure);

/// Buffers for allocation-free checks; one per thread (WholeBodyValidity::MakeWorkspace).
struct WholeBodyValidityWorkspace {
  KinematicsCache cache;
  Eigen::VectorXd pair_distances_m;
  Eigen::VectorXd chassis_margins_m;
  WholeBodyState interpolated;
  /// For the exact checks in exact zones; made on first use.
  std::optional<SceneClearanceWorkspace> exact;
};

/// The planner's whole-body validity test on the distance fields (the optimizer's view of the
/// world): joint limits, base cylinder on the 2D base field, arm spheres on the 3D field,
/// self-collision pairs and arm above the chassis (core/robot/self_collision.h). With the
/// default margins a valid state is also clear of the exact scene boxes
/// (core/collision/scene_clearance.h) whose rasterisation made the fields, for every robot
/// part at least half a cell inside the fields' volume (beyond it the fields assume free
/// space) and with the fields' default zero level (SignedDistanceFieldOptions).
/// With exact zones (WithExactZones): a state whose base lies in a zone and that the fields
/// reject for its base or an arm sphere is checked again against the exact scene (base
/// cylinder and every sphere at the zones' margins, self and chassis as below), and is valid
/// if that passes; in a zone the base is always checked (check_base only skips it outside
/// the zones), since the exact check must then cover the rigid spheres the 2D field stands
/// for.
/// Const methods are thread-safe given one workspace per thread. The kinematics (and model)
/// and both fields must outlive this object.
class WholeBodyValidity {
 public:
  /// Throws std::invalid_argument for a negative or non-finite margin or a non-positive edge
  /// step.
  WholeBodyValidity(const Kinematics& kinematics, const SignedDistanceField2& base_field,
                    const SignedDistanceField3& arm_field,
                    const WholeBodyValidityOptions& options = {});

  WholeBodyValidityWorkspace MakeWorkspace() const;

  /// A copy that also accepts states the exact scene accepts in `zones` (see the class
  /// comment). Throws std::invalid_argument for bad zone options.
  WholeBodyValidity WithExactZones(ExactZones zones) const;
  const ExactZones& exact_zones() const { return zones_; }

  const Kinematics& kinematics() const { return kinematics_; }
  const RobotModel& model() const { return kinematics_.model(); }
  double base_margin_m() const { return base_margin_m_; }
  double arm_margin_m() const { return arm_margin_m_; }
  /// The spheres checked on the 3D field: all but the rigid ones the base field covers
  /// (SpheresToCheckOnArmField), which pass whenever the base passes the 2D check.
  const std::vector<int>& arm_field_spheres() const { return arm_field_spheres_; }
  const WholeBodyValidityOptions& options() const { return options_; }

  /// First failing check of `state` (kNone if valid). Never throws.
  ValidityFailure Check(const WholeBodyState& state, WholeBodyValidityWorkspace* workspace,
                        bool check_base = true) const;
  bool IsValid(const WholeBodyState& state, WholeBodyValidityWorkspace* workspace) const {
    return Check(state, workspace) == ValidityFailure::kNone;
  }
  /// Check on the fields alone, ignoring the exact zones.
  ValidityFailure CheckOnFields(const WholeBodyState& state, WholeBodyValidityWorkspace* workspace,
                                bool check_base = true) const;
  /// The base cylinder alone at p_WB on the 2D field; in an exact zone, where the field
  /// rejects it, its exact clearance (base band boxes) above the zones' obstacle margin.
  bool IsBaseValid(const Eigen::Vector2d& p_WB) const;
  /// The base cylinder alone on the 2D field (no zones).
  bool IsBaseValidOnField(const Eigen::Vector2d& p_WB) const;

  /// Checks the straight segment from a to b (linear in x, y, yaw and q; yaw not wrapped) at
  /// EdgeSteps(a, b) + 1 evenly spaced states, a and b included. With check_base = false the
  /// base cylinder is skipped (for callers that checked the base path once already).
  ValidityFailure CheckEdge(const WholeBodyState& a, const WholeBodyState& b,
                            WholeBodyValidityWorkspace* workspace, bool check_base = true) const;
  bool IsEdgeValid(const WholeBodyState& a, const WholeBodyState& b,
                   WholeBodyValidityWorkspace* workspace) const {
    return CheckEdge(a, b, workspace) == ValidityFailure::kNone;
  }

  /// Number of interpolation intervals of the edge a -> b under this object's step options.
  int EdgeSteps(const WholeBodyState& a, const WholeBodyState& b) const {
    return EdgeInterpolationSteps(a, b, options_.max_edge_step_m, options_.max_edge_step_rad);
  }

  /// Intervals n >= 1 such that consecutive states of the linear interpolation a -> b differ
  /// by at most max_step_m in base position and max_step_rad in yaw and each joint.
  static int EdgeInterpolationSteps(const WholeBodyState& a, const WholeBodyState& b,
                                    double max_step_m, double max_step_rad);
  /// The state at fraction s in [0, 1] of the linear interpolation a -> b, into *out
  /// (allocation-free once out->q_rad has the right size).
  static void Interpolate(const WholeBodyState& a, const WholeBodyState& b, double s,
                          WholeBodyState* out);

 private:
  const Kinematics& kinematics_;
  const SignedDistanceField2& base_field_;
  const SignedDistanceField3& arm_field_;
  SelfCollision self_collision_;
  WholeBodyValidityOptions options_;
  std::vector<int> arm_field_spheres_;
  double base_margin_m_ = 0.0;
  double arm_margin_m_ = 0.0;
  ExactZones zones_;
};

}  // namespace topay
