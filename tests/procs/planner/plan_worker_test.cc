#include "procs/planner/plan_worker.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/trajectory/arc_yaw_sampling.h"
#include "core/validate/trajectory_validator.h"
#include "tests/common/arm_state.h"
#include "tests/procs/planner/planner_test_support.h"

namespace topay::planner {
namespace {

class PlanWorkerTest : public ::testing::Test {
 protected:
  PlanWorkerTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  static WholeBodyPlannerOptions Options() {
    WholeBodyPlannerOptions options;
    options.optimizer.time_limit_s = 15.0;  // generous: tests run in parallel on loaded cores
    options.front_end.acquisition_budget_s = 8.0;
    return options;
  }

  MapWork RoomWork(const std::vector<OrientedBox>& boxes) const {
    MapWork work;
    work.reset = true;
    work.geometry = testing::RoomGeometry();
    work.states = testing::StatesOf(work.geometry, boxes);
    work.map_seq = 1;
    return work;
  }

  PlanJob Job(std::int64_t id, const WholeBodyState& start, const WholeBodyState& goal) const {
    PlanJob job;
    job.map_seq = 1;
    job.job_id = id;
    job.goal_id = 7;
    job.start = MakeTrajectorySample(start.num_joints());
    job.start.state = start;
    job.X_WE_goal = kinematics_.EndEffectorPose(goal);
    job.hint = goal;
    job.time_limit_s = 30.0;
    job.certify_reachability = true;
    return job;
  }

  static PlanJobOutcome WaitForResult(PlanWorker* worker) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (std::chrono::steady_clock::now() < until) {
      if (std::optional<PlanJobOutcome> out = worker->TakeResult()) return std::move(*out);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ADD_FAILURE() << "no result within 90 s";
    return {};
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(PlanWorkerTest, PlansOnTheMapItWasGivenAndTheResultHoldsOnTheExactBoxes) {
  PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, 1.0);
  worker.SubmitMap(RoomWork(testing::RoomBoxes()));
  const WholeBodyState start = BentArmState(-2.5, -2.5, 0.0);
  const WholeBodyState goal = BentArmState(2.3, 2.0, 1.0);
  worker.SubmitPlan(Job(1, start, goal));
  const PlanJobOutcome out = WaitForResult(&worker);
  ASSERT_TRUE(out.result.success()) << out.result.failure_reason;
  EXPECT_EQ(out.job.job_id, 1);
  EXPECT_EQ(out.fields_map_seq, 1);
  // The voxels hold the boxes, so a trajectory clear of the voxels is clear of the boxes.
  Scene exact;
  exact.boxes = testing::RoomBoxes();
  exact.bounds_W_m = {Eigen::Vector3d(-4, -4, 0), Eigen::Vector3d(4, 4, 1.6)};
  const TrajectoryValidator validator(kinematics_, exact, model_.base_limits);
  const ValidationReport report =
      validator.Validate(SampleArcYaw(*out.result.trajectory), start, out.job.X_WE_goal);
  EXPECT_TRUE(report.ok) << report.Report();
  EXPECT_FALSE(worker.busy());
  EXPECT_EQ(worker.counts().plans, 1);
}

TEST_F(PlanWorkerTest, TargetBehindAWallIsCertifiedUnreachableWithoutPlanning) {
  std::vector<OrientedBox> boxes = testing::RoomBoxes();
  boxes.push_back(MakeBox({1.0, 0.0, 0.6}, {0.1, 8.0, 1.2}));  // splits the room in two
  PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, 1.0);
  worker.SubmitMap(RoomWork(boxes));
  worker.SubmitPlan(Job(1, BentArmState(-2.5, -2.5, 0.0), BentArmState(3.0, 0.0, 0.0)));
  const PlanJobOutcome out = WaitForResult(&worker);
  EXPECT_FALSE(out.result.success());
  EXPECT_TRUE(out.certified_unreachable);
  EXPECT_NE(out.result.failure_reason.find("unreachable"), std::string::npos) << out.result.failure_reason;
}

TEST_F(PlanWorkerTest, WithoutAMapThePlanFailsAndSaysSo) {
  PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, 1.0);
  PlanJob job = Job(1, BentArmState(-2.5, -2.5, 0.0), BentArmState(2.3, 2.0, 1.0));
  worker.SubmitPlan(job);
  const PlanJobOutcome out = WaitForResult(&worker);
  EXPECT_FALSE(out.result.success());
  EXPECT_NE(out.result.failure_reason.find("no map"), std::string::npos) << out.result.failure_reason;
}

TEST_F(PlanWorkerTest, ANewJobCancelsTheRunningOne) {
  PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, 1.0);
  worker.SubmitMap(RoomWork(testing::RoomBoxes()));
  PlanJob slow = Job(1, BentArmState(-2.5, -2.5, 0.0), BentArmState(2.3, 2.0, 1.0));
  slow.certify_reachability = false;
  worker.SubmitPlan(slow);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // it is running (or queued)
  worker.SubmitPlan(Job(2, BentArmState(-2.5, -2.5, 0.0), BentArmState(-2.0, -2.5, 0.0)));
  std::vector<PlanJobOutcome> outcomes;
  outcomes.push_back(WaitForResult(&worker));
  if (outcomes.back().job.job_id == 1) outcomes.push_back(WaitForResult(&worker));
  ASSERT_EQ(outcomes.back().job.job_id, 2);
  if (outcomes.size() == 2) {  // job 1 had started: it was stopped, not finished
    EXPECT_TRUE(outcomes[0].result.status == PlanStatus::kCancelled || outcomes[0].result.success())
        << ToString(outcomes[0].result.status);
  }
}

