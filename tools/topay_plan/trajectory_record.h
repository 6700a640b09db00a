#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/planner/whole_body_plan_result.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"
#include "core/validate/validation_report.h"

namespace topay::plan {

/// A planned trajectory as a record: what it came from (metadata), its pieces and its
/// samples. Files: tools/topay_plan/trajectory_json.h.

/// The validator's figures for the chosen trajectory (see ValidationReport).
struct TrajectoryValidationFigures {
  bool ok = false;
  double duration_s = 0.0;
  int num_samples = 0;
  double min_clearance_m = std::numeric_limits<double>::infinity();  ///< Obstacles.
  std::string min_clearance_part;  ///< e.g. "sphere 5 (link4)", "base cylinder".
  double min_self_clearance_m = std::numeric_limits<double>::infinity();
  double worst_limit_ratio = 0.0;  ///< Largest value / limit (1 = at the limit).
  std::string
      worst_limit;  ///< ToString(Limit), e.g. "yaw rate"; for joints with " (joint k)" appended.
  double worst_limit_t_s = std::numeric_limits<double>::quiet_NaN();
  double end_position_error_m = std::numeric_limits<double>::quiet_NaN();
  double end_orientation_error_rad = std::numeric_limits<double>::quiet_NaN();
};

/// The figures of a validation report.
TrajectoryValidationFigures FiguresOf(const ValidationReport& report);

/// What the trajectory came from and how it was planned.
struct TrajectoryMetadata {
  std::string scene_kind;  ///< Scene::kind.
  std::uint64_t scene_seed = 0;
  std::string scene_file;  ///< Empty if generated.
  int num_boxes = 0;
  std::string task_source;  ///< "generated", "task file" or "command line".
  std::string task_file;    ///< The task file's path for "task file", else empty.
  std::string task_range;   ///< "small" | "medium" | "large", or empty.
  std::uint64_t task_seed = 0;
  WholeBodyState start;
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  std::string base_limits_source;  ///< "benchmark" or "robot".
  BaseLimits base_limits;
  std::string status;  ///< ToString(PlanStatus).
  std::string failure_reason;
  PlanTimings timings;  ///< ms.
  double map_build_ms = 0.0;
  std::optional<TrajectoryValidationFigures> validation;  ///< Of the chosen trajectory.
};

/// The trajectory's pieces: enough to rebuild it exactly (RebuildTrajectory).
struct TrajectoryPieces {
  Eigen::Vector2d p0_W_m = Eigen::Vector2d::Zero();
  int panels_per_piece = 12;
  Eigen::VectorXd durations_s;   ///< M.
  Eigen::MatrixXd coefficients;  ///< 6M x D, MincoS3's layout (row 6j + k: t^k of piece j).
};

/// Everything a trajectory file holds.
struct TrajectoryFile {
  TrajectoryMetadata metadata;
  std::optional<TrajectoryPieces> pieces;  ///< Unset when the plan failed.
  double sample_period_s = 0.01;
  /// Empty when the plan failed. The files hold t, pose, s, v, omega, a, beta (q' and q''
  /// are not written; jerk is left empty).
  std::vector<TrajectorySample> samples;
};

/// The pieces of a solved trajectory. Throws std::invalid_argument if it is not solved.
TrajectoryPieces PiecesOf(const ArcYawTrajectory& trajectory);

/// Samples at t = 0, period, 2 period, ... (t = k period exactly, below the end by more than
/// 1e-9 s) and at the exact end. Throws std::invalid_argument for a period outside
/// [1e-4, 10] s or an unsolved trajectory.
std::vector<TrajectorySample> SampleTrajectory(const ArcYawTrajectory& trajectory,
                                               double period_s = 0.01);

/// The trajectory the pieces describe: head (piece 0 at t = 0), waypoints (each piece's end)
/// and tail (the last piece's end) read off the polynomials and solved again by MINCO, which
/// gives back the same coefficients when the pieces are a MINCO trajectory. Throws
/// std::invalid_argument if they are not (coefficients off by more than 1e-6 relative:
/// pieces not C4-continuous), or for sizes that do not fit (rows != 6M, D < 3).
ArcYawTrajectory RebuildTrajectory(const TrajectoryPieces& pieces);

}  // namespace topay::plan
