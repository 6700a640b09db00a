// The planner's two YAML files from untrusted text: the core planner's options
// (core/io/planner_config.h ParsePlannerOptions; config/planner/topay.yaml) and topay-planner's
// own (procs/planner/planner_process_options.h LoadPlannerProcessOptions, path only: through a
// temporary file; config/planner/planner.yaml). Bad input must be a ConfigError naming the
// file; what loads must pass the options' own checks, the process's options also once applied
// to the core planner's (AdaptPlannerOptions, as topay-planner does).
// Input: [selector][YAML text]; selector bit 0: 0 the core planner's file, 1 the process's.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/io/planner_config.h"
#include "core/optimization/trajectory_optimizer.h"
#include "core/planning/arm_rrt_star.h"
#include "core/planning/front_end_options.h"
#include "core/planning/topological_path_search.h"
#include "core/validate/limit_ratios.h"
#include "core/validate/trajectory_validator.h"
#include "procs/planner/planner_process_options.h"
#include "tests/fuzz/fuzz_reader.h"
#include "tests/fuzz/loader_checks.h"
#include "tests/fuzz/loader_temp_file.h"

namespace topay::fuzz {
namespace {

constexpr const char* kCoreSource = "fuzz_topay.yaml";

// The checks the planner's constructor and Plan run on its options.
void CheckCoreOptions(const WholeBodyPlannerOptions& o) {
  try {
    CheckWholeBodyPlannerOptions(o);
    if (o.base_limits) CheckKinematicLimits(*o.base_limits, JointLimits{}, 0);
    CheckFrontEndOptions(o.front_end);
    CheckTrajectoryOptimizerOptions(o.optimizer);
    CheckTrajectoryValidatorOptions(o.validator);
  } catch (const std::invalid_argument&) {
    FuzzCheck(false, "loaded planner options pass the planner's checks");
  }
  FuzzCheck(CheckTopologicalPathSearchOptions(o.front_end.topology).empty(),
            "loaded topology options pass their check");
  FuzzCheck(CheckArmRrtStarOptions(o.front_end.rrt).empty(), "loaded RRT* options pass their check");
}

void FuzzCorePlannerOptions(const std::string& text) {
  std::optional<WholeBodyPlannerOptions> options;
  try {
    options = ParsePlannerOptions(text, kCoreSource);
  } catch (const ConfigError& e) {
    CheckConfigError(e, kCoreSource);
    return;
  }
  CheckCoreOptions(*options);
}

void FuzzPlannerProcessOptions(const std::string& text, const LoaderTempFile& file) {
  file.Write(text);
  std::optional<planner::PlannerProcessOptions> options;
  try {
    options = planner::LoadPlannerProcessOptions(file.path());
  } catch (const ConfigError& e) {
    CheckConfigError(e, file.path());
    return;
  }
  try {
    planner::CheckPlannerProcessOptions(*options, file.path());
  } catch (const ConfigError&) {
    FuzzCheck(false, "loaded process options pass CheckPlannerProcessOptions");
  }
  FuzzCheck(planner::FieldUpdatePeriod(*options) > 0.0, "the fields are updated at a positive period");
  WholeBodyPlannerOptions core;
  planner::AdaptPlannerOptions(*options, &core);
  CheckCoreOptions(core);
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  static const LoaderTempFile file("topay_fuzz_planner", ".yaml");
  FuzzReader in(data, size);
  const std::uint8_t selector = in.Byte();
  const std::string text = in.RestAsString();
  if ((selector & 1) == 0) {
    FuzzCorePlannerOptions(text);
  } else {
    FuzzPlannerProcessOptions(text, file);
  }
  return 0;
}
