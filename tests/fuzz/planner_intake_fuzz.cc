// topay-planner's subscriptions (GOAL, ROBOT_STATE, MAP_UPDATE, TRACKER_STATUS) up to the point
// where a plan job would be submitted, with the library calls its node makes (PlannerNode::On*):
// the goal read (msgs::FromMessage) and screened against the live map and the arm's reach
// (ScreenGoal), the robot state read, the map taken in (MapIntake::Accept: the receiver plus the
// work for the planning thread) and queried for blocked boxes near the robot. The planning
// itself is the planner's own tests and benchmarks (a plan takes 0.1-2 s, no fuzzer pace).
// Checked: refusals and rejections say why; a MapWork's changes lie inside its grid.
// Input: subscriber_fuzz.h, 4 channels (ticks are ignored).
#include <cstdint>
#include <string>

#include "core/optimization/trajectory_problem.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/convert_goal.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/planner/goal_screen.h"
#include "procs/planner/map_intake.h"
#include "procs/planner/planner_process_options.h"
#include "tests/fuzz/subscriber_fuzz.h"
#include "topay/tracker_status_t.hpp"

namespace {

using namespace topay;

void TakeMap(const map_update_t& msg, planner::MapIntake* intake, const std::optional<msgs::RobotStateEstimate>& robot) {
  msgs::MapAcceptResult result;
  const std::optional<planner::MapWork> work = intake->Accept(msg, &result);
  if (result.outcome == msgs::MapUpdateOutcome::kRejected) FuzzCheck(!result.reason.empty(), "a rejection says why");
  if (work && work->reset) {
    FuzzCheck(static_cast<std::int64_t>(work->states.size()) == work->geometry.NumCells(), "a reset has every voxel");
  } else if (work) {
    for (const VoxelChange& c : work->changes) {
      FuzzCheck((c.voxel.array() >= 0).all() && (c.voxel.array() < work->geometry.dims.array()).all(),
                "a change lies inside the grid");
    }
  }
  if (!intake->has_map()) return;
  const Eigen::Vector3d p_W = robot ? Eigen::Vector3d(robot->state.x_m, robot->state.y_m, 0.5)
                                    : Eigen::Vector3d(0.0, 0.0, 0.5);
  if (!p_W.allFinite()) return;
  intake->NearBlocked(p_W, 0.3);
  intake->BlockedBoxesNear(Eigen::AlignedBox3d(p_W - Eigen::Vector3d(1.5, 1.5, 0.5), p_W + Eigen::Vector3d(1.5, 1.5, 1.0)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  static const planner::PlannerProcessOptions options =
      planner::LoadPlannerProcessOptions(ShippedConfig("planner/planner.yaml"));
  static const Kinematics kinematics(ShippedRobotModel());
  static const ReachHeights reach = ComputeReachHeights(kinematics);
  planner::MapIntake intake(options.map.unknown);
  std::optional<msgs::RobotStateEstimate> robot;
  FuzzReader in(data, size);
  for (int i = 0; i < kMaxSubscriberOps; ++i) {
    const std::optional<SubscriberOp> op = NextSubscriberOp(in, 4);
    if (!op) break;
    if (op->tick) continue;
    std::string error;
    switch (op->channel) {
      case 0:
        if (auto m = DecodeFuzzed<goal_t>(op->bytes, op->fix_fingerprint)) {
          const std::optional<msgs::PlanGoal> goal = msgs::FromMessage(*m, &error);
          if (goal) ScreenGoal(*goal, intake, reach, options.goals);
        }
        break;
      case 1:
        if (auto m = DecodeFuzzed<robot_state_t>(op->bytes, op->fix_fingerprint)) {
          if (auto estimate = msgs::FromMessage(*m, &error)) robot = std::move(estimate);
        }
        break;
      case 2:
        if (auto m = DecodeFuzzed<map_update_t>(op->bytes, op->fix_fingerprint)) TakeMap(*m, &intake, robot);
        break;
      default:
        DecodeFuzzed<tracker_status_t>(op->bytes, op->fix_fingerprint);
        break;
    }
  }
  return 0;
}
