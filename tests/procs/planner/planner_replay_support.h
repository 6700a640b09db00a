#pragma once
// Shared by the tests of topay-planner's deterministic mode (docs/planner.md#replay): waiting
// for a planner to have handled its inbox, and what its exit report says it handled.

#include <cstdint>
#include <string>

#include "graph_test_support.h"

namespace topay::test {

/// Spins `watcher` until the heartbeat of planner `name` (deterministic mode) says its inbox
/// is empty and no plan runs, having handled `handled` inputs (any number if < 0), twice in a
/// row (a heartbeat period apart: nothing came in between). False on timeout.
inline bool WaitUntilInboxEmpty(HeartbeatWatcher* watcher, const std::string& name, double timeout_s,
                                std::int64_t handled = -1) {
  const std::string wanted = handled >= 0 ? "inputs " + std::to_string(handled) + " handled, 0 waiting" : "0 waiting";
  std::string last_status;
  std::int64_t last_seq = -1;
  bool done = false;
  return watcher->SpinUntil([&] {
    const auto hb = watcher->last.find(name);
    if (done || hb == watcher->last.end() || hb->second.seq == last_seq) return done;
    const std::string& status = hb->second.status;
    const bool idle = status.find(wanted) != std::string::npos && status.find("plan running") == std::string::npos;
    done = idle && status == last_status;
    last_status = status;
    last_seq = hb->second.seq;
    return done;
  }, timeout_s);
}

/// The inputs a deterministic planner's exit report (in `output`) says it handled (-1: none).
inline std::int64_t MessagesHandled(const std::string& output) {
  const std::string key = "deterministic: ";
  const std::size_t at = output.rfind(key);
  return at == std::string::npos ? -1 : std::stoll(output.substr(at + key.size()));
}

}  // namespace topay::test
