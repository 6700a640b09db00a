#pragma once
// One seed's report in topay-missions: topay-report's library on the run folder's log (summary
// text, summary.json, path.png, time_plots.png), and the row of the results table from it.

#include <ostream>
#include <string>

#include "results_table.h"

namespace topay::tools {

/// Reports the run in `row->run_dir` (its graph.lcmlog, room.json) on `out` and in the folder,
/// and fills the row: the mission's result (unless the row already says TIMEOUT), contacts,
/// time, replans, boxes and tracking errors. A log that cannot be read leaves the result as it
/// was ("not run" becomes "NO LOG") with the reason in `detail`.
void ReportRun(MissionRunRow* row, std::ostream& out);

}  // namespace topay::tools
