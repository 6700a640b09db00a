#include "tools/topay_bench/bench_record.h"

#include <sstream>

namespace topay::bench {

std::string CellName(const std::string& scene, const std::string& range, bool tight) {
  return scene + " " + range + (tight ? " tight" : "");
}

std::string BenchRecord::cell() const { return CellName(scene, range, tight); }

void FillOutcome(const WholeBodyPlanResult& plan, double time_limit_ms, BenchRecord* r) {
  r->success = plan.success();
  r->status = std::string(ToString(plan.status));
  r->failure_reason = plan.failure_reason;
  r->failure = ClassifyPlanFailure(plan);
  r->timings = plan.timings;
  if (plan.sampled) r->duration_s = plan.sampled->duration_s;
  r->num_candidates = static_cast<int>(plan.candidates.size());
  r->num_paths = static_cast<int>(plan.front_end.paths.size());
  r->num_classes = plan.front_end.stats.num_classes_kept;
  r->num_base_paths = plan.front_end.stats.num_base_paths;
  r->plan_rounds = plan.rounds;
  if (const CandidateReport* chosen = plan.chosen_candidate();
      chosen != nullptr && chosen->validation) {
    r->validation = plan::FiguresOf(*chosen->validation);
  }
  if (const CandidateReport* chosen = plan.chosen_candidate()) {
    const BackEndSummary& o = chosen->optimization;
    r->optimizer = OptimizerWork{o.num_pieces,       o.stage1_iterations,     o.stage2_iterations,
                                 o.outer_iterations, o.objective_evaluations, o.penalty_escalations};
  }
  if (r->success && r->tp_ms() > time_limit_ms) {
    std::ostringstream reason;
    reason << "time limit: T.P. " << r->tp_ms() << " ms > " << time_limit_ms << " ms";
    r->success = false;
    r->status = std::string(ToString(PlanStatus::kTimeLimit));
    r->failure = FailureCategory::kTimeLimit;
    r->failure_reason = reason.str();
  }
}

}  // namespace topay::bench
