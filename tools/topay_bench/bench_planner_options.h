#pragma once

#include <cstdint>

#include "core/planner/whole_body_planner_options.h"
#include "core/robot/robot_model.h"
#include "tools/topay_bench/bench_method.h"

namespace topay::bench {

/// The run-wide settings that topay-bench puts on top of the loaded planner options.
struct BenchPlannerSettings {
  BaseLimits base_limits;  ///< The chosen base limits (benchmark or robot).
  int num_threads = 2;     ///< 0: all cores; 1: deterministic (MakeDeterministic).
  double time_limit_ms = 3000.0;
};

/// The planner options of one method on one task, from the options loaded from the YAML:
///  1. base_limits; num_threads and front_end.num_threads; time_limit_s = time_limit_ms / 1000;
///  2. the random stages' seeds from the task seed: front_end.seed = DeriveSeed(task_seed,
///     1000) and front_end.ik.seed = DeriveSeed(task_seed, 1001) (every method of a task gets
///     the same seeds; the YAML's seeds are replaced);
///  3. ApplyBenchMethod(method);
///  4. with num_threads == 1: MakeDeterministic (work budgets instead of wall-clock ones).
WholeBodyPlannerOptions BenchPlannerOptions(const WholeBodyPlannerOptions& loaded,
                                            BenchMethod method,
                                            const BenchPlannerSettings& settings,
                                            std::uint64_t task_seed);

}  // namespace topay::bench
