// BrakingRun: the start of a run of drive outputs that only shrink towards zero (the devices' own
// stop ramps), as the fault tool times a stop by; its end at all zeros; anything else ends it.

#include "tools/topay_faults/braking_run.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::tools {
namespace {

TEST(BrakingRun, StartsWhenEveryAxisShrinksOrIsZeroAndLastsThroughTheZeros) {
  BrakingRun run(1e-3);
  EXPECT_EQ(run.Add({0.59, -0.18, 0.7}, 0.00), -1.0);  // nothing to compare with
  EXPECT_EQ(run.Add({0.59, -0.18, 0.7}, 0.02), -1.0);  // frozen outputs: not braking
  EXPECT_EQ(run.Add({0.59, -0.18, 0.5}, 0.04), -1.0);  // the arm brakes, the base not yet
  EXPECT_EQ(run.Add({0.57, -0.16, 0.3}, 0.06), 0.06);  // every axis now
  EXPECT_EQ(run.Add({0.55, -0.14, 0.0}, 0.08), 0.06);  // the arm at zero, the base still ramping
  EXPECT_EQ(run.Add({0.0, 0.0005, 0.0}, 0.10), 0.06);  // all (near) zero
  EXPECT_EQ(run.Add({0.0, 0.0, 0.0}, 0.12), 0.06);     // and staying there
}

TEST(BrakingRun, AnAxisThatGrowsOrHoldsOrIsNotANumberEndsIt) {
  BrakingRun run(1e-3);
  run.Add({0.5, 0.2}, 0.0);
  EXPECT_EQ(run.Add({0.4, 0.1}, 0.1), 0.1);
  EXPECT_EQ(run.Add({0.3, -0.15}, 0.2), -1.0);  // |omega| grew: a new command, whatever its sign
  EXPECT_EQ(run.Add({0.2, 0.1}, 0.3), 0.3);
  EXPECT_EQ(run.Add({0.2, 0.05}, 0.4), -1.0);   // v held
  EXPECT_EQ(run.Add({0.1, 0.0}, 0.5), 0.5);
  EXPECT_EQ(run.Add({NAN, 0.0}, 0.6), -1.0);
  EXPECT_EQ(run.Add({0.0, 0.0}, 0.7), 0.7);     // zeros are zeros, whatever came before
  EXPECT_EQ(run.Add({0.0, 0.0, 0.0}, 0.8), -1.0);  // another number of axes: nothing to compare with
  EXPECT_EQ(run.Add({0.0, 0.0, 0.0}, 0.9), 0.9);
}

}  // namespace
}  // namespace topay::tools
