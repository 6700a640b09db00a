#include "tools/report/summary_format.h"

#include <fmt/format.h>

namespace topay::report {
namespace {

std::string Plural(std::int64_t n, const std::string& word, const std::string& words = "") {
  return fmt::format("{} {}", n, n == 1 ? word : (words.empty() ? word + "s" : words));
}

std::string MissionLines(const MissionSummary& m) {
  if (m.result == MissionResult::kNone && m.steps.empty() && m.name.empty()) {
    return "mission: no MISSION_STATUS in the log\n";
  }
  std::string out = fmt::format("mission '{}': {} after {:.1f} s ({} of {} steps seen)\n", m.name,
                                ToString(m.result), m.elapsed_s, m.steps.size(), m.num_steps);
  for (const MissionStepSummary& step : m.steps) {
    out += fmt::format("  {:>2}. {:<28} {:7.1f} s{}\n", step.index + 1, step.description, step.time_s,
                       step.moving ? ", " + Plural(step.attempts, "attempt") : "");
  }
  if (!m.detail.empty()) out += fmt::format("  detail: {}\n", m.detail);
  return out;
}

std::string PlannerLines(const RunSummary& s) {
  const PlannerSummary& p = s.planner;
  std::string out = fmt::format("replans: {} over {}; {} ({} rebuilt); {}\n", p.replans, Plural(p.goals, "goal"),
                                Plural(s.trajectory_messages, "TRAJECTORY message"), s.trajectories_rebuilt,
                                Plural(p.stopping, "stopping trajectory", "stopping trajectories"));
  const TimingStats& t = p.planning_ms;
  out += fmt::format("planning (SUCCEEDED): {}, total median {:.1f} ms, p95 {:.1f} ms, max {:.1f} ms; {}\n",
                     Plural(t.count, "plan"), t.median, t.p95, t.max, Plural(p.failures, "failed goal"));
  for (const auto& [reason, count] : p.failure_reasons) out += fmt::format("  failed {}x: {}\n", count, reason);
  if (p.reached_at_rest > 0) {
    out += fmt::format("  {} reached at rest (no plan needed)\n", Plural(p.reached_at_rest, "goal"));
  }
  return out;
}

std::string CollisionLine(const CollisionSummary& c) {
  return fmt::format("ground-truth collisions: {} contact events, {} steps in contact, max depth {:.4f} m; "
                     "{} SIM_CONTACT{}\n",
                     c.contact_events, c.contact_steps, c.max_depth_m, c.contact_messages,
                     c.has_sim_status ? "" : " (no SIM_STATUS in the log)");
}

std::string TrackingLines(const TrackingSummary& t) {
  return fmt::format(
             "tracking ({} TRACKING cycles): position RMS {:.4f} m, max {:.4f} m; yaw RMS {:.4f} rad, max "
             "{:.4f} rad; joints RMS {:.4f} rad, max {:.4f} rad\n",
             t.position_m.count, t.position_m.rms, t.position_m.max, t.yaw_rad.rms, t.yaw_rad.max,
             t.joint_rad.rms, t.joint_rad.max) +
         fmt::format("NMPC solve: median {:.3f} ms, p99 {:.3f} ms, max {:.3f} ms\n", t.solve_ms.median,
                     t.solve_ms.p99, t.solve_ms.max);
}

// Only in runs with the plant's true state on the bus (CAN graphs): the estimator's error.
std::string EstimationLine(const EstimationSummary& e) {
  if (e.pairs == 0) return "";
  return fmt::format("estimation ({} ROBOT_STATE vs SIM_PLANT_STATE): position RMS {:.4f} m, max {:.4f} m; yaw RMS "
                     "{:.4f} rad, max {:.4f} rad; joints RMS {:.4f} rad, max {:.4f} rad\n",
                     e.pairs, e.position_m.rms, e.position_m.max, e.yaw_rad.rms, e.yaw_rad.max, e.joint_rad.rms,
                     e.joint_rad.max);
}

std::string MotionLines(const RunSummary& s) {
  std::string out = fmt::format("driven: {:.2f} m; boxes appeared: {}\n", s.distance_driven_m,
                                s.appeared_boxes.size());
  for (const AppearedBox& b : s.appeared_boxes) {
    out += b.has_box ? fmt::format("  box {} '{}' at ({:.2f}, {:.2f}, {:.2f}) m\n", b.box_id, b.name,
                                   b.center_W_m.x(), b.center_W_m.y(), b.center_W_m.z())
                     : fmt::format("  box {} '{}' (present again)\n", b.box_id, b.name);
  }
  return out;
}

std::string ChannelLines(const RunSummary& s) {
  std::int64_t total = 0;
  for (const auto& [channel, c] : s.channels) total += c.messages;
  std::string out = fmt::format("messages: {} on {} channels over {:.1f} s, {}\n", total, s.channels.size(),
                                s.log_span_s, Plural(s.decode_failures, "decode failure"));
  for (const auto& [channel, c] : s.channels) {
    out += fmt::format("  {:<18} {:>9}{}\n", channel, c.messages,
                       c.decode_failures > 0 ? fmt::format("  ({} malformed)", c.decode_failures) : "");
  }
  return out;
}

std::string FileLines(const RunSummary& s) {
  std::string out = fmt::format("log: {}\n", s.log_path);
  const ReportFiles& f = s.files;
  if (!f.summary_json.empty()) out += fmt::format("summary: {}\n", f.summary_json);
  if (!f.path_png.empty()) out += fmt::format("path plot: {}\n", f.path_png);
  if (!f.time_plots_png.empty()) out += fmt::format("time plots: {}\n", f.time_plots_png);
  return out;
}

}  // namespace

std::string FormatSummary(const RunSummary& s) {
  return MissionLines(s.mission) + PlannerLines(s) + CollisionLine(s.collisions) + TrackingLines(s.tracking) +
         EstimationLine(s.estimation) + MotionLines(s) + ChannelLines(s) + FileLines(s);
}

}  // namespace topay::report
