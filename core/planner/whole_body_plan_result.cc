#include "core/planner/whole_body_plan_result.h"

#include <iomanip>
#include <sstream>

namespace topay {

std::string_view ToString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSuccess:
      return "success";
    case PlanStatus::kInvalidInput:
      return "invalid_input";
    case PlanStatus::kFrontEndFailed:
      return "front_end_failed";
    case PlanStatus::kOptimizationFailed:
      return "optimization_failed";
    case PlanStatus::kTimeLimit:
      return "time_limit";
    case PlanStatus::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

std::string_view ToString(PlanStage stage) {
  switch (stage) {
    case PlanStage::kNone: return "none";
    case PlanStage::kStartCheck: return "start check";
    case PlanStage::kMapBuilding: return "map building";
    case PlanStage::kFrontEnd: return "front end";
    case PlanStage::kOptimization: return "optimization";
    case PlanStage::kValidation: return "validation";
  }
  return "unknown";
}

std::string WholeBodyPlanResult::Report() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1);
  out << "plan: " << ToString(status);
  if (stopped_stage != PlanStage::kNone) out << " (during " << ToString(stopped_stage) << ")";
  if (!failure_reason.empty()) out << " -- " << failure_reason;
  out << "\n";
  if (timings.map_ms > 0.0 || timings.start_check_ms > 0.0) {
    out << "time: start check " << timings.start_check_ms << " ms, map " << timings.map_ms
        << " ms (inside the total)\n";
  }
  out << "time: search " << timings.search_ms << " ms, sampling " << timings.sampling_ms
      << " ms (front end " << timings.front_end_ms << " ms), optimization "
      << timings.optimization_ms << " ms, wait " << timings.wait_ms << " ms, total "
      << timings.total_ms << " ms\n";
  if (rounds > 1) {
    out << "rounds: " << rounds << " (the last at margin level " << margin_level
        << "; earlier: " << earlier_rounds << ")\n";
  }
  out << "front end: " << front_end.paths.size() << " whole-body paths, "
      << front_end.stats.num_base_paths << " base paths (" << front_end.stats.num_classes_kept
      << " topological classes), " << front_end.stats.num_goal_candidates
      << " goal candidates\n";
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const CandidateReport& c = candidates[i];
    out << "  candidate " << i << (static_cast<int>(i) == chosen ? " (chosen)" : "") << ": ";
    if (!c.started) {
      out << "not started\n";
      continue;
    }
    out << ToString(c.optimization.status) << ", " << std::setprecision(2)
        << c.optimization.duration_s << " s trajectory, " << c.optimization.inner_iterations()
        << " L-BFGS iterations, " << std::setprecision(1) << c.wall_ms << " ms";
    if (c.validation) out << (c.validation->ok ? ", validated" : ", REJECTED by the validator");
    if (!c.optimization.reason.empty()) out << " -- " << c.optimization.reason;
    if (c.validation && !c.validation->ok) out << " -- " << c.validation->first_failure.message;
    out << "\n";
  }
  if (const CandidateReport* c = chosen_candidate(); c != nullptr && c->validation) {
    const ValidationReport& v = *c->validation;
    out << std::setprecision(3) << "trajectory: " << v.duration_s << " s, min clearance "
        << v.min_obstacle.clearance_m << " m (" << v.min_obstacle.name << "), min self clearance "
        << v.min_self.clearance_m << " m, worst constraint ratio " << v.worst_limit.ratio
        << " (" << ToString(v.worst_limit.limit) << "), end-effector error "
        << v.end_position_error_m << " m / " << v.end_orientation_error_rad << " rad\n";
  }
  return out.str();
}

}  // namespace topay
