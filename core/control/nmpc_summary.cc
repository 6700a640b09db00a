#include "core/control/nmpc_summary.h"

#include <cstdio>

namespace topay {

std::string NmpcSummary::Report() const {
  char text[512];
  std::snprintf(text, sizeof(text),
                "NMPC solve: %.3f ms (base %.3f ms, %d it, cost %.4g -> %.4g; joints %.3f ms, "
                "%d it)%s, %d input(s) projected\n"
                "NMPC totals: %d solves, %d over budget, %d failed, %d warm-start resets\n",
                solve_ms, base_solve_ms, base_iterations, base_initial_cost, base_final_cost,
                joint_solve_ms, joint_iterations, fell_back ? ", FELL BACK to the shifted previous" : "",
                projected_inputs, num_solves, num_over_budget, num_failed, num_warm_resets);
  return text;
}

}  // namespace topay
