#include "core/planner/failure_cause.h"

#include <algorithm>

#include "core/collision/start_target_diagnosis.h"

namespace topay {

std::optional<std::string> FrontEndFailureCause(FrontEndStatus status,
                                                const WholeBodyValidity& validity,
                                                const Scene& scene, const WholeBodyState& start,
                                                const Eigen::Isometry3d& X_WE_target) {
  switch (status) {
    case FrontEndStatus::kStartInvalid: {
      const Kinematics& kinematics = validity.kinematics();
      if (auto exact = DiagnoseStartState(kinematics, scene, start)) return exact;
      StartDiagnosisOptions margins;
      margins.obstacle_margin_m = std::max(validity.base_margin_m(), validity.arm_margin_m());
      margins.self_margin_m = validity.options().self_margin_m;
      if (auto near = DiagnoseStartState(kinematics, scene, start, margins)) {
        return "within the planner's margin (" + std::to_string(margins.obstacle_margin_m) +
               " m to boxes): " + *near;
      }
      return std::nullopt;
    }
    case FrontEndStatus::kNoGoal:
    case FrontEndStatus::kNoBasePath:
    case FrontEndStatus::kNoArmPath:
      if (auto target = DiagnoseTarget(scene, X_WE_target)) return "target: " + *target;
      return std::nullopt;
    default:
      return std::nullopt;
  }
}

}  // namespace topay
