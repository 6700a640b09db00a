// The tracker's watch on the planner (procs/tracker/planner_watch.h): a new planner process is a
// restart, a stray copy with another pid is not, a silence counts only once heard, other
// processes' heartbeats are not the planner's.

#include "procs/tracker/planner_watch.h"

#include <gtest/gtest.h>

namespace topay::tracker {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;
constexpr std::int64_t kSecond = 1'000'000;

heartbeat_t Beat(const std::string& name, std::int32_t pid, std::int64_t seq) {
  heartbeat_t m{};
  m.process_name = name;
  m.pid = pid;
  m.seq = seq;
  return m;
}

TEST(PlannerWatch, ANewPlannerProcessIsARestart) {
  PlannerWatch watch({});
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 100, 0), kT0), PlannerWatch::Event::kFirstHeard);
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 100, 1), kT0 + kSecond), PlannerWatch::Event::kNone);
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 100, 2), kT0 + 2 * kSecond), PlannerWatch::Event::kNone);
  // Killed right after its heartbeat and restarted 0.4 s later: counts from 0 again.
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 230, 0), kT0 + 2 * kSecond + 400'000), PlannerWatch::Event::kRestarted);
  EXPECT_EQ(watch.pid(), 230);
  EXPECT_EQ(watch.previous_pid(), 100);
  EXPECT_EQ(watch.restarts(), 1);
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 230, 1), kT0 + 3 * kSecond), PlannerWatch::Event::kNone);
}

TEST(PlannerWatch, APlannerThatDiedAtItsFirstHeartbeatIsReplacedAfterAGap) {
  PlannerWatch watch({});
  watch.OnHeartbeat(Beat("planner", 100, 0), kT0);
  // Same seq, another pid, 1.6 s later: the first died (its next heartbeat never came).
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 101, 0), kT0 + 1'600'000), PlannerWatch::Event::kRestarted);
}

TEST(PlannerWatch, AStrayCopyWithAnotherPidIsIgnored) {
  PlannerWatch watch({});
  watch.OnHeartbeat(Beat("planner", 100, 0), kT0);
  watch.OnHeartbeat(Beat("planner", 100, 5), kT0 + 5 * kSecond);
  // A bit-flipped copy of the live planner's heartbeat (pid changed, seq the same) just after it.
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 100 ^ 64, 5), kT0 + 5 * kSecond + 10'000), PlannerWatch::Event::kIgnored);
  // An old copy of the live planner's (its seq went back).
  EXPECT_EQ(watch.OnHeartbeat(Beat("planner", 100, 3), kT0 + 5 * kSecond + 20'000), PlannerWatch::Event::kIgnored);
  EXPECT_EQ(watch.pid(), 100);
  EXPECT_EQ(watch.restarts(), 0);
  EXPECT_EQ(watch.ignored(), 2);
}

TEST(PlannerWatch, OtherProcessesAreNotThePlanner) {
  PlannerWatch watch({});
  EXPECT_EQ(watch.OnHeartbeat(Beat("mapper", 7, 0), kT0), PlannerWatch::Event::kNone);
  EXPECT_FALSE(watch.heard());
  EXPECT_EQ(watch.OnHeartbeat(Beat("topay-planner", 9, 0), kT0), PlannerWatch::Event::kFirstHeard);
  EXPECT_EQ(watch.OnHeartbeat(Beat("mapper", 8, 0), kT0 + 1), PlannerWatch::Event::kNone);
  EXPECT_EQ(watch.pid(), 9);
}

TEST(PlannerWatch, SilenceCountsOnlyOnceHeardAndCanBeSwitchedOff) {
  PlannerWatch watch({});
  EXPECT_FALSE(watch.Silent(kT0 + 100 * kSecond)) << "never heard: a tracker fed by a test or a tool";
  watch.OnHeartbeat(Beat("planner", 100, 0), kT0);
  EXPECT_FALSE(watch.Silent(kT0 + 3 * kSecond));
  EXPECT_TRUE(watch.Silent(kT0 + 3 * kSecond + 1));
  watch.OnHeartbeat(Beat("planner", 100, 1), kT0 + 4 * kSecond);
  EXPECT_FALSE(watch.Silent(kT0 + 5 * kSecond));

  PlannerWatchOptions off;
  off.silence_s = 0.0;
  PlannerWatch never(off);
  never.OnHeartbeat(Beat("planner", 100, 0), kT0);
  EXPECT_FALSE(never.Silent(kT0 + 100 * kSecond));
}

}  // namespace
}  // namespace topay::tracker
