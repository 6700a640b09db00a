// topay-report: the closed-loop run report from a run's LCM log: prints the summary (mission
// result and step times, replans, ground-truth collisions, tracking errors, planning and solve
// times, distance, appeared boxes, messages per channel) and writes summary.json, path.png and
// time_plots.png (docs/report.md). Exit 0 when written (whatever the mission's result), 1 for
// an unreadable log or scene or an output that cannot be written, 2 usage.

#include <exception>
#include <iostream>

#include "tools/common/tool_cli.h"
#include "tools/report/report_tool.h"
#include "tools/report/summary_format.h"

int main(int argc, char** argv) {
  using namespace topay;
  report::ReportOptions options;
  CLI::App app{"topay-report: summary and plots of a closed-loop run from its LCM log"};
  app.add_option("--log", options.log_path, "the run's LCM log (<run>/graph.lcmlog)")->required();
  app.add_option("--scene", options.scene_path, "the room's scene JSON: its boxes drawn as outlines");
  app.add_option("--out", options.out_dir, "output folder (default: the log's folder)");
  app.add_option("--json", options.json_path, "also write the summary JSON to this file");
  app.footer(tools::ExitCodesFooter(false));
  if (const auto code = tools::ParseCommandLine(app, argc, argv, "topay-report")) return *code;
  try {
    const report::RunSummary summary = report::WriteReport(options);
    std::cout << report::FormatSummary(summary);
  } catch (const std::exception& e) {
    std::cerr << "topay-report: " << e.what() << "\n";
    return tools::kExitFileError;
  }
  return tools::kExitSuccess;
}
