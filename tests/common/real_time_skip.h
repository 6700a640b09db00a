#pragma once
// Tests of real-time closed loops through real processes check what happens at the graph's own
// rates: the tracker's 50 Hz NMPC keeping the robot on its trajectory, a planner answering before
// the robot gets there, a replay's planner keeping pace; and a few tests of wall-clock budgets
// (a supervisor's restart time against its heartbeat timeout). In a build that runs several times
// slower (tests/common/sanitizer_build.h) those rates cannot be kept and the test would fail on
// time, not on what it checks; there it is skipped, saying so. Their processes' threads are still
// checked under the same sanitizer by the process tests (docs/reliability.md).

#include <gtest/gtest.h>

#include "tests/common/sanitizer_build.h"

/// In a test body or SetUp: skips (GTEST_SKIP, with `reason` and the build's slowdown) in a
/// build where wall-clock rates cannot be kept (topay::testing::kRealTimeLoopsCannotKeepUp).
/// `reason` says which rate the test checks.
#define TOPAY_SKIP_IN_SLOW_BUILD(reason)                                                             \
  do {                                                                                               \
    if (::topay::testing::kRealTimeLoopsCannotKeepUp) {                                              \
      GTEST_SKIP() << reason << ": this sanitizer build runs ~" << ::topay::testing::kBuildSlowdown \
                   << "x slower and its processes cannot keep that rate (runs in make test)";       \
    }                                                                                                \
  } while (0)

/// In a test body or SetUp: skips a real-time closed loop where its rates cannot be kept.
#define TOPAY_SKIP_REAL_TIME_LOOP_IN_SLOW_BUILD() TOPAY_SKIP_IN_SLOW_BUILD("a real-time closed loop")
