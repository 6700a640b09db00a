#include "core/validate/validation_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/common/angles.h"
#include "core/validate/limit_ratios.h"

namespace topay {
namespace {

std::string At(double t_s) {
  std::ostringstream out;
  out.precision(3);
  out << "t = " << std::fixed << t_s << " s: ";
  return out.str();
}

const char* Unit(Limit limit) {
  switch (limit) {
    case Limit::kLinearVelocity: return " m/s";
    case Limit::kLinearAcceleration: return " m/s^2";
    case Limit::kYawRate: case Limit::kJointVelocity: return " rad/s";
    case Limit::kYawAcceleration: case Limit::kJointAcceleration: return " rad/s^2";
    case Limit::kJointPosition: return " rad";
    default: return "";
  }
}

// Keeps the smaller clearance (strictly smaller: the earliest sample wins ties).
void Record(double clearance_m, int part, int box, double t_s, ClearanceRecord* record) {
  if (clearance_m < record->clearance_m) {
    record->clearance_m = clearance_m;
    record->part = part;
    record->box = box;
    record->t_s = t_s;
  }
}

}  // namespace

ValidationRun::ValidationRun(const TrajectoryValidator& validator, const WholeBodyState& start,
                             const Eigen::Isometry3d& X_WE_goal, ValidationReport* report,
                             const WholeBodyRates* start_rates)
    : validator_(validator),
      options_(validator.options()),
      model_(validator.kinematics().model()),
      start_(start),
      start_rates_(start_rates),
      X_WE_goal_(X_WE_goal),
      report_(report),
      workspace_(validator.checker().MakeWorkspace()) {}

void ValidationRun::Fail(ValidationCheck check, double t_s, int index, double value,
                         double threshold, const std::string& message, Limit limit,
                         int box) {
  sample_failed_ = true;
  if (HasFirstFailure()) return;
  ValidationFailure& failure = report_->first_failure;
  failure.check = check;
  failure.limit = limit;
  failure.t_s = t_s;
  failure.index = index;
  failure.box = box;
  failure.value = value;
  failure.threshold = threshold;
  failure.message = message;
}

bool ValidationRun::CheckSample(double t_s, const TrajectorySample& sample, bool is_first,
                                bool is_last) {
  sample_failed_ = false;
  if (!CheckFinite(t_s, sample)) return true;
  if (is_first) CheckStart(t_s, sample.state);
  if (is_first && start_rates_ != nullptr) CheckStartRates(t_s, sample);
  validator_.kinematics().Update(sample.state, &workspace_.cache);
  CheckObstacles(t_s);
  CheckSelf(t_s);
  CheckLimits(t_s, sample);
  if (is_last) CheckEnd(t_s, sample);
  return sample_failed_;
}

bool ValidationRun::CheckFinite(double t_s, const TrajectorySample& sample) {
  const WholeBodyState& state = sample.state;
  const char* quantity = nullptr;
  int joint = -1;
  if (!std::isfinite(state.x_m)) quantity = "x_m";
  else if (!std::isfinite(state.y_m)) quantity = "y_m";
  else if (!std::isfinite(state.yaw_rad)) quantity = "yaw_rad";
  else if (!std::isfinite(sample.v_mps)) quantity = "v_mps";
  else if (!std::isfinite(sample.omega_radps)) quantity = "omega_radps";
  else if (!std::isfinite(sample.a_mps2)) quantity = "a_mps2";
  else if (!std::isfinite(sample.beta_radps2)) quantity = "beta_radps2";
  const Eigen::VectorXd* vectors[] = {&state.q_rad, &sample.qd_radps, &sample.qdd_radps2};
  const char* names[] = {"q_rad", "qd_radps", "qdd_radps2"};
  for (int v = 0; v < 3 && quantity == nullptr; ++v) {
    for (int j = 0; j < vectors[v]->size(); ++j) {
      if (!std::isfinite((*vectors[v])(j))) {
        quantity = names[v];
        joint = j;
        break;
      }
    }
  }
  if (quantity == nullptr) return true;
  std::ostringstream message;
  message << At(t_s) << quantity;
  if (joint >= 0) message << " of " << JointName(joint);
  message << " is not finite";
  Fail(ValidationCheck::kNonFinite, t_s, joint, std::numeric_limits<double>::quiet_NaN(), 0.0,
       message.str());
  return false;
}

void ValidationRun::CheckStartRates(double t_s, const TrajectorySample& sample) {
  const WholeBodyRates& r = *start_rates_;
  const int n = model_.num_joints();
  struct Quantity {
    const char* name;
    double value, expected, tolerance;
    int joint;
  };
  const double velocity_tol = options_.start_velocity_tolerance;
  const double acceleration_tol = options_.start_acceleration_tolerance;
  std::vector<Quantity> quantities = {
      {"forward speed v", sample.v_mps, r.v_mps, velocity_tol, -1},
      {"yaw rate omega", sample.omega_radps, r.omega_radps, velocity_tol, -1},
      {"forward acceleration a", sample.a_mps2, r.a_mps2, acceleration_tol, -1},
      {"yaw acceleration beta", sample.beta_radps2, r.beta_radps2, acceleration_tol, -1}};
  const Eigen::VectorXd qd = r.JointVelocities(n), qdd = r.JointAccelerations(n);
  for (int j = 0; j < n; ++j) {
    quantities.push_back({"velocity", sample.qd_radps(j), qd(j), velocity_tol, j});
    quantities.push_back({"acceleration", sample.qdd_radps2(j), qdd(j), acceleration_tol, j});
  }
  for (const Quantity& q : quantities) {
    const double error = std::abs(q.value - q.expected);
    if (error <= q.tolerance) continue;  // a NaN was reported by CheckFinite
    std::ostringstream message;
    message << At(t_s) << (q.joint >= 0 ? JointName(q.joint) + " " : std::string()) << q.name
            << " is " << q.value << ", the moving start's " << q.expected << " (tolerance "
            << q.tolerance << ")";
    Fail(ValidationCheck::kStart, t_s, q.joint, error, q.tolerance, message.str());
    return;
  }
}

void ValidationRun::CheckStart(double t_s, const WholeBodyState& state) {
  const double position_error_m = std::hypot(state.x_m - start_.x_m, state.y_m - start_.y_m);
  const double yaw_error_rad = std::abs(WrapAngle(state.yaw_rad - start_.yaw_rad));
  int joint = -1;
  const double joint_error_rad =
      state.q_rad.size() == 0 ? 0.0 : (state.q_rad - start_.q_rad).cwiseAbs().maxCoeff(&joint);
  const double position_tolerance_m = options_.start_position_tolerance_m;
  const double angle_tolerance_rad = options_.start_angle_tolerance_rad;
  if (position_error_m > position_tolerance_m) {
    std::ostringstream message;
    message << At(t_s) << "base position is " << position_error_m
            << " m from the start's (tolerance " << position_tolerance_m << " m)";
    Fail(ValidationCheck::kStart, t_s, -1, position_error_m, position_tolerance_m,
         message.str());
  } else if (yaw_error_rad > angle_tolerance_rad) {
    std::ostringstream message;
    message << At(t_s) << "yaw differs from the start's by " << yaw_error_rad
            << " rad (tolerance " << angle_tolerance_rad << " rad)";
    Fail(ValidationCheck::kStart, t_s, -1, yaw_error_rad, angle_tolerance_rad, message.str());
  } else if (joint_error_rad > angle_tolerance_rad) {
    std::ostringstream message;
    message << At(t_s) << JointName(joint) << " differs from the start's by "
            << joint_error_rad << " rad (tolerance " << angle_tolerance_rad << " rad)";
    Fail(ValidationCheck::kStart, t_s, joint, joint_error_rad, angle_tolerance_rad,
         message.str());
  }
}

void ValidationRun::CheckObstacles(double t_s) {
  const double margin_m = options_.obstacle_margin_m;
  // Boxes farther than both the smallest clearance so far and the margin can neither fail
  // this sample nor lower the minimum: skip them (the checker's cutoff; just above the
  // margin so that a clearance equal to the margin is still resolved and fails).
  const double cutoff_m =
      std::max(report_->min_obstacle.clearance_m,
               std::nextafter(margin_m, std::numeric_limits<double>::infinity()));
  SceneClearance clearance;
  validator_.checker().ComputeObstacleParts(workspace_.cache, cutoff_m, &clearance);
  Record(clearance.base_m, -1, clearance.base_box, t_s, &report_->min_obstacle);
  Record(clearance.spheres_m, clearance.sphere, clearance.sphere_box, t_s,
         &report_->min_obstacle);
  // Eq. (13), with the exact geometry: clearance > margin for the base and every sphere.
  if (!(clearance.base_m > margin_m)) {
    std::ostringstream message;
    message << At(t_s) << "base cylinder vs box " << clearance.base_box << ": clearance "
            << clearance.base_m << " m <= margin " << margin_m << " m";
    Fail(ValidationCheck::kBaseCollision, t_s, -1, clearance.base_m, margin_m, message.str(),
         Limit::kNone, clearance.base_box);
  }
  if (!(clearance.spheres_m > margin_m)) {
    std::ostringstream message;
    message << At(t_s) << SphereName(clearance.sphere) << " vs box " << clearance.sphere_box
            << ": clearance " << clearance.spheres_m << " m <= margin " << margin_m << " m";
    Fail(ValidationCheck::kArmCollision, t_s, clearance.sphere, clearance.spheres_m, margin_m,
         message.str(), Limit::kNone, clearance.sphere_box);
  }
}

void ValidationRun::CheckSelf(double t_s) {
  const SelfCollision& self = validator_.self_collision();
  const double margin_m = options_.self_margin_m;
  // Eq. (14): every self-collision pair apart, every sphere above the chassis top.
  self.Distances(workspace_.cache, workspace_.pair_distances_m);
  self.ChassisMargins(workspace_.cache, workspace_.chassis_margins_m);
  int pair = -1;
  int sphere = -1;
  const double pair_m = self.num_pairs() == 0 ? SceneClearance::kInfinity
                                              : workspace_.pair_distances_m.minCoeff(&pair);
  const double chassis_m = self.num_spheres() == 0
                               ? SceneClearance::kInfinity
                               : workspace_.chassis_margins_m.minCoeff(&sphere);
  Record(pair_m, pair, -1, t_s, &report_->min_self);
  Record(chassis_m, sphere, -1, t_s, &report_->min_chassis);
  if (!(pair_m > margin_m)) {
    std::ostringstream message;
    message << At(t_s) << PairName(pair) << ": distance " << pair_m << " m <= margin "
            << margin_m << " m";
    Fail(ValidationCheck::kSelfCollision, t_s, pair, pair_m, margin_m, message.str());
  }
  if (!(chassis_m > margin_m)) {
    std::ostringstream message;
    message << At(t_s) << SphereName(sphere) << " above the chassis top: margin " << chassis_m
            << " m <= " << margin_m << " m";
    Fail(ValidationCheck::kChassisCollision, t_s, sphere, chassis_m, margin_m, message.str());
  }
}

void ValidationRun::CheckLimits(double t_s, const TrajectorySample& sample) {
  const JointLimits& joints = model_.joint_limits;
  LimitRatio rate = WorstRateRatio(sample, validator_.base_limits(), joints);
  LimitRatio position = WorstJointPositionRatio(sample.state.q_rad, joints);
  for (LimitRatio* ratio : {&position, &rate}) {
    ratio->t_s = t_s;
    if (ratio->limit != Limit::kNone &&
        (report_->worst_limit.limit == Limit::kNone || ratio->ratio > report_->worst_limit.ratio)) {
      report_->worst_limit = *ratio;
    }
  }
  // Eq. (11), joint positions: hard limits.
  int joint = -1;
  const double excess_rad = MaxJointPositionExcess(sample.state.q_rad, joints, &joint);
  if (excess_rad > options_.joint_position_tolerance_rad) {
    std::ostringstream message;
    message << At(t_s) << "joint position of " << JointName(joint) << ": q = "
            << sample.state.q_rad(joint) << " rad is " << excess_rad << " rad outside ["
            << joints.q_min_rad(joint) << ", " << joints.q_max_rad(joint) << "] rad";
    Fail(ValidationCheck::kLimit, t_s, joint, sample.state.q_rad(joint),
         sample.state.q_rad(joint) > joints.q_max_rad(joint) ? joints.q_max_rad(joint)
                                                             : joints.q_min_rad(joint),
         message.str(), Limit::kJointPosition);
  }
  // Eqs. (9)-(12), rates: value / limit <= 1 + tolerance.
  if (rate.ratio > 1.0 + options_.limit_tolerance) {
    std::ostringstream message;
    message << At(t_s) << ToString(rate.limit);
    if (rate.joint >= 0) message << " of " << JointName(rate.joint);
    message << ": ratio " << rate.ratio << " > 1 + " << options_.limit_tolerance << " (value "
            << rate.value << Unit(rate.limit) << ", limit " << rate.bound << Unit(rate.limit)
            << ")";
    Fail(ValidationCheck::kLimit, t_s, rate.joint, rate.ratio, 1.0 + options_.limit_tolerance,
         message.str(), rate.limit);
  }
}

void ValidationRun::CheckEnd(double t_s, const TrajectorySample& sample) {
  // Eqs. (18)-(20): at rest at the end.
  const double tolerance = options_.end_rest_tolerance;
  int joint = -1;
  const double qd_abs =
      sample.qd_radps.size() == 0 ? 0.0 : sample.qd_radps.cwiseAbs().maxCoeff(&joint);
  if (std::abs(sample.v_mps) > tolerance || std::abs(sample.omega_radps) > tolerance ||
      qd_abs > tolerance) {
    std::ostringstream message;
    message << At(t_s) << "not at rest at the end: v = " << sample.v_mps << " m/s, omega = "
            << sample.omega_radps << " rad/s, max |qd| = " << qd_abs << " rad/s ("
            << JointName(joint) << "); tolerance " << tolerance;
    const double worst = std::max({std::abs(sample.v_mps), std::abs(sample.omega_radps), qd_abs});
    Fail(ValidationCheck::kEndNotAtRest, t_s, qd_abs == worst ? joint : -1, worst, tolerance,
         message.str());
  }
  // Eq. (7): FK(s_f) = p_e, with the validator's tolerances (0.01 m / 0.02 rad).
  const Eigen::Isometry3d& X_WE = workspace_.cache.X_WE;
  const double position_error_m = (X_WE.translation() - X_WE_goal_.translation()).norm();
  const double orientation_error_rad =
      Eigen::AngleAxisd(X_WE_goal_.linear().transpose() * X_WE.linear()).angle();
  report_->end_position_error_m = position_error_m;
  report_->end_orientation_error_rad = orientation_error_rad;
  const bool position_ok = position_error_m <= options_.ee_position_tolerance_m;
  const bool orientation_ok = orientation_error_rad <= options_.ee_orientation_tolerance_rad;
  if (position_ok && orientation_ok) return;
  std::ostringstream message;
  message << At(t_s) << "end-effector error " << position_error_m << " m (tolerance "
          << options_.ee_position_tolerance_m << " m), " << orientation_error_rad
          << " rad (tolerance " << options_.ee_orientation_tolerance_rad << " rad)";
  if (!position_ok) {
    Fail(ValidationCheck::kEndEffectorPosition, t_s, -1, position_error_m,
         options_.ee_position_tolerance_m, message.str());
  } else {
    Fail(ValidationCheck::kEndEffectorOrientation, t_s, -1, orientation_error_rad,
         options_.ee_orientation_tolerance_rad, message.str());
  }
}

void ValidationRun::NameRecords() {
  ClearanceRecord& obstacle = report_->min_obstacle;
  if (obstacle.box >= 0) {
    obstacle.name = (obstacle.part < 0 ? std::string("base cylinder") : SphereName(obstacle.part)) +
                    " vs box " + std::to_string(obstacle.box);
  }
  if (report_->min_self.part >= 0) report_->min_self.name = PairName(report_->min_self.part);
  if (report_->min_chassis.part >= 0) {
    report_->min_chassis.name = SphereName(report_->min_chassis.part);
  }
}

std::string ValidationRun::SphereName(int sphere) const {
  if (sphere < 0 || sphere >= static_cast<int>(model_.spheres.size())) return "sphere ?";
  return "sphere " + std::to_string(sphere) + " (" +
         model_.links[model_.spheres[sphere].link].name + ")";
}

std::string ValidationRun::PairName(int pair) const {
  if (pair < 0 || pair >= static_cast<int>(model_.self_collision_pairs.size())) return "pair ?";
  const auto [i, j] = model_.self_collision_pairs[pair];
  return "self-collision pair " + std::to_string(pair) + ": " + SphereName(i) + " and " +
         SphereName(j);
}

std::string ValidationRun::JointName(int joint) const {
  if (joint < 0 || joint >= model_.num_joints()) return "joint ?";
  return model_.joint_names[joint] + " (index " + std::to_string(joint) + ")";
}

}  // namespace topay
