#include "sim/scenes/tight_task_generator.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/geometry/primitive_box_distance.h"
#include "core/planning/base_reachability.h"
#include "sim/scenes/quantize.h"
#include "sim/scenes/task_sampling.h"

namespace topay {
namespace {

void Require(bool condition, const std::string& option, const std::string& message) {
  if (!condition) {
    throw std::invalid_argument("tight task generator option " + option + ": " + message);
  }
}

void CheckTightOptions(const TaskGeneratorOptions& o) {
  Require(std::isfinite(o.tight_clearance_max_m) && o.tight_clearance_max_m > o.obstacle_margin_m,
          "tight_clearance_max_m", "must be finite and above obstacle_margin_m");
  Require(std::isfinite(o.tight_base_spread_m) && o.tight_base_spread_m >= 0.0,
          "tight_base_spread_m", "must be finite and >= 0");
  Require(std::isfinite(o.tight_pocket_window_m) && o.tight_pocket_window_m >= 0.0,
          "tight_pocket_window_m", "must be finite and >= 0");
  Require(std::isfinite(o.tight_passage_clearance_m) && o.tight_passage_clearance_m >= 0.0,
          "tight_passage_clearance_m", "must be finite and >= 0");
  Require(std::isfinite(o.tight_approach_radius_m) && o.tight_approach_radius_m >= 0.0,
          "tight_approach_radius_m", "must be finite and >= 0");
  Require(o.tight_arm_tries > 0 && o.max_tight_base_tries > 0 && o.max_tight_pair_tries > 0,
          "tight_arm_tries/max_tight_base_tries/max_tight_pair_tries", "must be positive");
  Require(o.table_goal_fraction >= 0.0 && o.table_goal_fraction <= 1.0, "table_goal_fraction",
          "must be in [0, 1]");
  Require(std::isfinite(o.on_table_height_min_m) && std::isfinite(o.on_table_height_max_m) &&
              0.0 <= o.on_table_height_min_m && o.on_table_height_min_m <= o.on_table_height_max_m,
          "on_table_height_min_m/max_m", "need 0 <= min <= max");
}

// A box the base of a tight end is drawn near, and how far from its centre (xy) a drawn base
// position can be: the half diagonal of its grown footprint.
struct Anchor {
  int box = -1;
  double reach_m = 0.0;
};

// Draws the tight ends of one task; holds the checker and the candidate anchors.
class TightEndSampler {
 public:
  TightEndSampler(const GeneratedScene& scene, DistanceRange range, const Kinematics& kinematics,
                  const TaskGeneratorOptions& options, Rng* rng)
      : scene_(scene.scene),
        kinematics_(kinematics),
        options_(options),
        rng_(*rng),
        region_(MakeBaseRegion(scene_.bounds_W_m, range, options.wall_margin_m)),
        bounds_(DistanceRangeBounds(range)),
        grow_m_(kinematics.model().base_cylinder.radius_m + options.tight_base_spread_m),
        checker_(kinematics, scene_, SceneClearanceOptions{options.tight_clearance_max_m}),
        workspace_(checker_.MakeWorkspace()) {
    for (std::size_t b = 0; b < scene.roles.size(); ++b) {
      const BoxRole role = scene.roles[b];
      if (role == BoxRole::kWall) continue;
      const Eigen::Vector3d half = scene_.boxes[b].HalfSize();
      const Anchor anchor{static_cast<int>(b), std::hypot(half.x() + grow_m_, half.y() + grow_m_)};
      if (!CanHoldBase(anchor)) continue;
      any_box_.push_back(anchor);
      if (role == BoxRole::kTableTop) table_tops_.push_back(anchor);
    }
  }

  bool has_table_tops() const { return !table_tops_.empty(); }

  // A tight start state in *state (its measurements in *end); false if none in the budget.
  bool DrawStart(WholeBodyState* state, TightEnd* end) {
    std::vector<Anchor> anchors;
    for (const Anchor& a : any_box_) {
      if (FarthestRegionPoint(Center(a)) + a.reach_m >= bounds_.min_m) anchors.push_back(a);
    }
    return DrawEnd(anchors, TightGoalKind::kNearBox, std::nullopt, state, end, nullptr);
  }

  // A tight goal of `kind` in range of `start`; *table_top: the anchor for on/under kinds.
  // Its base must be one the start's base can reach (ProvenBaseRegion).
  bool DrawGoal(const WholeBodyState& start, TightGoalKind kind, WholeBodyState* state,
                TightEnd* end, int* table_top) {
    const Eigen::Vector2d p_start(start.x_m, start.y_m);
    std::optional<ProvenBaseRegion> from_start;
    if (options_.tight_pocket_window_m > 0.0) {
      from_start.emplace(scene_, kinematics_, p_start, Openness());
    }
    std::vector<Anchor> anchors;
    for (const Anchor& a : kind == TightGoalKind::kNearBox ? any_box_ : table_tops_) {
      const double d = (Center(a) - p_start).norm();
      if (d + a.reach_m >= bounds_.min_m && d - a.reach_m <= bounds_.max_m) anchors.push_back(a);
    }
    return DrawEnd(anchors, kind, p_start, state, end, table_top,
                   from_start ? &*from_start : nullptr);
  }

