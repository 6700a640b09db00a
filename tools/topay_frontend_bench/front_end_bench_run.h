#pragma once

#include <ostream>

#include "core/planning/front_end_options.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/scene_kind.h"
#include "tools/topay_frontend_bench/front_end_tally.h"
#include "tools/topay_frontend_bench/frontend_bench_options.h"

namespace topay::frontend_bench {

/// The front-end options of task `index`: the planner YAML's (`configured`) with the bench
/// options' overrides, the task's seed and the benchmark's base yaw-rate limit.
FrontEndOptions TaskFrontEndOptions(const FrontEndBenchOptions& o,
                                    const FrontEndOptions& configured, int index,
                                    const Kinematics& kinematics);

/// Runs the front end on generated task `index` (GenerateBenchmarkCase(kind, range,
/// DeriveSeed(o.seed, index))): builds the fields (before the front end's clock starts),
/// plans, re-checks every returned path against the exact scene and certifies unsolvable
/// tasks; adds the outcome to `tally`. With o.verbose, one line per task (and per arm job)
/// on `log`.
void RunFrontEndTask(const FrontEndBenchOptions& o, const FrontEndOptions& configured,
                     SceneKind kind, DistanceRange range, int index,
                     const Kinematics& kinematics, FrontEndTally* tally, std::ostream& log);

}  // namespace topay::frontend_bench
