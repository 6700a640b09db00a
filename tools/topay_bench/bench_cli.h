#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "tools/topay_bench/bench_options.h"

namespace topay::bench {

/// What topay-bench's command line fills in: the options, and the raw --method / --compare
/// text (turned into options.methods by FinishBenchCommandLine).
struct BenchCommandLine {
  BenchOptions options;
  std::string method;
  std::string compare;
};

/// Defines topay-bench's flags on `app`, writing into *line; `config_dir` holds the default
/// planner YAML (planner/topay.yaml) and robot files (robot/topay_mm.urdf, .yaml).
void AddBenchFlags(const std::string& config_dir, CLI::App* app, BenchCommandLine* line);

/// After app.parse: options.methods from --method (one method only) or --compare. Throws
/// plan::UsageError naming the flag for a bad list or for several methods in --method.
void FinishBenchCommandLine(BenchCommandLine* line);

}  // namespace topay::bench
