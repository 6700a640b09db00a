#pragma once
// Tests of real-time closed loops through real processes check what happens at the graph's own
// rates: the tracker's 50 Hz NMPC keeping the robot on its trajectory, a planner answering before
// the robot gets there, a replay's planner keeping pace. In a build that runs several times
// slower (tests/common/sanitizer_build.h) those rates cannot be kept and the test would fail on
// time, not on what it checks; there it is skipped, saying so. Their processes' threads are still
// checked under the same sanitizer by the process tests (docs/reliability.md).

#include <gtest/gtest.h>

#include "tests/common/sanitizer_build.h"

/// In a test body or SetUp: skips (GTEST_SKIP, with the reason) where real-time loops cannot
/// keep their rates (topay::testing::kRealTimeLoopsCannotKeepUp).
#define TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD()                                                      \
  do {                                                                                                 \
    if (::topay::testing::kRealTimeLoopsCannotKeepUp) {                                                \
      GTEST_SKIP() << "a real-time closed loop: this sanitizer build runs ~"                           \
                   << ::topay::testing::kBuildSlowdown                                                 \
                   << "x slower and its processes cannot keep the graph's rates (runs in make test)"; \
    }                                                                                                  \
  } while (0)
