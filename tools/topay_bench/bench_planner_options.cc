#include "tools/topay_bench/bench_planner_options.h"

#include "core/common/random.h"
#include "core/planner/deterministic_options.h"

namespace topay::bench {

WholeBodyPlannerOptions BenchPlannerOptions(const WholeBodyPlannerOptions& loaded,
                                            BenchMethod method,
                                            const BenchPlannerSettings& settings,
                                            std::uint64_t task_seed) {
  WholeBodyPlannerOptions options = loaded;
  options.base_limits = settings.base_limits;
  options.num_threads = settings.num_threads;
  options.front_end.num_threads = settings.num_threads;
  options.time_limit_s = settings.time_limit_ms / 1000.0;
  options.front_end.seed = DeriveSeed(task_seed, 1000);
  options.front_end.ik.seed = DeriveSeed(task_seed, 1001);
  ApplyBenchMethod(method, &options);
  if (settings.num_threads == 1) MakeDeterministic(&options);
  return options;
}

}  // namespace topay::bench
