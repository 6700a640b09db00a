#include "procs/tracker/field_scan_intake.h"

#include <fmt/format.h>

namespace topay::tracker {

FieldScanIntake::FieldScanIntake(const RobotModel& model, double self_margin_m)
    : model_(model), kinematics_(model_), cache_(kinematics_.MakeCache()), body_(self_margin_m) {}

void FieldScanIntake::AddState(std::int64_t utime, const WholeBodyState& state) { history_.Add(utime, state); }

std::optional<std::string> FieldScanIntake::Take(const point_cloud_t& msg, std::vector<Eigen::Vector3f>* p_WP) {
  p_WP->clear();
  last_self_points_ = 0;
  if (const std::optional<msgs::CloudError> error = msgs::CheckCloud(msg, input_options_, &cloud_)) {
    return error->ToString();
  }
  const std::optional<WholeBodyState> state = history_.At(cloud_.utime);
  if (!state) {
    return fmt::format("no robot state within {:.2f} s of the scan's capture time: its points cannot be told "
                       "from the robot's own",
                       history_.options().max_gap_s);
  }
  if (state->num_joints() != kinematics_.num_joints()) {
    return fmt::format("robot state with {} joints, the model has {}", state->num_joints(), kinematics_.num_joints());
  }
  kinematics_.Update(*state, &cache_);
  body_.Update(model_, cache_);
  const Eigen::Isometry3f X_WS = cloud_.X_WS.cast<float>();
  p_WP->reserve(cloud_.p_SP.size());
  for (const Eigen::Vector3f& p_SP : cloud_.p_SP) {
    if (!p_SP.allFinite()) continue;
    p_WP->push_back(X_WS * p_SP);
  }
  last_self_points_ = body_.RemoveFrom(p_WP);
  return std::nullopt;
}

}  // namespace topay::tracker
