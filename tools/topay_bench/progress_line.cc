#include "tools/topay_bench/progress_line.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace topay::bench {

std::string ProgressLine(int done, int total, double elapsed_s) {
  constexpr int kWidth = 20;
  const int shown_total = std::max(total, 1);
  const int clamped = std::clamp(done, 0, shown_total);
  const int filled = kWidth * clamped / shown_total;
  std::ostringstream out;
  out << "[" << std::string(filled, '#') << std::string(kWidth - filled, '-') << "] " << clamped
      << "/" << total << " tasks, " << std::lround(elapsed_s) << " s, ETA ";
  if (clamped == 0) {
    out << "?";
  } else {
    out << std::lround(elapsed_s / clamped * (shown_total - clamped)) << " s";
  }
  return out.str();
}

}  // namespace topay::bench
