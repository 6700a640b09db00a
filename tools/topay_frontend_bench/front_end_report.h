#pragma once

#include <ostream>

#include "tools/topay_frontend_bench/front_end_tally.h"
#include "tools/topay_frontend_bench/frontend_bench_options.h"

namespace topay::frontend_bench {

/// Writes the benchmark's Markdown table (one row: the cell's stage times as median / p95,
/// success rates with their counts) and the notes below it (certified unsolvable tasks,
/// cancelled jobs, status counts, stage medians, exact-check failures).
void WriteFrontEndReport(const FrontEndBenchOptions& o, const FrontEndTally& t,
                         std::ostream& out);

}  // namespace topay::frontend_bench
