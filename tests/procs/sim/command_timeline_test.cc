// Commands on their own time (procs/sim/command_timeline.h): kept until the step of their stamp,
// far-future stamps taken as now, out-of-order ones dropped; and the point of it: a plant that
// stalled and caught up ends where a plant that never stalled ends, which handing it the latest
// command before the catch-up does not.

#include "procs/sim/command_timeline.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/plant/plant.h"
#include "tests/sim/plant/plant_test_robot.h"

namespace topay::simproc {
namespace {

sim::ActuatorCommand Cmd(double v, double w = 0.0) {
  sim::ActuatorCommand c;
  c.v_mps = v;
  c.omega_radps = w;
  c.qdot_radps = Eigen::VectorXd::Zero(7);
  return c;
}

std::vector<double> Speeds(const std::vector<sim::ActuatorCommand>& due) {
  std::vector<double> v;
  for (const sim::ActuatorCommand& c : due) v.push_back(c.v_mps);
  return v;
}

TEST(CommandTimeline, KeepsACommandUntilTheStepOfItsStamp) {
  CommandTimeline timeline;
  std::vector<sim::ActuatorCommand> due;
  EXPECT_EQ(timeline.Push(1'000'000, Cmd(0.1), 1'000'000, 1'000'000), "");
  EXPECT_EQ(timeline.Push(1'003'000, Cmd(0.2), 1'000'000, 1'003'000), "");  // 3 ms ahead of the plant
  timeline.TakeDue(1'002'000, &due);
  EXPECT_EQ(Speeds(due), std::vector<double>({0.1}));
  EXPECT_EQ(timeline.pending(), 1u);
  timeline.TakeDue(1'003'999, &due);
  EXPECT_EQ(Speeds(due), std::vector<double>({0.2}));
  timeline.TakeDue(1'010'000, &due);
  EXPECT_TRUE(due.empty());
  EXPECT_EQ(timeline.counts().caught_up, 0);  // 3 ms ahead: real time, not a stall
}

TEST(CommandTimeline, AfterAStallEachWaitingCommandIsDueAtItsOwnStep) {
  CommandTimeline timeline;
  // The plant stopped at 2.000 s; 0.4 s of commands (200 Hz) arrive before it steps again.
  for (int k = 1; k <= 80; ++k) {
    EXPECT_EQ(timeline.Push(2'000'000 + 5'000 * k, Cmd(0.01 * k), 2'000'000, 2'400'000), "");
  }
  EXPECT_EQ(timeline.counts().caught_up, 79);  // all but the first (5 ms ahead) from 10 ms on
  EXPECT_EQ(timeline.counts().largest_lead_us, 400'000);
  std::vector<sim::ActuatorCommand> due;
  timeline.TakeDue(2'002'000, &due);
  EXPECT_TRUE(due.empty());
  timeline.TakeDue(2'012'000, &due);  // stamps 2.005 and 2.010
  EXPECT_EQ(Speeds(due).size(), 2u);
  EXPECT_DOUBLE_EQ(due.back().v_mps, 0.02);
  timeline.TakeDue(2'400'000, &due);
  EXPECT_EQ(due.size(), 78u);
  EXPECT_DOUBLE_EQ(due.back().v_mps, 0.80);
}

TEST(CommandTimeline, AStampFarAheadOfTheWallClockIsTakenAsNow) {
  CommandTimeline timeline;
  std::vector<sim::ActuatorCommand> due;
  // A corrupted stamp an hour ahead: not held for an hour, due at the plant's next step.
  EXPECT_EQ(timeline.Push(3'600'000'000 + 5'000'000, Cmd(0.3), 5'000'000, 5'000'000), "");
  EXPECT_EQ(timeline.counts().restamped, 1);
  timeline.TakeDue(5'002'000, &due);
  EXPECT_EQ(Speeds(due), std::vector<double>({0.3}));
  // Within the lead (2 ms) it is trusted: a clock adjusted by a millisecond.
  EXPECT_EQ(timeline.Push(5'003'000, Cmd(0.4), 5'002'000, 5'002'000), "");
  EXPECT_EQ(timeline.counts().restamped, 1);
  timeline.TakeDue(5'002'999, &due);
  EXPECT_TRUE(due.empty());
  // 3 ms ahead is not: due at once.
  EXPECT_EQ(timeline.Push(5'008'000, Cmd(0.5), 5'004'000, 5'005'000), "");
  EXPECT_EQ(timeline.counts().restamped, 2);
  timeline.TakeDue(5'005'000, &due);
  EXPECT_EQ(Speeds(due), std::vector<double>({0.4, 0.5}));
}

TEST(CommandTimeline, AnOlderCommandNeverReplacesANewerOne) {
  CommandTimeline timeline;
  std::vector<sim::ActuatorCommand> due;
  EXPECT_EQ(timeline.Push(1'010'000, Cmd(0.5), 1'000'000, 1'010'000), "");
  timeline.TakeDue(1'012'000, &due);
  const std::string why = timeline.Push(1'005'000, Cmd(0.9), 1'012'000, 1'012'000);  // reordered on the way
  EXPECT_NE(why.find("before the newest command kept"), std::string::npos) << why;
  EXPECT_EQ(timeline.counts().out_of_order, 1);
  timeline.TakeDue(1'020'000, &due);
  EXPECT_TRUE(due.empty());
  EXPECT_EQ(timeline.Push(1'010'000, Cmd(0.6), 1'012'000, 1'012'000), "");  // the same stamp: kept
  EXPECT_NE(timeline.Report().find("1 out of order"), std::string::npos) << timeline.Report();
}

TEST(CommandTimeline, AFloodKeepsAtMostMaxPending) {
  CommandTimelineOptions options;
  options.max_pending = 10;
  CommandTimeline timeline(options);
  for (int k = 0; k < 25; ++k) timeline.Push(1'000'000 + k, Cmd(k), 0, 1'000'000);
  EXPECT_EQ(timeline.pending(), 10u);
  EXPECT_EQ(timeline.counts().overflowed, 15);
  std::vector<sim::ActuatorCommand> due;
  timeline.TakeDue(2'000'000, &due);
  ASSERT_EQ(due.size(), 10u);
  EXPECT_DOUBLE_EQ(due.front().v_mps, 15.0);  // the newest ten
}

// The commands a tracker gives through a bend and a stop: 200 Hz, 1.2 s.
sim::ActuatorCommand BendAndStop(int k) {
  const double t = 0.005 * k;
  if (t < 0.5) return Cmd(0.6, 0.0);
  if (t < 0.9) return Cmd(0.6, 1.2);
  return Cmd(0.0, 0.0);
}
constexpr std::int64_t kEpoch = 10'000'000;
std::int64_t StampOf(int k) { return kEpoch + 5'000 * k; }
std::int64_t StepUtime(const sim::Plant& plant) { return kEpoch + std::llround((plant.time_s() + plant.step_s()) * 1e6); }

// Steps the plant to `end_s`, taking the commands of the timeline at each step.
void StepWithTimeline(sim::Plant* plant, CommandTimeline* timeline, double end_s) {
  std::vector<sim::ActuatorCommand> due;
  while (plant->time_s() < end_s - 1e-9) {
    timeline->TakeDue(StepUtime(*plant), &due);
    for (const sim::ActuatorCommand& c : due) EXPECT_EQ(plant->Command(c), "");
    plant->Step();
  }
}

TEST(CommandTimeline, AStalledPlantCatchesUpToWhereAPlantThatNeverStalledIs) {
  const double stall_from_s = 0.45, stall_to_s = 1.05, end_s = 1.6;  // the stall spans the bend
  sim::PlantOptions options;
  // Never stalled: each command arrives when the wall clock reaches its stamp, a step at a time.
  sim::Plant steady(test::TopayRobot(), options, 7);
  CommandTimeline steady_timeline;
  int next = 0;
  while (steady.time_s() < end_s - 1e-9) {
    while (StampOf(next) <= StepUtime(steady)) {
      steady_timeline.Push(StampOf(next), BendAndStop(next), StepUtime(steady) - 2'000, StampOf(next));
      ++next;
    }
    StepWithTimeline(&steady, &steady_timeline, steady.time_s() + options.step_s);
  }
  // Stalled: no steps from 0.45 s to 1.05 s of the wall clock while the commands keep coming;
  // then the steps it missed in a burst. Once with the timeline, once as before it (the latest
  // command handed to the plant on arrival, then the burst).
  sim::Plant caught_up(test::TopayRobot(), options, 7), latest_only(test::TopayRobot(), options, 7);
  CommandTimeline timeline;
  next = 0;
  for (sim::Plant* plant : {&caught_up, &latest_only}) {
    next = 0;
    while (plant->time_s() < end_s - 1e-9) {
      const double wall_s = plant->time_s() < stall_from_s - 1e-9 ? plant->time_s() + options.step_s
                                                                  : std::max(stall_to_s, plant->time_s() + options.step_s);
      while (StampOf(next) <= kEpoch + std::llround(wall_s * 1e6)) {
        if (plant == &caught_up) {
          timeline.Push(StampOf(next), BendAndStop(next), StepUtime(*plant) - 2'000, StampOf(next));
        } else {
          plant->Command(BendAndStop(next));
        }
        ++next;
      }
      if (plant == &caught_up) {
        StepWithTimeline(plant, &timeline, plant->time_s() + options.step_s);
      } else {
        plant->Step();
      }
    }
  }
  EXPECT_GT(timeline.counts().caught_up, 100);
  const auto distance = [](const sim::Plant& a, const sim::Plant& b) {
    return std::hypot(a.state().state.x_m - b.state().state.x_m, a.state().state.y_m - b.state().state.y_m);
  };
  EXPECT_LT(distance(caught_up, steady), 1e-9);
  EXPECT_NEAR(caught_up.state().state.yaw_rad, steady.state().state.yaw_rad, 1e-9);
  // Handed the latest command at once, the plant skipped the bend: the stop command drove it all.
  EXPECT_GT(distance(latest_only, steady), 0.1);
}

}  // namespace
}  // namespace topay::simproc
