#pragma once
// topay-report's work behind its flags: read the log (and the scene), summarise, write
// summary.json, path.png and time_plots.png. main.cc only parses flags and prints.

#include <string>

#include "tools/report/path_plot_view.h"
#include "tools/report/run_summary.h"
#include "tools/report/run_time_plots.h"

namespace topay::report {

struct ReportOptions {
  std::string log_path;    ///< the run's graph.lcmlog (required)
  std::string scene_path;  ///< the room's scene JSON, for the boxes' outlines; empty: none
  std::string out_dir;     ///< where the files go; empty: the log's folder (created if missing)
  std::string json_path;   ///< also write the summary JSON here; empty: only out_dir/summary.json
  PathPlotOptions path_plot;
  RunTimePlotOptions time_plots;
};

/// Does it all; the summary's `files` say what was written. Throws std::runtime_error whose
/// message names the file and what is wrong: a missing or unreadable log or scene
/// (ConfigError for a bad scene file), an output that cannot be written.
RunSummary WriteReport(const ReportOptions& options);

}  // namespace topay::report