 private:
  Eigen::Vector2d Center(const Anchor& a) const {
    return scene_.boxes[a.box].center_W_m.head<2>();
  }

  // The grown footprint can meet the base region.
  bool CanHoldBase(const Anchor& a) const {
    const Eigen::Vector2d c = Center(a);
    const Eigen::Vector2d nearest = c.cwiseMax(region_.min_m).cwiseMin(region_.max_m);
    return (nearest - c).norm() <= a.reach_m;
  }

  double FarthestRegionPoint(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d far((p.x() - region_.min_m.x() > region_.max_m.x() - p.x())
                                  ? region_.min_m.x() : region_.max_m.x(),
                              (p.y() - region_.min_m.y() > region_.max_m.y() - p.y())
                                  ? region_.min_m.y() : region_.max_m.y());
    return (far - p).norm();
  }

  bool DrawEnd(const std::vector<Anchor>& anchors, TightGoalKind kind,
               const std::optional<Eigen::Vector2d>& p_start, WholeBodyState* state,
               TightEnd* end, int* table_top, const ProvenBaseRegion* from_start = nullptr) {
    if (anchors.empty()) return false;
    const int last = static_cast<int>(anchors.size()) - 1;
    for (int i = 0; i < options_.max_tight_base_tries; ++i) {
      const Anchor& anchor = anchors[rng_.UniformInt(0, last)];
      const OrientedBox& box = scene_.boxes[anchor.box];
      if (!DrawBasePose(box, state)) continue;
      const Eigen::Vector2d p_WB(state->x_m, state->y_m);
      if (p_start && !bounds_.Contains((p_WB - *p_start).norm())) continue;
      if (from_start != nullptr && !from_start->Reaches(p_WB)) continue;
      if (DrawTightArm(kind, box, state, end) && !InPocket(*state)) {
        if (table_top != nullptr) *table_top = kind == TightGoalKind::kNearBox ? -1 : anchor.box;
        return true;
      }
    }
    return false;
  }

  // A base pose near `box` (uniform over its footprint grown by grow_m_, yaw uniform); false
  // if it leaves the base region or the base cylinder is not clear.
  bool DrawBasePose(const OrientedBox& box, WholeBodyState* state) {
    const Eigen::Vector3d half = box.HalfSize();
    const double u = rng_.Uniform(-half.x() - grow_m_, half.x() + grow_m_);
    const double v = rng_.Uniform(-half.y() - grow_m_, half.y() + grow_m_);
    const double yaw = rng_.Uniform(-std::numbers::pi, std::numbers::pi);
    const double c = std::cos(box.yaw_rad);
    const double s = std::sin(box.yaw_rad);
    state->x_m = QuantizeMicro(box.center_W_m.x() + c * u - s * v);
    state->y_m = QuantizeMicro(box.center_W_m.y() + s * u + c * v);
    state->yaw_rad = QuantizeMicro(yaw);
    const Eigen::Vector2d p_WB(state->x_m, state->y_m);
    if (!region_.Contains(p_WB)) return false;
    const double margin = options_.obstacle_margin_m;
    return checker_.BaseClearance(p_WB, margin) > margin;
  }

  // The base of `state` is not proven able to leave the pocket window with the passage
  // clearance (CertifyBaseOpen).
  bool InPocket(const WholeBodyState& state) const {
    if (options_.tight_pocket_window_m == 0.0) return false;
    return CertifyBaseOpen(scene_, kinematics_, Eigen::Vector2d(state.x_m, state.y_m),
                           options_.tight_pocket_window_m, Openness())
        .certified_unreachable;
  }

  BaseOpennessOptions Openness() const {
    BaseOpennessOptions openness;
    openness.clearance_m = options_.tight_passage_clearance_m;
    openness.approach_radius_m = options_.tight_approach_radius_m;
    return openness;
  }

  // Every arm sphere above the floor and the end-effector point inside the scene's bounds.
  bool AboveFloorAndInBounds(const KinematicsCache& cache) const {
    const double floor_z = scene_.bounds_W_m.min().z();
    const std::vector<CollisionSphere>& spheres = kinematics_.model().spheres;
    for (std::size_t s = 0; s < spheres.size(); ++s) {
      if (cache.p_WS[s].z() - spheres[s].radius_m < floor_z) return false;
    }
    return scene_.bounds_W_m.contains(cache.X_WE.translation());
  }

