#pragma once

#include <string>

namespace topay::bench {

/// One progress line (no newline), e.g. "[########------------]  4/10 tasks, 12 s, ETA 18 s":
/// a 20-character bar, the count, the elapsed time and the remaining time estimated from
/// the mean time per finished task ("ETA ?" before the first one). topay-bench prints it on
/// stderr, behind a carriage return, only when stderr is a terminal.
std::string ProgressLine(int done, int total, double elapsed_s);

}  // namespace topay::bench
