#include "core/planning/goal_clearance.h"

#include <algorithm>

#include "core/planning/field_clearance.h"

namespace topay {

std::string GoalClearanceTally::Describe() const {
  std::string out = std::to_string(field_accepted + exact_accepted + rejected()) +
                    " goal states checked: " + std::to_string(field_accepted) +
                    " clear on the fields, " + std::to_string(exact_accepted) +
                    " clear only exactly; rejected";
  const auto add = [&out](int count, const char* what) {
    if (count > 0) out += " " + std::to_string(count) + " " + what + ",";
  };
  add(exact_arm, "arm sphere vs box (exact)");
  add(exact_base, "base vs box (exact)");
  add(field_only, "on the fields (no exact check)");
  add(self_collision, "self collision or arm below the chassis");
  add(joint_limit, "joint limit");
  if (out.back() == ',') {
    out.pop_back();
  } else {
    out += " none";
  }
  return out;
}

GoalClearance::GoalClearance(const WholeBodyValidity& validity,
                             const SignedDistanceField2& base_field,
                             const SignedDistanceField3& arm_field,
                             const SceneClearanceChecker* exact, const ExactZoneOptions& margins)
    : validity_(validity),
      base_field_(base_field),
      arm_field_(arm_field),
      exact_(exact),
      margins_(margins),
      workspace_(validity.MakeWorkspace()) {
  if (exact_ != nullptr) exact_workspace_ = exact_->MakeWorkspace();
}

double GoalClearance::operator()(const WholeBodyState& state) {
  const ValidityFailure failure = validity_.CheckOnFields(state, &workspace_);
  switch (failure) {
    case ValidityFailure::kNone:
      ++tally_.field_accepted;
      return FieldClearance(validity_, base_field_, arm_field_, state, &workspace_);
    case ValidityFailure::kBaseCollision:
    case ValidityFailure::kArmCollision:
      break;
    case ValidityFailure::kJointLimit:
      ++tally_.joint_limit;
      return -1.0;
    case ValidityFailure::kSelfCollision:
    case ValidityFailure::kChassis:
      ++tally_.self_collision;
      return -1.0;
    default:  // malformed
      return -1.0;
  }
  if (exact_ == nullptr) {
    ++tally_.field_only;
    return -1.0;
  }
  const double self_margin_m = std::max(margins_.self_margin_m, validity_.options().self_margin_m);
  const SceneClearance c = exact_->Compute(state, &exact_workspace_);
  if (!(c.base_m > margins_.obstacle_margin_m)) {
    ++tally_.exact_base;
    return -1.0;
  }
  if (!(c.spheres_m > margins_.obstacle_margin_m)) {
    ++tally_.exact_arm;
    return -1.0;
  }
  if (!(c.self_m > self_margin_m && c.chassis_m > self_margin_m)) {
    ++tally_.self_collision;
    return -1.0;
  }
  ++tally_.exact_accepted;
  return kExactOnlyClearance;
}

}  // namespace topay