TEST_F(PlanWorkerTest, WaitForResultBlocksUntilTheResultOrTheTimeout) {
  PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, 1.0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(worker.WaitForResult(0.2).has_value()) << "no job: no result";
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(190));
  // No map submitted: the plan fails at once.
  worker.SubmitPlan(Job(1, BentArmState(-2.5, -2.5, 0.0), BentArmState(2.3, 2.0, 1.0)));
  const std::optional<PlanJobOutcome> out = worker.WaitForResult(30.0);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->job.job_id, 1);
  EXPECT_FALSE(worker.TakeResult().has_value()) << "taken once";
}

TEST_F(PlanWorkerTest, APlanThatFlushesAllMapUpdatesPlansOnFieldsWithEveryOneSubmittedBeforeIt) {
  constexpr double kNeverByItself_s = 1e6;
  const WholeBodyState start = BentArmState(-2.5, -2.5, 0.0), goal = BentArmState(-1.5, -2.5, 0.0);
  std::vector<OrientedBox> boxes = testing::RoomBoxes();
  boxes.push_back(MakeBox({2.0, 2.0, 0.5}, {0.4, 0.4, 1.0}));  // far from the plan: it changes nothing for it
  MapWork box;
  box.geometry = testing::RoomGeometry();
  box.map_seq = 2;
  const std::vector<std::uint8_t> before = testing::StatesOf(box.geometry, testing::RoomBoxes());
  const std::vector<std::uint8_t> after = testing::StatesOf(box.geometry, boxes);
  const Eigen::Vector3i& dims = box.geometry.dims;
  for (int iz = 0; iz < dims.z(); ++iz) {
    for (int iy = 0; iy < dims.y(); ++iy) {
      for (int ix = 0; ix < dims.x(); ++ix) {
        const std::int64_t i = box.geometry.Index(ix, iy, iz);
        if (after[i] != before[i]) box.changes.push_back({Eigen::Vector3i(ix, iy, iz), VoxelState::kOccupied});
      }
    }
  }
  ASSERT_FALSE(box.changes.empty());
  for (const bool flush_all_map : {false, true}) {
    PlanWorker worker(kinematics_, Options(), UnknownVoxelPolicy::kFree, kNeverByItself_s);
    worker.SubmitMap(RoomWork(testing::RoomBoxes()));
    PlanJob first = Job(1, start, goal);
    first.certify_reachability = false;
    worker.SubmitPlan(first);
    ASSERT_EQ(WaitForResult(&worker).fields_map_seq, 1);
    worker.SubmitMap(box);
    PlanJob second = Job(2, start, goal);
    second.map_seq = 2;
    second.certify_reachability = false;
    second.flush_all_map = flush_all_map;
    worker.SubmitPlan(second);
    const PlanJobOutcome out = WaitForResult(&worker);
    EXPECT_TRUE(out.result.success()) << out.result.failure_reason;
    // Without it the plan brings only its fresh region (around its start) up to date: the box
    // far from it waits for the background (never, here), so its fields hold map 1 wholly.
    EXPECT_EQ(out.fields_map_seq, flush_all_map ? 2 : 1) << "flush_all_map " << flush_all_map;
  }
}

}  // namespace
}  // namespace topay::planner
