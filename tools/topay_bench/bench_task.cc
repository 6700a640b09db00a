#include "tools/topay_bench/bench_task.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "core/common/random.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/validate/trajectory_validator.h"
#include "tools/topay_bench/flatness_data_json.h"
#include "tools/topay_bench/plan_trajectory_file.h"
#include "tools/topay_plan/plan_query.h"
#include "tools/topay_plan/plan_summary_fill.h"
#include "tools/topay_plan/trajectory_json.h"
#include "core/planning/base_reachability.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_generator.h"
#include "sim/scenes/task_json.h"

namespace topay::bench {
namespace {

constexpr double kSamplePeriodS = 0.01;  // the validator's 10 ms samples

BenchRecord TaskRecord(const BenchTaskContext& c, int index, const PlanningTask& task,
                       std::uint64_t scene_seed) {
  BenchRecord r;
  r.task = index;
  r.task_seed = task.seed;
  r.scene_seed = scene_seed;
  r.scene = std::string(SceneKindName(c.kind));
  r.range = std::string(DistanceRangeName(c.range));
  r.tight = c.generator.tightness == TaskTightness::kTight;
  r.tight_info = task.tight;
  r.start = task.start;
  r.goal_hint = task.goal;
  r.used_hint = c.use_hint;
  r.X_WE_goal = task.X_WE_goal;
  r.base_distance_m = task.base_distance_m;
  return r;
}

std::vector<BenchRecord> GenerationFailed(const BenchTaskContext& c, int index,
                                          std::uint64_t task_seed, const std::string& what) {
  std::vector<BenchRecord> records;
  const std::size_t m = c.methods.size();
  const std::size_t runs = c.sensed != nullptr ? 2 * m : m;
  for (std::size_t k = 0; k < runs; ++k) {
    PlanningTask task;
    task.seed = task_seed;
    BenchRecord r = TaskRecord(c, index, task, 0);
    r.used_hint = false;
    const BenchMethod method = c.methods[(index + k) % m];
    r.method = k < m ? std::string(BenchMethodName(method)) : SensedMethodName(method);
    r.order = static_cast<int>(k);
    r.status = "generation_failed";
    r.failure = FailureCategory::kGenerationFailed;
    r.failure_reason = "task generation: " + what;
    records.push_back(r);
  }
  return records;
}

plan::PlanQuery QueryOf(const BenchmarkCase& bench_case) {
  plan::PlanQuery q;
  q.scene = bench_case.scene.scene;
  q.scene_source = "generated from task seed " + std::to_string(bench_case.task.seed);
  q.start = bench_case.task.start;
  q.X_WE_goal = bench_case.task.X_WE_goal;
  q.goal_state = bench_case.task.goal;
  q.task_source = "generated";
  q.task_range = std::string(DistanceRangeName(bench_case.task.range));
  q.task_seed = bench_case.task.seed;
  return q;
}

// The trajectory JSON (and the flatness pieces) of one method's plan.
void DumpPlan(const BenchTaskContext& c, int index, const std::string& method,
              const plan::PlanQuery& query, double map_ms, const WholeBodyPlannerOptions& options,
              const WholeBodyPlanResult& plan) {
  plan::PlanToolOptions tool;
  tool.scene_kind = std::string(SceneKindName(c.kind));
  tool.range = query.task_range;
  tool.seed = query.task_seed;
  tool.use_goal_hint = c.use_hint;
  plan::PlanToolSummary summary;
  plan::FillQueryInputs(tool, query, &summary);
  plan::FillPlannerSettings(options, c.limit_choice, &summary);
  summary.map_build_ms = map_ms;
  summary.plan = plan;
  const plan::TrajectoryFile file =
      PlanTrajectoryFile(plan::MetadataOf(tool, summary), plan, kSamplePeriodS);
  plan::WriteTrajectoryJson(TaskFilePath(c.dump_dir, index, method + "_trajectory.json"), file);
  const CandidateReport* chosen = plan.chosen_candidate();
  if (chosen != nullptr &&
      chosen->optimization.parameterisation == TrajectoryParameterisation::kFlatness) {
    WriteFlatnessDataJson(TaskFilePath(c.dump_dir, index, method + "_pieces.json"),
                          chosen->optimization.flatness);
  }
}

// The exact scene's verdict on a plan made on a sensed map: a success stays one only if the
// independent validator accepts the trajectory against the exact boxes.
void ValidateOnExactScene(const Kinematics& kinematics, const Scene& exact,
                          const WholeBodyPlanner& planner, const TrajectoryValidatorOptions& options,
                          const plan::PlanQuery& query, const WholeBodyPlanResult& plan,
                          BenchRecord* r) {
  if (!r->success || !plan.sampled) return;
  const TrajectoryValidator validator(kinematics, exact, planner.base_limits(), options);
  const ValidationReport report = validator.Validate(*plan.sampled, query.start, query.X_WE_goal);
  if (report.ok) return;
  r->success = false;
  r->status = "exact_scene_rejected";
  r->failure = FailureCategory::kValidatorRejected;
  r->failure_reason = "exact scene: " + report.first_failure.message;
}

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::string TaskFilePath(const std::string& dir, int index, const std::string& suffix) {
  char name[32];
  std::snprintf(name, sizeof(name), "task_%04d_", index);
  return dir + "/" + name + suffix;
}

std::string SensedMethodName(BenchMethod method) {
  return std::string(BenchMethodName(method)) + "@sensed";
}

namespace {

// Every method on the task's sensed map, in the task's rotation, after the exact runs.
void RunOnSensedMap(const BenchTaskContext& c, int index, const BenchmarkCase& bench_case,
                    const plan::PlanQuery& query, bool base_unreachable,
                    std::vector<BenchRecord>* records) {
  const std::uint64_t task_seed = bench_case.task.seed;
  const SensedMap sensed = BuildSensedMap(query.scene, bench_case.task, *c.kinematics, *c.sensed,
                                          PlannerFieldOptions(*c.kinematics), task_seed);
  const std::size_t m = c.methods.size();
  for (std::size_t k = 0; k < m; ++k) {
    const BenchMethod method = c.methods[(static_cast<std::size_t>(index) + k) % m];
    const WholeBodyPlannerOptions exact_options =
        BenchPlannerOptions(*c.loaded_options, method, c.settings, task_seed);
    WholeBodyPlannerOptions options = exact_options;
    options.validator.obstacle_margin_m += c.sensed->map_margin_m;
    const WholeBodyPlanner planner(*c.kinematics, sensed.fields->base_field_2d(),
                                   sensed.fields->field_3d(), sensed.scene, options);
    const WholeBodyPlanResult plan =
        planner.Plan(query.start, query.X_WE_goal, c.use_hint ? query.goal_state : std::nullopt);
    BenchRecord r = TaskRecord(c, index, bench_case.task, query.scene.seed);
    r.method = SensedMethodName(method);
    r.order = static_cast<int>(m + k);
    r.map_ms = sensed.figures.mapping_ms + sensed.figures.fields_ms + sensed.figures.boxes_ms;
    r.sensed = sensed.figures;
    r.base_unreachable = base_unreachable;
    FillOutcome(plan, c.settings.time_limit_ms, &r);
    ValidateOnExactScene(*c.kinematics, query.scene, planner, exact_options.validator, query, plan, &r);
    records->push_back(r);
    if (!c.dump_dir.empty()) DumpPlan(c, index, r.method, query, r.map_ms, options, plan);
  }
}

}  // namespace

std::vector<BenchRecord> RunBenchTask(const BenchTaskContext& c, int index) {
  const std::uint64_t task_seed = DeriveSeed(c.seed, static_cast<std::uint64_t>(index));
  BenchmarkCase bench_case;
  try {
    bench_case = GenerateBenchmarkCase(c.kind, c.range, task_seed, *c.kinematics, c.generator);
  } catch (const std::exception& e) {  // runtime_error (gave up), invalid_argument (range)
    return GenerationFailed(c, index, task_seed, e.what());
  }
  const plan::PlanQuery query = QueryOf(bench_case);
  if (!c.dump_dir.empty()) {
    WriteSceneJson(TaskFilePath(c.dump_dir, index, "scene.json"), query.scene,
                   &bench_case.scene.roles);
    WriteTaskJson(TaskFilePath(c.dump_dir, index, "task.json"), bench_case.task);
  }
  const auto map_start = std::chrono::steady_clock::now();
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(query.scene, PlannerFieldOptions(*c.kinematics));
  const double map_ms = MillisecondsSince(map_start);
  const bool base_unreachable =
      CertifyTargetUnreachable(query.scene, *c.kinematics, {query.start.x_m, query.start.y_m},
                               query.X_WE_goal)
          .certified_unreachable;

  std::vector<BenchRecord> records;
  const std::size_t m = c.methods.size();
  for (std::size_t k = 0; k < m; ++k) {
    const BenchMethod method = c.methods[(static_cast<std::size_t>(index) + k) % m];
    const WholeBodyPlannerOptions options =
        BenchPlannerOptions(*c.loaded_options, method, c.settings, task_seed);
    const WholeBodyPlanner planner(*c.kinematics, fields.base_field_2d, fields.field_3d,
                                   query.scene, options);
    const WholeBodyPlanResult plan =
        planner.Plan(query.start, query.X_WE_goal, c.use_hint ? query.goal_state : std::nullopt);
    BenchRecord r = TaskRecord(c, index, bench_case.task, query.scene.seed);
    r.method = std::string(BenchMethodName(method));
    r.order = static_cast<int>(k);
    r.map_ms = map_ms;
    r.base_unreachable = base_unreachable;
    FillOutcome(plan, c.settings.time_limit_ms, &r);
    records.push_back(r);
    if (!c.dump_dir.empty()) DumpPlan(c, index, r.method, query, map_ms, options, plan);
  }
  if (c.sensed != nullptr) RunOnSensedMap(c, index, bench_case, query, base_unreachable, &records);
  return records;
}

}  // namespace topay::bench
