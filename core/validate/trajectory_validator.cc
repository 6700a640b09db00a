#include "core/validate/trajectory_validator.h"

#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/validate/limit_ratios.h"
#include "core/validate/validation_run.h"

namespace topay {
namespace {

void RequireOption(bool ok, const char* field, double value, const char* rule) {
  if (!ok) {
    std::ostringstream message;
    message << "TrajectoryValidatorOptions::" << field << " must be " << rule << ", got "
            << value;
    throw std::invalid_argument(message.str());
  }
}


bool IsRotation(const Eigen::Matrix3d& R) {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-6 &&
         R.determinant() > 0.0;
}

// Problems with the call itself, found before sampling; empty if none.
std::string CheckInput(const SampledTrajectory& trajectory, const WholeBodyState& start,
                       const Eigen::Isometry3d& X_WE_goal, int num_joints,
                       const TrajectoryValidatorOptions& options) {
  std::ostringstream message;
  if (!trajectory.make_sampler) {
    message << "the trajectory has no sampler (make_sampler is empty)";
  } else if (trajectory.num_joints != num_joints) {
    message << "the trajectory has " << trajectory.num_joints << " joints, the robot "
            << num_joints;
  } else if (!(std::isfinite(trajectory.duration_s) && trajectory.duration_s > 0.0)) {
    message << "duration_s " << trajectory.duration_s << " is not finite and > 0";
  } else if (trajectory.duration_s > options.max_duration_s) {
    message << "duration_s " << trajectory.duration_s << " exceeds max_duration_s "
            << options.max_duration_s;
  } else if (start.num_joints() != num_joints) {
    message << "the start state has " << start.num_joints() << " joints, the robot "
            << num_joints;
  } else if (!start.IsFinite()) {
    message << "the start state is not finite";
  } else if (!X_WE_goal.matrix().allFinite() || !IsRotation(X_WE_goal.linear())) {
    message << "X_WE_goal is not finite or its rotation is not a rotation matrix";
  }
  return message.str();
}

// Sample times: t_k = k * period while t_k < T (less a hair, so that the end is not sampled
// twice), then T itself.
int NumGridSamples(double duration_s, double period_s) {
  const double hair_s = 1e-9 * period_s;
  int count = static_cast<int>(std::ceil((duration_s - hair_s) / period_s));
  while (count > 1 && (count - 1) * period_s >= duration_s - hair_s) --count;
  while (count * period_s < duration_s - hair_s) ++count;
  return count < 1 ? 1 : count;
}

// Runs the sampler at t_s; false (with the failure recorded) if it throws or resizes.
bool Sample(const TrajectorySampler& sampler, double t_s, int num_joints, ValidationRun* run,
            TrajectorySample* sample) {
  try {
    sampler(t_s, sample);
  } catch (const std::exception& error) {
    std::ostringstream message;
    message << "t = " << t_s << " s: the sampler threw: " << error.what();
    run->Fail(ValidationCheck::kSampler, t_s, -1, 0.0, 0.0, message.str());
    return false;
  }
  if (sample->state.q_rad.size() != num_joints || sample->qd_radps.size() != num_joints ||
      sample->qdd_radps2.size() != num_joints) {
    std::ostringstream message;
    message << "t = " << t_s << " s: the sampler resized the sample (q, qd, qdd have "
            << sample->state.q_rad.size() << ", " << sample->qd_radps.size() << ", "
            << sample->qdd_radps2.size() << " entries, expected " << num_joints << ")";
    run->Fail(ValidationCheck::kSampler, t_s, -1, 0.0, 0.0, message.str());
    *sample = MakeTrajectorySample(num_joints);
    return false;
  }
  return true;
}

}  // namespace

void CheckTrajectoryValidatorOptions(const TrajectoryValidatorOptions& o) {
  auto finite_nonnegative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  auto finite_positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  RequireOption(finite_positive(o.sample_period_s), "sample_period_s", o.sample_period_s,
                "finite and > 0");
  RequireOption(finite_positive(o.max_duration_s), "max_duration_s", o.max_duration_s,
                "finite and > 0");
  RequireOption(o.max_duration_s / o.sample_period_s <= 1e8, "max_duration_s", o.max_duration_s,
                "at most 1e8 sample periods");
  const std::pair<const char*, double> nonnegative[] = {
      {"limit_tolerance", o.limit_tolerance},
      {"joint_position_tolerance_rad", o.joint_position_tolerance_rad},
      {"ee_position_tolerance_m", o.ee_position_tolerance_m},
      {"ee_orientation_tolerance_rad", o.ee_orientation_tolerance_rad},
      {"obstacle_margin_m", o.obstacle_margin_m},
      {"self_margin_m", o.self_margin_m},
      {"start_position_tolerance_m", o.start_position_tolerance_m},
      {"start_angle_tolerance_rad", o.start_angle_tolerance_rad},
      {"end_rest_tolerance", o.end_rest_tolerance},
      {"start_velocity_tolerance", o.start_velocity_tolerance},
      {"start_acceleration_tolerance", o.start_acceleration_tolerance}};
  for (const auto& [field, value] : nonnegative) {
    RequireOption(finite_nonnegative(value), field, value, "finite and >= 0");
  }
}

TrajectoryValidator::TrajectoryValidator(const Kinematics& kinematics, const Scene& scene,
                                         const BaseLimits& base_limits,
                                         const TrajectoryValidatorOptions& options)
    : kinematics_(kinematics),
      scene_(scene),
      base_limits_(base_limits),
      options_(options),
      checker_(kinematics, scene_),
      self_collision_(kinematics) {
  CheckTrajectoryValidatorOptions(options_);
  CheckKinematicLimits(base_limits_, kinematics.model().joint_limits, kinematics.num_joints());
}

ValidationReport TrajectoryValidator::Validate(const SampledTrajectory& trajectory,
                                               const WholeBodyState& start,
                                               const Eigen::Isometry3d& X_WE_goal,
                                               std::stop_token stop) const {
  return Run(trajectory, start, nullptr, X_WE_goal, stop);
}

ValidationReport TrajectoryValidator::Validate(const SampledTrajectory& trajectory,
                                               const MovingState& start,
                                               const Eigen::Isometry3d& X_WE_goal,
                                               std::stop_token stop) const {
  return Run(trajectory, start.state, &start.rates, X_WE_goal, stop);
}

ValidationReport TrajectoryValidator::Run(const SampledTrajectory& trajectory,
                                          const WholeBodyState& start,
                                          const WholeBodyRates* start_rates,
                                          const Eigen::Isometry3d& X_WE_goal,
                                          std::stop_token stop) const {
  ValidationReport report;
  report.duration_s = trajectory.duration_s;
  ValidationRun run(*this, start, X_WE_goal, &report, start_rates);
  const int num_joints = kinematics_.num_joints();
  std::string input_error = CheckInput(trajectory, start, X_WE_goal, num_joints, options_);
  if (input_error.empty() && start_rates != nullptr &&
      !(start_rates->IsFinite() && start_rates->HasJointCount(num_joints))) {
    input_error = "the start rates are not finite or not sized for " +
                  std::to_string(num_joints) + " joints";
  }
  TrajectorySampler sampler;
  if (input_error.empty()) {
    try {
      sampler = trajectory.make_sampler();
    } catch (const std::exception& error) {
      run.Fail(ValidationCheck::kSampler, 0.0, -1, 0.0, 0.0,
               std::string("make_sampler threw: ") + error.what());
      return report;
    }
    if (!sampler) run.Fail(ValidationCheck::kInput, 0.0, -1, 0.0, 0.0, "make_sampler returned "
                                                                        "an empty sampler");
  } else {
    run.Fail(ValidationCheck::kInput, std::numeric_limits<double>::quiet_NaN(), -1, 0.0, 0.0,
             input_error);
  }
  if (!sampler) return report;

  TrajectorySample sample = MakeTrajectorySample(num_joints);
  const int num_grid = NumGridSamples(trajectory.duration_s, options_.sample_period_s);
  for (int k = 0; k <= num_grid; ++k) {
    const bool is_last = k == num_grid;
    const double t_s = is_last ? trajectory.duration_s : k * options_.sample_period_s;
    if (stop.stop_requested()) {
      report.stopped = true;
      std::ostringstream message;
      message << "t = " << t_s << " s: stopped (time limit or cancel) after " << k << " of "
              << num_grid + 1 << " samples: the trajectory is not validated";
      run.Fail(ValidationCheck::kStopped, t_s, -1, k, num_grid + 1, message.str());
      break;
    }
    ++report.num_samples;
    const bool failed = !Sample(sampler, t_s, num_joints, &run, &sample) ||
                        run.CheckSample(t_s, sample, k == 0, is_last);
    if (failed) ++report.num_failed_samples;
    if (failed && options_.stop_at_first_failure) break;
  }
  run.NameRecords();
  report.ok = report.first_failure.check == ValidationCheck::kNone;
  return report;
}

}  // namespace topay
