#include "core/validate/validation_report.h"

#include <cmath>
#include <sstream>

namespace topay {
namespace {

std::string FormatTime(double t_s) {
  std::ostringstream out;
  if (std::isnan(t_s)) {
    out << "-";
  } else {
    out.precision(3);
    out << std::fixed << t_s << " s";
  }
  return out.str();
}

void PrintClearance(std::ostringstream& out, const char* label, const ClearanceRecord& record) {
  out << "  " << label << ": ";
  if (std::isinf(record.clearance_m) && record.clearance_m > 0.0) {
    out << "none within reach\n";
    return;
  }
  out << record.clearance_m << " m, " << record.name << " at " << FormatTime(record.t_s)
      << "\n";
}

}  // namespace

std::string_view ToString(ValidationCheck check) {
  switch (check) {
    case ValidationCheck::kNone: return "none";
    case ValidationCheck::kInput: return "input";
    case ValidationCheck::kSampler: return "sampler";
    case ValidationCheck::kNonFinite: return "non-finite value";
    case ValidationCheck::kStart: return "start state";
    case ValidationCheck::kBaseCollision: return "base collision";
    case ValidationCheck::kArmCollision: return "arm collision";
    case ValidationCheck::kSelfCollision: return "self collision";
    case ValidationCheck::kChassisCollision: return "arm-chassis collision";
    case ValidationCheck::kLimit: return "limit";
    case ValidationCheck::kEndNotAtRest: return "end not at rest";
    case ValidationCheck::kEndEffectorPosition: return "end-effector position";
    case ValidationCheck::kEndEffectorOrientation: return "end-effector orientation";
    case ValidationCheck::kStopped: return "stopped";
  }
  return "unknown";
}

std::string_view ToString(Limit limit) {
  switch (limit) {
    case Limit::kNone: return "none";
    case Limit::kJointPosition: return "joint position";
    case Limit::kLinearVelocity: return "linear velocity";
    case Limit::kYawRate: return "yaw rate";
    case Limit::kCoupledVelocity: return "coupled v-omega";
    case Limit::kLinearAcceleration: return "linear acceleration";
    case Limit::kYawAcceleration: return "yaw acceleration";
    case Limit::kJointVelocity: return "joint velocity";
    case Limit::kJointAcceleration: return "joint acceleration";
  }
  return "unknown";
}

std::string ValidationReport::Report() const {
  std::ostringstream out;
  out.precision(4);
  out << "trajectory validation: " << (ok ? "PASS" : "FAIL") << " (" << num_samples
      << " samples over " << duration_s << " s, " << num_failed_samples << " failing)\n";
  if (!ok) {
    out << "  first failure [" << ToString(first_failure.check) << "]: "
        << first_failure.message << "\n";
  }
  PrintClearance(out, "min obstacle clearance", min_obstacle);
  PrintClearance(out, "min self clearance", min_self);
  PrintClearance(out, "min chassis margin", min_chassis);
  out << "  worst limit ratio: ";
  if (worst_limit.limit == Limit::kNone) {
    out << "-\n";
  } else {
    out << worst_limit.ratio << " (" << ToString(worst_limit.limit);
    if (worst_limit.joint >= 0) out << ", joint index " << worst_limit.joint;
    out << ": " << worst_limit.value << " vs " << worst_limit.bound << ") at "
        << FormatTime(worst_limit.t_s) << "\n";
  }
  out << "  end-effector error: " << end_position_error_m << " m, " << end_orientation_error_rad
      << " rad\n";
  return out.str();
}

}  // namespace topay
