#include "core/planner/whole_body_planner_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void CheckWholeBodyPlannerOptions(const WholeBodyPlannerOptions& o) {
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) {
      throw std::invalid_argument(std::string("WholeBodyPlannerOptions::") + field + " must be " +
                                  rule);
    }
  };
  require(o.early_termination_window_s >= 0.0, "early_termination_window_s",
          ">= 0 (+infinity: wait for every candidate)");
  require(o.num_threads >= 0, "num_threads", ">= 0 (0: all cores)");
  require(o.time_limit_s > 0.0, "time_limit_s", "> 0 (+infinity: no limit)");
  require(o.max_candidates >= 1, "max_candidates", ">= 1");
}

}  // namespace topay
