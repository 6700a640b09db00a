#include "core/optimization/back_end_summary.h"

#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/trajectory/arc_yaw_sampling.h"

namespace topay {
namespace {

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), format, a, b, c, d);
  return buffer;
}

void ReportCost(const BackEndSummary& s, std::ostringstream* out) {
  const ObjectiveBreakdown& cost = s.final_cost;
  *out << Format("  cost %.4g: jerk %.4g, time %.4g, end effector %.4g", cost.total, cost.jerk,
                 cost.time, cost.end_effector);
  if (s.parameterisation == TrajectoryParameterisation::kFlatness) {
    *out << Format(", min speed %.3g", s.final_min_speed_cost);
  }
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    if (cost.penalties[t] > 0.0) {
      *out << ", " << ToString(static_cast<PenaltyTerm>(t)) << " "
           << Format("%.3g", cost.penalties[t]);
    }
  }
  *out << "\n";
}

void ReportChecks(const BackEndSummary& s, std::ostringstream* out) {
  const FieldFeasibilityReport& f = s.feasibility;
  if (f.num_samples > 0) {
    *out << Format("  field check (%.0f samples): base %.4f m, arm %.4f m, self %.4f m,",
                   f.num_samples, f.min_base_clearance_m, f.min_arm_clearance_m,
                   f.min_self_clearance_m)
         << Format(" chassis %.4f m beyond requirement; worst rate ratio %.4f (",
                   f.min_chassis_clearance_m, f.max_rate_ratio)
         << f.worst_rate << ")\n";
  }
  std::string violated;
  for (int t = 0; t < kNumPenaltyTerms; ++t) {
    if (s.check_violations[t] > 0.0) {
      violated += (violated.empty() ? "" : ", ") +
                  std::string(ToString(static_cast<PenaltyTerm>(t))) + " " +
                  Format("%.3g", s.check_violations[t]);
    }
  }
  if (!violated.empty()) *out << "  dense check violations: " << violated << "\n";
}

}  // namespace

std::string_view ToString(BackEndStatus status) {
  switch (status) {
    case BackEndStatus::kSuccess: return "success";
    case BackEndStatus::kNotConverged: return "not converged";
    case BackEndStatus::kCancelled: return "cancelled";
    case BackEndStatus::kInvalidInput: return "invalid input";
  }
  return "unknown";
}

ArcYawTrajectory BackEndSummary::MakeTrajectory() const {
  if (num_pieces <= 0) {
    throw std::invalid_argument("BackEndSummary::MakeTrajectory: no trajectory (" + reason + ")");
  }
  if (parameterisation != TrajectoryParameterisation::kArcLengthYaw) {
    throw std::invalid_argument(
        "BackEndSummary::MakeTrajectory: a flatness trajectory (use Sampled())");
  }
  ArcYawTrajectory::Options options;
  options.integrator.panels_per_piece = panels_per_piece;
  ArcYawTrajectory trajectory(static_cast<int>(head.rows()) - 2, num_pieces, options);
  trajectory.Update(p0_W, head, tail, waypoints, durations_s);
  return trajectory;
}

SampledTrajectory BackEndSummary::Sampled() const {
  if (parameterisation == TrajectoryParameterisation::kFlatness) {
    if (num_pieces <= 0) {
      throw std::invalid_argument("BackEndSummary::Sampled: no trajectory (" + reason + ")");
    }
    return SampleFlatness(flatness);
  }
  // SampleArcYaw holds the trajectory by reference: keep it alive with the samplers.
  const auto trajectory = std::make_shared<const ArcYawTrajectory>(MakeTrajectory());
  SampledTrajectory sampled = SampleArcYaw(*trajectory);
  sampled.make_sampler = [trajectory, make = std::move(sampled.make_sampler)]() {
    TrajectorySampler sampler = make();
    return TrajectorySampler([trajectory, sampler = std::move(sampler)](
                                 double t_s, TrajectorySample* sample) { sampler(t_s, sample); });
  };
  return sampled;
}

std::string BackEndSummary::Report() const {
  std::ostringstream out;
  out << (parameterisation == TrajectoryParameterisation::kFlatness
              ? "Back end (flatness baseline): "
              : "Back end (arc length-yaw): ")
      << ToString(status);
  if (!reason.empty()) out << " (" << reason << ")";
  out << "\n";
  if (num_pieces > 0) {
    out << Format("  trajectory: %.0f pieces, %.3f s; end effector error %.4f m / %.4f rad\n",
                  num_pieces, duration_s, ee_position_error_m, ee_orientation_error_rad);
  }
  if (!endpoint_relief.empty()) out << "  endpoint relief: " << endpoint_relief << "\n";
  if (time_stretch != 1.0) {
    out << Format("  time stretch: every duration x %.3f (rate limits only)\n", time_stretch);
  }
  out << Format("  iterations: stage 1 %.0f, stage 2 %.0f (%.0f outer, final rho %.3g",
                stage1_iterations, stage2_iterations, outer_iterations, final_rho)
      << Format(", %.0f penalty escalations", penalty_escalations)
      << (collapse_restarts > 0 ? Format(", %.0f restarts after a collapsed duration", collapse_restarts)
                                : std::string())
      << ")\n";
  out << Format("  objective evaluations %.0f; time %.2f ms", objective_evaluations,
                1e3 * total_s)
      << Format(" (warm start %.2f, stage 1 %.2f, stage 2 %.2f, check %.2f ms)\n",
                1e3 * warm_start_s, 1e3 * stage1_s, 1e3 * stage2_s, 1e3 * check_s);
  if (num_pieces > 0) {
    ReportCost(*this, &out);
    ReportChecks(*this, &out);
  }
  return out.str();
}

}  // namespace topay
