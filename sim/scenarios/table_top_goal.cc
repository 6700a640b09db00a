#include "sim/scenarios/table_top_goal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/robot/whole_body_ik.h"
#include "sim/scenes/tight_task_generator.h"

namespace topay {

bool AboveTableTop(const OrientedBox& table_top, const Eigen::Vector3d& p_WE, const PickPlaceScenarioOptions& options) {
  TaskGeneratorOptions on_table;
  on_table.on_table_height_min_m = options.height_min_m;
  on_table.on_table_height_max_m = options.height_max_m;
  return GoalKindHolds(TightGoalKind::kOnTable, table_top, p_WE, on_table, 0.0);
}

TableTopGoalSampler::TableTopGoalSampler(const GeneratedScene& room, const Kinematics& kinematics,
                                         const PickPlaceScenarioOptions& options)
    : room_(room),
      kinematics_(kinematics),
      options_(options),
      checker_(kinematics, room.scene),
      reach_m_(ArmReachBound(kinematics.model())) {
  if (room.roles.size() != room.scene.boxes.size()) {
    throw std::invalid_argument("TableTopGoalSampler: " + std::to_string(room.roles.size()) + " roles for " +
                                std::to_string(room.scene.boxes.size()) + " boxes");
  }
  for (std::size_t b = 0; b < room.roles.size(); ++b) {
    const OrientedBox& box = room.scene.boxes[b];
    const double upper_face_z = box.center_W_m.z() + 0.5 * box.size_m.z();
    if (room.roles[b] == BoxRole::kTableTop && upper_face_z <= options.top_height_max_m) {
      table_tops_.push_back(static_cast<int>(b));
    }
  }
}

Eigen::Isometry3d TableTopGoalSampler::DrawTarget(const OrientedBox& top, Rng* rng) const {
  const Eigen::Vector3d half = top.HalfSize();
  const double inset_x = std::min(options_.edge_inset_m, half.x()), inset_y = std::min(options_.edge_inset_m, half.y());
  const double depth_max = std::max(options_.edge_depth_max_m, std::max(inset_x, inset_y));
  double u = 0.0, v = 0.0;
  do {  // uniform over the inset footprint within depth_max of an edge (the arm reaches over it)
    u = rng->Uniform(-half.x() + inset_x, half.x() - inset_x);
    v = rng->Uniform(-half.y() + inset_y, half.y() - inset_y);
  } while (std::min(half.x() - std::abs(u), half.y() - std::abs(v)) > depth_max);
  const double height = rng->Uniform(options_.height_min_m, options_.height_max_m);
  // The tool points away from the nearest edge, into the table (the arm comes over that edge).
  const bool x_edge = half.x() - std::abs(u) < half.y() - std::abs(v);
  const double inward_B = x_edge ? (u > 0.0 ? std::numbers::pi : 0.0) : (v > 0.0 ? -0.5 : 0.5) * std::numbers::pi;
  const double yaw = top.yaw_rad + inward_B + rng->Uniform(-options_.tool_yaw_spread_rad, options_.tool_yaw_spread_rad);
  const double pitch = rng->Uniform(options_.tool_pitch_min_rad, options_.tool_pitch_max_rad);
  const double c = std::cos(top.yaw_rad), s = std::sin(top.yaw_rad);
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.translation() = Eigen::Vector3d(top.center_W_m.x() + c * u - s * v, top.center_W_m.y() + s * u + c * v,
                                       top.center_W_m.z() + half.z() + height);
  X_WE.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(0.5 * std::numbers::pi + pitch, Eigen::Vector3d::UnitY())).toRotationMatrix();
  return X_WE;
}

bool TableTopGoalSampler::ArmAboveFloor(const WholeBodyState& state) const {
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(state, &cache);
  const std::vector<CollisionSphere>& spheres = kinematics_.model().spheres;
  const double floor_z = room_.scene.bounds_W_m.min().z();
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    if (cache.p_WS[s].z() - spheres[s].radius_m < floor_z + options_.obstacle_clearance_m) return false;
  }
  return true;
}

