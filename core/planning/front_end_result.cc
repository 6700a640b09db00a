#include "core/planning/front_end_result.h"

namespace topay {

std::string_view ToString(FrontEndStatus status) {
  switch (status) {
    case FrontEndStatus::kSuccess: return "success";
    case FrontEndStatus::kInvalidInput: return "invalid_input";
    case FrontEndStatus::kStartInvalid: return "start_invalid";
    case FrontEndStatus::kNoGoal: return "no_goal";
    case FrontEndStatus::kNoBasePath: return "no_base_path";
    case FrontEndStatus::kNoArmPath: return "no_arm_path";
    case FrontEndStatus::kCancelled: return "cancelled";
  }
  return "unknown";
}

}  // namespace topay