  // Uniform arm configurations at the base pose of *state until one is clear and tight (and
  // meets the goal kind for `anchor`).
  bool DrawTightArm(TightGoalKind kind, const OrientedBox& anchor, WholeBodyState* state,
                    TightEnd* end) {
    const double floor_z = scene_.bounds_W_m.min().z();
    for (int i = 0; i < options_.tight_arm_tries; ++i) {
      DrawUniformArm(kinematics_.model().joint_limits, rng_, state);
      kinematics_.Update(*state, &workspace_.cache);
      if (!GoalKindHolds(kind, anchor, workspace_.cache.X_WE.translation(), options_, floor_z) ||
          !AboveFloorAndInBounds(workspace_.cache)) {
        continue;
      }
      const SceneClearance clearance = checker_.Compute(*state, &workspace_);
      if (!clearance.IsCollisionFree(options_.obstacle_margin_m, options_.self_margin_m) ||
          !(clearance.obstacle_m() <= options_.tight_clearance_max_m)) {
        continue;
      }
      const bool base = clearance.base_m <= clearance.spheres_m;
      end->clearance_m = clearance.obstacle_m();
      end->box = base ? clearance.base_box : clearance.sphere_box;
      end->body = base ? TightBody::kBase : TightBody::kArm;
      return true;
    }
    return false;
  }

  const Scene& scene_;
  const Kinematics& kinematics_;
  const TaskGeneratorOptions& options_;
  Rng& rng_;
  BaseRegion region_;
  DistanceBounds bounds_;
  double grow_m_;
  SceneClearanceChecker checker_;  // cutoff tight_clearance_max_m: nearer boxes are exact
  SceneClearanceWorkspace workspace_;
  std::vector<Anchor> any_box_;     // non-wall boxes whose grown footprint meets the region
  std::vector<Anchor> table_tops_;  // the table tops among them
};

}  // namespace

bool GoalKindHolds(TightGoalKind kind, const OrientedBox& table_top, const Eigen::Vector3d& p_WE,
                   const TaskGeneratorOptions& options, double floor_z_m) {
  if (kind == TightGoalKind::kNearBox) return true;
  if (!(SignedDistanceToFootprint(table_top, p_WE.head<2>()) <= 0.0)) return false;
  const double top_z = table_top.center_W_m.z() + 0.5 * table_top.size_m.z();
  const double bottom_z = table_top.center_W_m.z() - 0.5 * table_top.size_m.z();
  if (kind == TightGoalKind::kOnTable) {
    const double height = p_WE.z() - top_z;
    return options.on_table_height_min_m <= height && height <= options.on_table_height_max_m;
  }
  return floor_z_m < p_WE.z() && p_WE.z() < bottom_z;
}

PlanningTask GenerateTightTask(const GeneratedScene& scene, DistanceRange range,
                               std::uint64_t seed, const Kinematics& kinematics,
                               const TaskGeneratorOptions& options) {
  CheckTightOptions(options);
  if (scene.roles.size() != scene.scene.boxes.size()) {
    throw std::invalid_argument("GenerateTightTask: the scene has " +
                                std::to_string(scene.roles.size()) + " box roles for " +
                                std::to_string(scene.scene.boxes.size()) + " boxes");
  }
  Rng rng(seed);
  TightEndSampler sampler(scene, range, kinematics, options, &rng);
  TightTaskInfo info;
  if (sampler.has_table_tops() && rng.Uniform01() < options.table_goal_fraction) {
    info.goal_kind =
        rng.Uniform01() < 0.5 ? TightGoalKind::kOnTable : TightGoalKind::kUnderTable;
  }
  PlanningTask task;
  task.range = range;
  task.seed = seed;
  task.scene_seed = scene.scene.seed;
  for (int pair = 0; pair < options.max_tight_pair_tries; ++pair) {
    if (!sampler.DrawStart(&task.start, &info.start)) continue;
    if (!sampler.DrawGoal(task.start, info.goal_kind, &task.goal, &info.goal,
                          &info.goal_table_top)) {
      continue;
    }
    task.X_WE_goal = kinematics.EndEffectorPose(task.goal);
    task.base_distance_m = BaseDistance(task.start, task.goal);
    task.tight = info;
    return task;
  }
  throw std::runtime_error(
      "GenerateTightTask: no tight start and " + std::string(TightGoalKindName(info.goal_kind)) +
      " goal in range \"" + std::string(DistanceRangeName(range)) + "\" in " +
      std::to_string(options.max_tight_pair_tries) + " pairs of " +
      std::to_string(options.max_tight_base_tries) + " base poses (seed " +
      std::to_string(seed) + ")");
}

}  // namespace topay
