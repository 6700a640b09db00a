// IssuedGoals (procs/planner/issued_goals.h): a goal id is taken once; a later copy is a repeat
// or a reuse, also after newer goals (finding 36: a corrupted copy of the mission's goal came
// after a forged goal had taken the planner's one-goal memory, and failed the mission's goal).

#include "procs/planner/issued_goals.h"

#include <gtest/gtest.h>

namespace topay::planner {
namespace {

using Verdict = IssuedGoals::Verdict;
using Bytes = std::vector<std::uint8_t>;

TEST(IssuedGoals, AnIdIsTakenOnceAndItsCopiesAreRepeatsOrReuses) {
  IssuedGoals goals;
  EXPECT_EQ(goals.Take(7, Bytes{1, 2, 3}), Verdict::kNew);
  EXPECT_EQ(goals.Take(7, Bytes{1, 2, 3}), Verdict::kRepeat);
  EXPECT_EQ(goals.Take(7, Bytes{1, 2, 4}), Verdict::kReused);
  EXPECT_EQ(goals.Take(7, Bytes{1, 2, 3}), Verdict::kRepeat);  // the reuse did not replace it
  EXPECT_EQ(goals.size(), 1u);
}

TEST(IssuedGoals, AnEarlierIdIsStillKnownAfterNewerOnes) {
  IssuedGoals goals;
  ASSERT_EQ(goals.Take(1796670159508831, Bytes{9}), Verdict::kNew);  // the mission's goal
  ASSERT_EQ(goals.Take(1726301415331167, Bytes{9}), Verdict::kNew);  // a copy with its id bit-flipped
  EXPECT_EQ(goals.Take(1796670159508831, Bytes{8}), Verdict::kReused);  // a copy with a flipped quaternion
}

TEST(IssuedGoals, TheOldestIdIsForgottenBeyondTheCapacity) {
  IssuedGoals goals(3);
  for (std::int64_t id = 1; id <= 4; ++id) ASSERT_EQ(goals.Take(id, Bytes{0}), Verdict::kNew);
  EXPECT_EQ(goals.size(), 3u);
  EXPECT_EQ(goals.Take(2, Bytes{1}), Verdict::kReused);
  EXPECT_EQ(goals.Take(1, Bytes{0}), Verdict::kNew);  // forgotten: taken again
  EXPECT_THROW(IssuedGoals(0), std::invalid_argument);
}

}  // namespace
}  // namespace topay::planner