bool TableTopGoalSampler::Admits(const TableTopGoal& goal, const TableTopGoalQuery& query) const {
  if (goal.table_top < 0 || goal.table_top >= static_cast<int>(room_.scene.boxes.size()) ||
      room_.roles[goal.table_top] != BoxRole::kTableTop || goal.table_top == query.exclude_table_top) {
    return false;
  }
  const Eigen::Vector2d p_WB(goal.state.x_m, goal.state.y_m);
  if ((p_WB - query.p_W_from_m).norm() < query.min_base_distance_m) return false;
  if (query.reachable == nullptr || !query.reachable->Reaches(p_WB)) return false;
  const Eigen::Vector3d p_WE = kinematics_.EndEffectorPose(goal.state).translation();
  if (!AboveTableTop(room_.scene.boxes[goal.table_top], p_WE, options_)) return false;
  return ArmAboveFloor(goal.state) &&
         checker_.Compute(goal.state).IsCollisionFree(options_.obstacle_clearance_m, 0.0);
}

std::optional<TableTopGoal> TableTopGoalSampler::Solve(int top, const Eigen::Isometry3d& X_WE,
                                                       const TableTopGoalQuery& query, Rng* rng) const {
  WholeBodyIkOptions ik;
  ik.seed = rng->NextSeed();
  ik.time_budget_s = std::numeric_limits<double>::infinity();
  ik.max_total_iterations = options_.ik_iterations;
  ik.min_clearance_m = options_.obstacle_clearance_m;
  ik.max_base_candidates = options_.ik_base_candidates;
  ik.max_solutions = 12;
  const WholeBodyIk solver(kinematics_, ik);
  const StateClearanceFn clearance = [this](const WholeBodyState& s) { return checker_.Compute(s).obstacle_m(); };
  WholeBodyIkQuery ik_query;
  ik_query.reference_base = Eigen::Vector3d(query.p_W_from_m.x(), query.p_W_from_m.y(), 0.0);
  const WholeBodyIkResult result = solver.Solve(X_WE, clearance, ik_query);
  for (const IkSolution& solution : result.solutions) {
    TableTopGoal goal;
    goal.table_top = top;
    goal.state = solution.state;
    goal.X_WE = kinematics_.EndEffectorPose(solution.state);
    goal.clearance_m = checker_.Compute(solution.state).obstacle_m();
    if (Admits(goal, query)) return goal;
  }
  return std::nullopt;
}

bool TableTopGoalSampler::NextToReachedBase(const OrientedBox& top, const TableTopGoalQuery& query) const {
  const double grow_m = kinematics_.model().base_cylinder.radius_m + 0.1;
  const Eigen::Vector2d half = top.HalfSize().head<2>() + Eigen::Vector2d::Constant(grow_m);
  const double c = std::cos(top.yaw_rad), s = std::sin(top.yaw_rad);
  const int n = 8;  // points per side of the grown footprint's border
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < n; ++i) {
      const double t = -1.0 + 2.0 * (i + 0.5) / n;
      const Eigen::Vector2d p_B = side == 0 ? Eigen::Vector2d(half.x(), t * half.y())
                                : side == 1 ? Eigen::Vector2d(-half.x(), t * half.y())
                                : side == 2 ? Eigen::Vector2d(t * half.x(), half.y())
                                            : Eigen::Vector2d(t * half.x(), -half.y());
      const Eigen::Vector2d p_W = top.center_W_m.head<2>() + Eigen::Vector2d(c * p_B.x() - s * p_B.y(), s * p_B.x() + c * p_B.y());
      if ((p_W - query.p_W_from_m).norm() >= query.min_base_distance_m && query.reachable->Reaches(p_W)) return true;
    }
  }
  return false;
}

std::optional<TableTopGoal> TableTopGoalSampler::Draw(const TableTopGoalQuery& query, Rng* rng) const {
  if (query.reachable == nullptr) return std::nullopt;
  std::vector<int> tops;
  for (const int top : table_tops_) {
    if (top != query.exclude_table_top && NextToReachedBase(room_.scene.boxes[top], query)) tops.push_back(top);
  }
  if (tops.empty()) return std::nullopt;
  for (int k = 0; k < options_.max_targets; ++k) {
    const int top = tops[rng->UniformInt(0, static_cast<std::int64_t>(tops.size()) - 1)];
    const Eigen::Isometry3d X_WE = DrawTarget(room_.scene.boxes[top], rng);
    // The base stands within the arm's reach of the target: skip targets too near `from`.
    if ((X_WE.translation().head<2>() - query.p_W_from_m).norm() + reach_m_ < query.min_base_distance_m) continue;
    if (std::optional<TableTopGoal> goal = Solve(top, X_WE, query, rng)) return goal;
  }
  return std::nullopt;
}

}  // namespace topay
