#include "sim/scenarios/table_top_goal.h"

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
    if (room.roles[b] == BoxRole::kTableTop) table_tops_.push_back(static_cast<int>(b));
  }
}

Eigen::Isometry3d TableTopGoalSampler::DrawTarget(const OrientedBox& top, Rng* rng) const {
  const Eigen::Vector3d half = top.HalfSize();
  const double inset_x = std::min(options_.edge_inset_m, half.x()), inset_y = std::min(options_.edge_inset_m, half.y());
  const double u = rng->Uniform(-half.x() + inset_x, half.x() - inset_x);
  const double v = rng->Uniform(-half.y() + inset_y, half.y() - inset_y);
  const double height = rng->Uniform(options_.height_min_m, options_.height_max_m);
  const double yaw = rng->Uniform(-std::numbers::pi, std::numbers::pi);
  const double pitch = options_.tool_down ? 0.5 * std::numbers::pi : rng->Uniform(0.0, 0.5 * std::numbers::pi);
  const double c = std::cos(top.yaw_rad), s = std::sin(top.yaw_rad);
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.translation() = Eigen::Vector3d(top.center_W_m.x() + c * u - s * v, top.center_W_m.y() + s * u + c * v,
                                       top.center_W_m.z() + half.z() + height);
  X_WE.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY())).toRotationMatrix();
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

std::optional<TableTopGoal> TableTopGoalSampler::Draw(const TableTopGoalQuery& query, Rng* rng) const {
  std::vector<int> tops;
  for (const int top : table_tops_) {
    if (top != query.exclude_table_top) tops.push_back(top);
  }
  if (tops.empty() || query.reachable == nullptr) return std::nullopt;
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
