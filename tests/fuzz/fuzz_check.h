#pragma once
// A fuzz target's own invariant: prints what failed and where, then aborts, so libFuzzer (or
// the replay driver) stops on the input and keeps it. A macro for __FILE__/__LINE__ (clang 14
// cannot use std::source_location with libstdc++ 12).

#include <cstdio>
#include <cstdlib>

namespace topay::fuzz {

inline void FuzzCheckAt(bool ok, const char* what, const char* file, int line) {
  if (ok) return;
  std::fprintf(stderr, "fuzz check failed at %s:%d: %s\n", file, line, what);
  std::abort();
}

}  // namespace topay::fuzz

#define FuzzCheck(ok, what) ::topay::fuzz::FuzzCheckAt((ok), (what), __FILE__, __LINE__)
