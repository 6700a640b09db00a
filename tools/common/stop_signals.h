#pragma once
// Ctrl-C and SIGTERM for tools that run child graphs: the signals are blocked (so they do not
// kill the tool mid-run; children started later get them unblocked by the child launcher) and
// polled, so the tool can stop its graph cleanly and still write its results.

#include <signal.h>

namespace topay::tools {

/// Blocks SIGINT and SIGTERM in the calling thread (call before starting any thread).
inline void BlockStopSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigprocmask(SIG_BLOCK, &signals, nullptr);
}

/// True once SIGINT or SIGTERM came (blocked, they wait to be taken here); never waits.
inline bool StopRequested() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  const timespec no_wait{0, 0};
  return sigtimedwait(&signals, nullptr, &no_wait) > 0;
}

}  // namespace topay::tools
