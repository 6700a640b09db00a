#include "tools/topay_plan/candidate_table.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace topay::plan {
namespace {

std::string BasePathText(const WholeBodyPlanResult& plan, int path_index) {
  if (path_index < 0 || path_index >= static_cast<int>(plan.front_end.paths.size())) return "-";
  const BasePath& base = plan.front_end.paths[path_index].base_path;
  std::ostringstream out;
  out << std::fixed << std::setprecision(1);
  if (base.source == BasePathSource::kJumpPointSearch) {
    out << "JPS";
  } else if (base.source == BasePathSource::kStanding) {
    out << "standing";
  } else {
    out << "PRM class " << base.homotopy_class;
  }
  out << ", " << base.length_m << " m";
  return out.str();
}

std::string Verdict(const CandidateReport& c) {
  if (!c.started) return "-";
  if (!c.validation) return c.optimization.reason.empty() ? "-" : c.optimization.reason;
  if (c.validation->ok) return "validated";
  return "rejected: " + c.validation->first_failure.message;
}

std::string Fixed(double value, int precision) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(precision) << value;
  return out.str();
}

}  // namespace

std::vector<CandidateRow> CandidateRows(const WholeBodyPlanResult& plan) {
  std::vector<CandidateRow> rows;
  for (std::size_t i = 0; i < plan.candidates.size(); ++i) {
    const CandidateReport& c = plan.candidates[i];
    CandidateRow row;
    row.index = static_cast<int>(i);
    row.base_path = BasePathText(plan, c.path_index);
    row.optimizer = c.started ? std::string(ToString(c.optimization.status)) : "not started";
    row.duration_s = c.started ? c.optimization.duration_s : 0.0;
    row.iterations = c.started ? c.optimization.inner_iterations() : 0;
    row.wall_ms = c.wall_ms;
    row.verdict = Verdict(c);
    row.chosen = static_cast<int>(i) == plan.chosen;
    rows.push_back(row);
  }
  return rows;
}

std::string FormatCandidateTable(const std::vector<CandidateRow>& rows, const std::string& indent) {
  if (rows.empty()) return "";
  std::size_t path_w = std::string("base path").size();
  std::size_t opt_w = std::string("optimizer").size();
  for (const CandidateRow& r : rows) {
    path_w = std::max(path_w, r.base_path.size());
    opt_w = std::max(opt_w, r.optimizer.size());
  }
  std::ostringstream out;
  out << std::left;
  out << indent << std::setw(4) << "#" << std::setw(path_w + 2) << "base path"
      << std::setw(opt_w + 2) << "optimizer" << std::right << std::setw(10) << "duration"
      << std::setw(8) << "iters" << std::setw(11) << "wall ms" << std::left << "  verdict\n";
  for (const CandidateRow& r : rows) {
    const bool ran = r.optimizer != "not started";
    out << indent << std::setw(4) << (std::to_string(r.index) + (r.chosen ? "*" : ""))
        << std::setw(path_w + 2) << r.base_path << std::setw(opt_w + 2) << r.optimizer << std::right
        << std::setw(10) << (ran ? Fixed(r.duration_s, 2) + " s" : "-") << std::setw(8)
        << (ran ? std::to_string(r.iterations) : "-") << std::setw(11)
        << (ran ? Fixed(r.wall_ms, 1) : "-") << std::left << "  " << r.verdict
        << (r.chosen ? " (chosen)" : "") << "\n";
  }
  return out.str();
}

}  // namespace topay::plan
