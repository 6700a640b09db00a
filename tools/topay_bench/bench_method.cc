#include "tools/topay_bench/bench_method.h"

namespace topay::bench {

std::string_view BenchMethodName(BenchMethod method) {
  switch (method) {
    case BenchMethod::kTopay:
      return "topay";
    case BenchMethod::kJpsOnly:
      return "jps-only";
    case BenchMethod::kSequential:
      return "sequential";
    case BenchMethod::kFlatness:
      return "flatness";
  }
  return "unknown";
}

std::vector<BenchMethod> AllBenchMethods() {
  return {BenchMethod::kTopay, BenchMethod::kJpsOnly, BenchMethod::kSequential,
          BenchMethod::kFlatness};
}

std::optional<BenchMethod> ParseBenchMethod(std::string_view name) {
  for (BenchMethod method : AllBenchMethods()) {
    if (BenchMethodName(method) == name) return method;
  }
  return std::nullopt;
}

void ApplyBenchMethod(BenchMethod method, WholeBodyPlannerOptions* options) {
  switch (method) {
    case BenchMethod::kTopay:
      return;
    case BenchMethod::kJpsOnly:
      options->front_end.topology.mode = BasePathMode::kJpsOnly;
      return;
    case BenchMethod::kSequential:
      options->sequential = true;
      return;
    case BenchMethod::kFlatness:
      options->optimizer.parameterisation = TrajectoryParameterisation::kFlatness;
      options->front_end.topology.mode = BasePathMode::kJpsOnly;
      options->max_candidates = 1;
      return;
  }
}

}  // namespace topay::bench
