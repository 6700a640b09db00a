// topay-bench-plot: draws the plots of topay-bench runs (success rate, planning time, duration
// against distance) from their summary.json and tasks.jsonl. Logic:
// tools/topay_bench_plot/bench_plot.h.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "tools/topay_bench_plot/bench_plot.h"

namespace {

constexpr int kExitSuccess = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Plot topay-bench runs: writes success_rate.png, planning_time.png and "
      "duration_vs_distance.png into --out.\n"
      "Exit codes: 0 written, 1 a missing or malformed input file or an unwritable output, "
      "2 a usage error."};
  std::string out_dir;
  std::vector<std::string> runs;
  app.add_option("--out", out_dir, "Output folder (created)")->required();
  app.add_option("runs", runs, "topay-bench --out folders (summary.json, tasks.jsonl)")
      ->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return e.get_exit_code() == 0 ? code : kExitUsage;
  }
  try {
    const topay::bench_plot::BenchRuns data = topay::bench_plot::ReadBenchRuns(runs);
    topay::bench_plot::WriteBenchPlots(data, out_dir);
  } catch (const std::exception& e) {
    std::cerr << "topay-bench-plot: " << e.what() << "\n";
    return kExitError;
  }
  std::cout << "wrote success_rate.png, planning_time.png, duration_vs_distance.png in "
            << out_dir << "\n";
  return kExitSuccess;
}
