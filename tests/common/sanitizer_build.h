#pragma once
// What a test needs to know about the sanitizer builds (make test-asan, make test-tsan;
// docs/reliability.md): their allocators replace glibc's, and everything runs slower, so a
// wall-clock budget that a test sets for work whose outcome (not speed) it checks is scaled.

namespace topay::testing {

// g++ 12 names its sanitizers with __SANITIZE_*__ macros, clang with __has_feature.
#if defined(__has_feature)
#define TOPAY_TEST_HAS_FEATURE(feature) __has_feature(feature)
#else
#define TOPAY_TEST_HAS_FEATURE(feature) 0
#endif

#if defined(__SANITIZE_ADDRESS__) || TOPAY_TEST_HAS_FEATURE(address_sanitizer)
inline constexpr bool kAddressSanitizerBuild = true;
#else
inline constexpr bool kAddressSanitizerBuild = false;
#endif

#if defined(__SANITIZE_THREAD__) || TOPAY_TEST_HAS_FEATURE(thread_sanitizer)
inline constexpr bool kThreadSanitizerBuild = true;
#else
inline constexpr bool kThreadSanitizerBuild = false;
#endif

#undef TOPAY_TEST_HAS_FEATURE

/// How many times longer the same work takes than in the normal build (the planner's tests
/// measured ~3-4x under ASan + UBSan; TSan is documented at 5-15x). Speed itself is measured
/// in benchmarks, never in these builds.
inline constexpr double kBuildSlowdown =
    kThreadSanitizerBuild ? 10.0 : (kAddressSanitizerBuild ? 4.0 : 1.0);

/// Real-time closed loops through real processes (the tracker's 50 Hz NMPC driving the
/// simulator, the planner in the loop, a replay's planner keeping pace) cannot keep their rates
/// in either sanitizer build: under TSan they fell behind (the robot 1 m off its trajectory, a
/// replay's inbox not emptied in 120 s); under ASan + UBSan, with a second test running beside
/// it, the tracker's solves took 5.4 ms (median) against their 5 ms budget, every one fell back
/// and tracking was lost (2026-12-06). Such tests skip here (tests/common/real_time_skip.h).
inline constexpr bool kRealTimeLoopsCannotKeepUp = kBuildSlowdown > 1.0;

}  // namespace topay::testing
