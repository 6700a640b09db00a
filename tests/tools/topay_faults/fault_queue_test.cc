// FaultQueue: round robin over the faults still owed, a mission-ending fault only as a mission's
// last episode, refused injections given up after three tries, episodes never begun owed again.

#include <gtest/gtest.h>

#include "tools/topay_faults/fault_queue.h"

namespace topay::tools {
namespace {

FaultSpec Fault(const std::string& name, bool ends_mission = false) {
  FaultSpec f;
  f.name = name;
  f.ends_mission = ends_mission;
  return f;
}

EpisodeResult Episode(const std::string& fault, bool injected, bool refused = false) {
  EpisodeResult e;
  e.fault = fault;
  e.injected = injected;
  e.refused = refused;
  return e;
}

TEST(FaultQueue, TakesTheFaultsInTurnUntilEachHasItsRuns) {
  FaultQueue queue({Fault("a"), Fault("b")}, 2);
  std::vector<std::string> order;
  for (const FaultSpec* f = queue.Next(0, 8); f != nullptr; f = queue.Next(0, 8)) {
    order.push_back(f->name);
    EXPECT_TRUE(queue.Record(Episode(f->name, true)));
  }
  EXPECT_EQ(order, (std::vector<std::string>{"a", "b", "a", "b"}));
  EXPECT_TRUE(queue.Done());
  EXPECT_EQ(queue.Remaining("a"), 0);
}

TEST(FaultQueue, AMissionEndingFaultComesOnlyAsAMissionsLastEpisode) {
  FaultQueue queue({Fault("kill-mission", true), Fault("a")}, 3);
  EXPECT_EQ(queue.Next(0, 2)->name, "a");
  EXPECT_EQ(queue.Next(1, 2)->name, "a");
  EXPECT_EQ(queue.Next(2, 2)->name, "kill-mission");  // the mission has hosted its 2 episodes
  FaultQueue only({Fault("kill-mission", true), Fault("a")}, 1);
  ASSERT_TRUE(only.Record(Episode("a", true)));
  EXPECT_EQ(only.Next(0, 5)->name, "kill-mission");  // nothing else is owed
}

TEST(FaultQueue, ARefusedInjectionIsTriedThreeTimesThenKept) {
  FaultQueue queue({Fault("a")}, 1);
  EXPECT_FALSE(queue.Record(Episode("a", false, true)));
  EXPECT_FALSE(queue.Record(Episode("a", false, true)));
  EXPECT_FALSE(queue.Done());
  EXPECT_TRUE(queue.Record(Episode("a", false, true)));  // given up: kept so the table shows it
  EXPECT_TRUE(queue.Done());
}

TEST(FaultQueue, AnEpisodeThatNeverBeganIsOwedAgain) {
  FaultQueue queue({Fault("a")}, 1);
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(queue.Record(Episode("a", false, false)));
  EXPECT_EQ(queue.Remaining("a"), 1);
  EXPECT_EQ(queue.Next(0, 8)->name, "a");
}

TEST(FaultQueue, EpisodesOfAnEarlierRunCountTowardTheirFaultsRuns) {
  FaultQueue queue({Fault("a"), Fault("b")}, 2);
  queue.Count(Episode("a", true));
  queue.Count(Episode("a", false, true));  // given up earlier: counted as kept
  queue.Count(Episode("a", true));         // more than owed: nothing below zero
  queue.Count(Episode("other", true));     // not chosen now
  EXPECT_EQ(queue.Remaining("a"), 0);
  EXPECT_EQ(queue.Remaining("b"), 2);
  std::vector<std::string> order;
  for (const FaultSpec* f = queue.Next(0, 8); f != nullptr; f = queue.Next(0, 8)) {
    order.push_back(f->name);
    queue.Record(Episode(f->name, true));
  }
  EXPECT_EQ(order, (std::vector<std::string>{"b", "b"}));
  EXPECT_TRUE(queue.Done());
}

}  // namespace
}  // namespace topay::tools
