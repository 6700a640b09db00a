#include "results_table.h"

#include <algorithm>

#include <fmt/format.h>

namespace topay::tools {
namespace {

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string Contacts(std::int64_t contacts) { return contacts < 0 ? "?" : std::to_string(contacts); }

std::string Centimetres(double metres) { return metres < 0.0 ? "-" : fmt::format("{:.2f}", 100.0 * metres); }

}  // namespace

std::string ResultsTable(const std::vector<MissionRunRow>& rows) {
  std::string text =
      "| seed | success | result | collisions | time s | replans | boxes | pos RMS cm | yaw RMS rad | joint RMS rad | "
      "estimate RMS cm |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  int successes = 0, no_scenario = 0;
  std::int64_t contacts = 0;
  std::vector<double> times;
  for (const MissionRunRow& r : rows) {
    text += fmt::format("| {} | {} | {} | {} | {:.1f} | {} | {} | {:.2f} | {:.4f} | {:.4f} | {} |\n", r.seed,
                        r.Success() ? "yes" : "NO", r.result, Contacts(r.contact_events), r.mission_time_s,
                        r.replans, r.boxes_appeared, 100.0 * r.position_rms_m, r.yaw_rms_rad, r.joint_rms_rad,
                        Centimetres(r.estimation_rms_m));
    successes += r.Success() ? 1 : 0;
    no_scenario += r.NoScenario() ? 1 : 0;
    contacts += std::max<std::int64_t>(r.contact_events, 0);
    if (r.result == "SUCCEEDED") times.push_back(r.mission_time_s);
  }
  text += fmt::format("\n{} / {} missions succeeded without contact; {} ground-truth contacts in all; median "
                      "mission time {:.1f} s (successful runs)",
                      successes, rows.size() - no_scenario, contacts, Median(times));
  if (no_scenario > 0) text += fmt::format("; {} seed(s) without a scenario (no mission run)", no_scenario);
  text += "\n";
  return text;
}

nlohmann::json ToJson(const MissionRunRow& row) {
  return {{"seed", row.seed},
          {"success", row.Success()},
          {"result", row.result},
          {"contact_events", row.contact_events},
          {"mission_time_s", row.mission_time_s},
          {"replans", row.replans},
          {"boxes_appeared", row.boxes_appeared},
          {"position_rms_m", row.position_rms_m},
          {"yaw_rms_rad", row.yaw_rms_rad},
          {"joint_rms_rad", row.joint_rms_rad},
          {"estimation_rms_m", row.estimation_rms_m},
          {"run_dir", row.run_dir},
          {"detail", row.detail}};
}

}  // namespace topay::tools
