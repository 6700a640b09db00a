// topay-bench: the benchmark harness. Runs N generated benchmark tasks (a fresh scene per
// task) with one planner method or several on identical tasks, and writes tasks.jsonl (one
// line per task and method), summary.json (one object per method) and, with
// --dump-trajectories, each task's scene, task and trajectory JSON. Prints a Markdown table;
// a progress bar on stderr when stderr is a terminal. Logic: tools/topay_bench/bench_run.h.
// Exit codes: 0 ran (whatever the success rate), 1 a file error, 2 a usage error.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "core/common/heap_retention.h"
#include "core/common/stopwatch.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_bench/bench_cli.h"
#include "tools/topay_bench/bench_run.h"
#include "tools/topay_bench/progress_line.h"
#include "tools/common/usage_error.h"

namespace {

namespace bench = topay::bench;

bench::BenchProgress TerminalProgress() {
  if (::isatty(STDERR_FILENO) == 0) return {};
  const topay::Stopwatch watch;
  return [watch](int done, int total) {
    const double elapsed_s = watch.ElapsedS();
    std::cerr << "\r" << bench::ProgressLine(done, total, elapsed_s) << (done == total ? "\n" : "")
              << std::flush;
  };
}

int Usage(const std::string& message) {
  std::cerr << "topay-bench: " << message << "\n(run with --help for usage)\n";
  return bench::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  topay::RetainFreedHeapMemory();  // plans reuse their grids' memory (heap_retention.h)
  CLI::App app{"Benchmark TopAY (and its baselines) on N generated tasks."};
  bench::BenchCommandLine line;
  bench::AddBenchFlags(topay::tools::ConfigDir(TOPAY_CONFIG_DIR), &app, &line);
  app.footer(topay::tools::ExitCodesFooter(false) +
             " A run exits 0 whatever its success rate.");
  try {
    app.parse(argc, argv);
    bench::FinishBenchCommandLine(&line);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return Usage(e.what());
  } catch (const topay::plan::UsageError& e) {
    return Usage(e.what());
  }
  try {
    const bench::BenchReport report = bench::RunBench(line.options, TerminalProgress());
    std::cout << report.Markdown();
    std::cout << "Wrote " << report.tasks_jsonl << " and " << report.summary_json << "\n";
    return bench::kExitRan;
  } catch (const topay::plan::UsageError& e) {
    return Usage(e.what());
  } catch (const std::exception& e) {
    std::cerr << "topay-bench: error: " << e.what() << "\n";
    return bench::kExitError;
  }
}

